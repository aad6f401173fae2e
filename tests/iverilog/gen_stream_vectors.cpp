// SPDX-License-Identifier: Apache-2.0
//
// gen_stream_vectors: golden vectors for the Icarus testbench of specular_stream
// (tests/iverilog/tb_specular_stream.sv), written by the bit-exact model
// (DeviceModel::stream, model/device/device_model.hpp) with the default build's ROM files.
//
//   gen_stream_vectors --out-dir DIR [--spans N] [--seed S] [--root REPO]
//
// DIR/spans.hex   one span per line, 32 hex digits (128 bits, $readmemh):
//                   [127:112] tag   [111:96] l   [95:80] n   [79:48] dpsi   [47:16] psi0
//                   [15:0] C        (unused high bits of a field are 0)
// DIR/pixels.hex  one expected pixel per line, 9 hex digits (36 bits), in output order:
//                   [35:32] last (0 or 1)   [31:16] tag   [15:0] intensity
// The span set: a fixed list of corner cases first (l = 0, n at the decoder's bank limits
// and invalid, C = 0 and the largest C, psi0 at and past pi/2 of both signs, the longest
// span the counter allows),
// then random spans (mostly short, as a rasterizer's are). Exit status 0, or 2 on a bad
// argument / missing ROM file.
#include "device_model.hpp"
#include "rom_image.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace {

using specular::device::Format;
using specular::device::Span;

constexpr uint32_t kTagMask = 0xffff;  // TagBits = 16 in the testbench

Span make_span(const Format& f, uint32_t c, double psi0, double dpsi, uint32_t n, uint32_t len) {
  Span s;
  s.reg.c = c;
  s.reg.psi0 = specular::device::quantize_angle(psi0, f);
  s.reg.dpsi = specular::device::quantize_angle(dpsi, f);
  s.reg.n = n;
  s.reg.len = len;
  return s;
}

// Corner cases, in this order at the head of the span list.
std::vector<Span> corner_spans(const Format& f) {
  const double half_pi = std::numbers::pi / 2;
  const uint32_t cmax = (1U << f.c_bits) - 1;
  std::vector<Span> v;
  v.push_back(make_span(f, 0x4000, 0.0, 0.0, 100, 0));          // l = 0, the peak
  v.push_back(make_span(f, cmax, 0.0, 0.001, 1, 3));            // largest C, n = 1
  v.push_back(make_span(f, 0, 0.1, 0.01, 50, 2));               // C = 0
  for (int j = 0; j < static_cast<int>(f.bank_max_n.size()); ++j) {  // each bank's limits
    const uint32_t hi = static_cast<uint32_t>(f.bank_max_n[j]);
    v.push_back(make_span(f, 0x7fff, -0.3, 0.02, hi, 5));
    v.push_back(make_span(f, 0x7fff, -0.3, 0.02, hi + 1, 1));
  }
  for (uint32_t n : {0U, 1001U, 1023U})                         // invalid n: every pixel 0
    v.push_back(make_span(f, 0x7fff, 0.0, 0.001, n, 2));
  // Across pi/2 and -pi/2 one code at a time (the far test of multiplier 11).
  Span up = make_span(f, 0x7fff, 0.0, 0.0, 1, 4), down = up;
  up.reg.psi0 = f.half_pi_code() - 2;
  up.reg.dpsi = 1;
  down.reg.psi0 = -f.half_pi_code() + 2;
  down.reg.dpsi = -1;
  v.push_back(up);
  v.push_back(down);
  v.push_back(make_span(f, 0x7fff, half_pi - 0.01, 0.004, 2, 6));  // past pi/2, n = 2
  v.push_back(make_span(f, 0x7fff, -7.9, 0.5, 3, 31));          // far angles of both signs
  v.push_back(make_span(f, 0x6000, -0.8, 0.8 / 1024, 20, (1U << f.len_bits) - 1));  // l = 2047
  return v;
}

// Random span: mostly short spans inside the lobe, some anywhere in the angle format.
Span random_span(const Format& f, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  Span s;
  auto& r = s.reg;
  r.c = static_cast<uint32_t>(rng() & ((1ULL << f.c_bits) - 1));
  const double pick = u01(rng);
  if (pick < 0.7) {
    r.psi0 = specular::device::quantize_angle(-2.0 + 4.0 * u01(rng), f);
  } else if (pick < 0.9) {
    r.psi0 = specular::device::quantize_angle((u01(rng) - 0.5) * 1e-3, f);
  } else {
    const int64_t half = int64_t{1} << (f.angle_bits - 1);
    r.psi0 = static_cast<int64_t>(rng() % static_cast<uint64_t>(2 * half)) - half;
  }
  const double mag = std::ldexp(1.0, -24 + static_cast<int>(rng() % 22)) * (1.0 + u01(rng));
  r.dpsi = specular::device::quantize_angle((rng() & 1) ? mag : -mag, f);
  r.n = u01(rng) < 0.9 ? 1 + static_cast<uint32_t>(rng() % 1000)
                       : static_cast<uint32_t>(rng() % (1U << f.n_bits));
  const double pl = u01(rng);
  if (pl < 0.6) r.len = static_cast<uint32_t>(rng() % 4);
  else if (pl < 0.97) r.len = 4 + static_cast<uint32_t>(rng() % 28);
  else r.len = 32 + static_cast<uint32_t>(rng() % 96);
  s.tag = static_cast<uint32_t>(rng()) & kTagMask;
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out_dir, root = ".";
  int n_spans = 1200;
  uint64_t seed = 1;
  CLI::App app{"Golden span and pixel vectors for tests/iverilog/tb_specular_stream.sv"};
  app.add_option("--out-dir", out_dir, "directory for spans.hex and pixels.hex")->required();
  app.add_option("--spans", n_spans, "number of spans, corner cases included")
      ->check(CLI::Range(40, 16384))
      ->capture_default_str();
  app.add_option("--seed", seed, "seed of the random spans")->capture_default_str();
  app.add_option("--root", root, "repository root (the ROM files are read from ROOT/roms)")
      ->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }

  const specular::BuildConfig& bc = specular::build_config("default");  // the RTL's default parameters
  const Format& f = bc.f;
  try {
    const auto model = specular::load_device_model(f, root + "/" + bc.coef_hex(), root + "/" + bc.cos_hex());
    std::vector<Span> spans = corner_spans(f);
    for (uint32_t i = 0; i < spans.size(); ++i) spans[i].tag = (0xc000 + i) & kTagMask;
    std::mt19937_64 rng(seed);
    while (static_cast<int>(spans.size()) < n_spans) spans.push_back(random_span(f, rng));
    const auto pixels = model.stream(spans);

    std::filesystem::create_directories(out_dir);
    std::ofstream sf(out_dir + "/spans.hex"), pf(out_dir + "/pixels.hex");
    char line[64];
    for (const Span& s : spans) {
      const auto r = model.latch(s.reg);
      std::snprintf(line, sizeof line, "%04x%04x%04x%08x%08x%04x\n", s.tag & kTagMask, r.len, r.n,
                    static_cast<uint32_t>(r.dpsi), static_cast<uint32_t>(r.psi0), r.c);
      sf << line;
    }
    for (const auto& p : pixels) {
      std::snprintf(line, sizeof line, "%01x%04x%04x\n", p.last ? 1U : 0U, p.tag & kTagMask,
                    p.intensity);
      pf << line;
    }
    if (!sf || !pf) throw std::runtime_error("cannot write to " + out_dir);
    std::printf("gen_stream_vectors: %zu spans, %zu pixels (seed %llu) in %s\n", spans.size(),
                pixels.size(), static_cast<unsigned long long>(seed), out_dir.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gen_stream_vectors: %s\n", e.what());
    return 2;
  }
  return 0;
}
