// SPDX-License-Identifier: Apache-2.0
// evaluator_bench: the speed axis of docs/speed_error.md. Every evaluator of model/reference/evaluators.hpp
// and the golden fixed-point device model shade the same scanline of 2048 pixels (l = 2047,
// the counter maximum) across the highlight lobe, side by side in one run.
//
// Fairness: each evaluator gets the input it naturally takes, precomputed outside the timed
// loop from the same pixel angles psi_i = psi0 + i*dpsi (the device's quantized angles):
// c_i = cos(psi_i) for pow, exp2poly, lut256, schlick, schlick_mod, lyon16 (a renderer has
// N.H from a dot product); psi_i for prototype, patent, patent_minimax (the accumulator of
// the spherical-interpolation setup produces the angle). Per-n state (the LUT, the
// coefficient a, the ROMs) is built once outside the loop, as per material in a renderer;
// `lut256_build` times the table rebuild separately.
//
// Whole-span evaluators (model/reference/span_shade.hpp) shade the same line from its span
// parameters, with nothing precomputed per pixel:
//   pow_cos        scalar double std::pow(std::cos(psi0 + i dpsi), n)
//   phong_scalar   per-pixel Phong in float: lerp N between the line's end normals (at the
//                  angles psi_0 and psi_l from H), normalize, N.H, std::pow
//   phong_sleef    the same, 8 pixels at a time with AVX2 and SLEEF's powf8 (scalar
//                  fallback when the CPU lacks AVX2)
//   device_simd    device_span: cos^k(a psi) in float, AVX2 when available (the fastest
//                  device-method evaluator measured)
//   device_simd_sse2  the same kernel forced to its x86-64 baseline build (SSE2 vectors)
//
// The scanline setup (model/host/setup_batch.hpp), where items are SPANS, each from vectors to
// register codes (quantization included), over 4096 synthetic spans (host::random_spans):
//   scanline_setup scanline_setup alone per span (no quantization): what setup_scalar costs
//                  without the rounding to codes
//   setup_scalar   scanline_setup + load_registers per span (double, the reference)
//   setup_batch    the batched setup, the best instruction set of the CPU (AVX-512, else AVX2)
//   setup_batch_avx2  the same held to AVX2
//   setup_batch_sse2  the same forced to its x86-64 baseline build
//
// Benchmark names are "<evaluator>/<n>"; items_per_second counts pixels (spans for the
// setup_* entries, named without /<n>), so ns per item = 1e9 / items_per_second. Run with
// --benchmark_format=json.
#include "device_model.hpp"
#include "evaluators.hpp"
#include "rom_image.hpp"
#include "setup_batch.hpp"
#include "span_shade.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

using namespace specular;

constexpr int kLen = kMaxLen;  // pixels 0..kMaxLen: the longest line of counter 5
constexpr int kPixels = kLen + 1;
constexpr double kHalfPi = 1.57079632679489661923;

struct Scanline {
  device::Registers regs;
  std::vector<double> psi, cosine;
};

// The lobe of cos^n is ~1/sqrt(n) wide; the line crosses it through the peak
// (psi from -end to +end) and stays inside (-pi/2, pi/2).
Scanline make_scanline(const device::Format& f, int n) {
  const double end = std::min(0.97 * kHalfPi, 4.0 / std::sqrt(static_cast<double>(n)));
  Scanline s;
  s.regs.c = device::quantize_c(1.0, f);
  s.regs.psi0 = device::quantize_angle(-end, f);
  s.regs.dpsi = device::quantize_angle(2.0 * end / kLen, f);
  s.regs.n = static_cast<uint32_t>(n);
  s.regs.len = kLen;
  const double p0 = device::angle_value(s.regs.psi0, f), dp = device::angle_value(s.regs.dpsi, f);
  for (int i = 0; i < kPixels; ++i) {
    s.psi.push_back(p0 + i * dp);
    s.cosine.push_back(std::cos(s.psi.back()));
  }
  return s;
}

template <class Eval>
void run_line(benchmark::State& state, const Eval& eval, const std::vector<double>& in) {
  std::vector<double> out(in.size());
  for (auto _ : state) {
    for (size_t i = 0; i < in.size(); ++i) out[i] = eval(in[i]);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(in.size()));
}

// The golden model's whole line for the registers, output codes.
void run_device(benchmark::State& state, const device::DeviceModel& dm, const device::Registers& regs) {
  for (auto _ : state) {
    std::vector<uint32_t> out = dm.line(regs);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(kPixels));
}

// "pow/50" (built with append: GCC 12 warns falsely on operator+ of a literal and a string).
std::string bench_name(const char* evaluator, int n) {
  std::string s(evaluator);
  s.append("/").append(std::to_string(n));
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<int> ns{5, 50, 500};
  device::Format f;
  const device::DeviceModel dm(f, coef_rom_image(f, CoefSpec{CoefPolicy::maclaurin}), cos_rom_image(f));
  const device::DeviceModel dm_mm(f, coef_rom_image(f, CoefSpec{CoefPolicy::minimax}), cos_rom_image(f));
  // Scanlines live until main returns; the benchmarks capture them by reference.
  static std::vector<Scanline> lines;
  lines.reserve(ns.size());
  for (int n : ns) lines.push_back(make_scanline(f, n));

  for (size_t j = 0; j < ns.size(); ++j) {
    const int n = ns[j];
    const Scanline& s = lines[j];
    const double dn = n;
    benchmark::RegisterBenchmark(bench_name("pow", n).c_str(), [&s, dn](benchmark::State& st) {
      run_line(st, PowEval{dn}, s.cosine);
    });
    benchmark::RegisterBenchmark(bench_name("exp2poly", n).c_str(), [&s, dn](benchmark::State& st) {
      run_line(st, Exp2PolyEval{dn}, s.cosine);
    });
    benchmark::RegisterBenchmark(bench_name("lut256", n).c_str(), [&s, dn](benchmark::State& st) {
      run_line(st, LutEval(dn), s.cosine);
    });
    benchmark::RegisterBenchmark(bench_name("schlick", n).c_str(), [&s, dn](benchmark::State& st) {
      run_line(st, SchlickEval{dn}, s.cosine);
    });
    benchmark::RegisterBenchmark(bench_name("schlick_mod", n).c_str(), [&s, dn](benchmark::State& st) {
      run_line(st, SchlickModEval{dn}, s.cosine);
    });
    benchmark::RegisterBenchmark(bench_name("lyon16", n).c_str(), [&s, dn](benchmark::State& st) {
      run_line(st, LyonEval(dn, 4), s.cosine);
    });
    benchmark::RegisterBenchmark(bench_name("prototype", n).c_str(), [&s, dn](benchmark::State& st) {
      run_line(st, prototype_eval(dn), s.psi);
    });
    const CoskEval pat = patent_eval(n, CoefSpec{CoefPolicy::maclaurin});
    const CoskEval patm = patent_eval(n, CoefSpec{CoefPolicy::minimax});
    benchmark::RegisterBenchmark(bench_name("patent", n).c_str(), [&s, pat](benchmark::State& st) {
      run_line(st, pat, s.psi);
    });
    benchmark::RegisterBenchmark(bench_name("patent_minimax", n).c_str(), [&s, patm](benchmark::State& st) {
      run_line(st, patm, s.psi);
    });
    // The golden fixed-point model of the device along the same line (its registers hold
    // the same quantized psi0 and dpsi); output codes, C = 1.
    benchmark::RegisterBenchmark(bench_name("device", n).c_str(),
                                 [&s, &dm](benchmark::State& st) { run_device(st, dm, s.regs); });
    benchmark::RegisterBenchmark(bench_name("device_minimax", n).c_str(),
                                 [&s, &dm_mm](benchmark::State& st) { run_device(st, dm_mm, s.regs); });
    // Whole-span evaluators: span parameters in, one value per pixel out.
    const double p0 = s.psi.front(), dp = s.psi[1] - s.psi[0];
    benchmark::RegisterBenchmark(bench_name("pow_cos", n).c_str(), [p0, dp, dn](benchmark::State& st) {
      std::vector<double> out(kPixels);
      for (auto _ : st) {
        pow_cos_span(dn, p0, dp, kLen, 1.0, out.data());
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
      }
      st.SetItemsProcessed(st.iterations() * static_cast<int64_t>(kPixels));
    });
    const Vec3f n0{float(std::sin(p0)), 0.0f, float(std::cos(p0))};
    const Vec3f n1{float(std::sin(s.psi.back())), 0.0f, float(std::cos(s.psi.back()))};
    const Vec3f h{0.0f, 0.0f, 1.0f};
    for (const auto& [name, path] : {std::pair{"phong_scalar", SimdPath::scalar}, std::pair{"phong_sleef", SimdPath::automatic}}) {
      benchmark::RegisterBenchmark(bench_name(name, n).c_str(), [=](benchmark::State& st) {
        std::vector<float> out(kPixels);
        for (auto _ : st) {
          phong_span(n0, n1, h, float(dn), kLen, 1.0f, out.data(), path);
          benchmark::DoNotOptimize(out.data());
          benchmark::ClobberMemory();
        }
        st.SetItemsProcessed(st.iterations() * static_cast<int64_t>(kPixels));
      });
    }
    const DeviceSpanPlan plan = device_span_plan(n);
    for (const auto& [name, path] : {std::pair{"device_simd", SimdPath::automatic}, std::pair{"device_simd_sse2", SimdPath::scalar}}) {
      benchmark::RegisterBenchmark(bench_name(name, n).c_str(), [=](benchmark::State& st) {
        std::vector<float> out(kPixels);
        for (auto _ : st) {
          device_span(plan, p0, dp, kLen, 1.0f, out.data(), path);
          benchmark::DoNotOptimize(out.data());
          benchmark::ClobberMemory();
        }
        st.SetItemsProcessed(st.iterations() * static_cast<int64_t>(kPixels));
      });
    }
    benchmark::RegisterBenchmark(bench_name("lut256_build", n).c_str(), [dn](benchmark::State& st) {
      for (auto _ : st) {
        LutEval lut(dn);
        benchmark::DoNotOptimize(lut.table.data());
        benchmark::ClobberMemory();
      }
      st.SetItemsProcessed(st.iterations() * static_cast<int64_t>(LutEval::kEntries));
    });
  }

  // The setup: 4096 spans, items are spans.
  static host::SpanBatch spans;
  for (const ScanlineInput& in : host::random_spans(4096, 20261202)) spans.push_back(in);
  benchmark::RegisterBenchmark("scanline_setup", [](benchmark::State& st) {
    double sink = 0.0;
    for (auto _ : st) {
      for (size_t i = 0; i < spans.size(); ++i) {
        const ScanlineSetup s = scanline_setup(spans.input(i));
        sink += s.C + s.psi0 + s.dpsi;
      }
      benchmark::DoNotOptimize(sink);
    }
    st.SetItemsProcessed(st.iterations() * static_cast<int64_t>(spans.size()));
  });
  benchmark::RegisterBenchmark("setup_scalar", [f](benchmark::State& st) {
    host::RegisterBatch out;
    for (auto _ : st) {
      host::setup_scalar(spans, f, out);
      benchmark::DoNotOptimize(out.c.data());
      benchmark::ClobberMemory();
    }
    st.SetItemsProcessed(st.iterations() * static_cast<int64_t>(spans.size()));
  });
  for (const auto& [name, path] : {std::pair{"setup_batch", SimdPath::automatic}, std::pair{"setup_batch_avx2", SimdPath::avx2},
                                  std::pair{"setup_batch_sse2", SimdPath::scalar}}) {
    benchmark::RegisterBenchmark(name, [f, path = path](benchmark::State& st) {
      host::RegisterBatch out;
      for (auto _ : st) {
        host::setup_batch(spans, f, out, path);
        benchmark::DoNotOptimize(out.c.data());
        benchmark::ClobberMemory();
      }
      st.SetItemsProcessed(st.iterations() * static_cast<int64_t>(spans.size()));
    });
  }

  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
