// SPDX-License-Identifier: Apache-2.0
// sim_regression: rtl/specular_unit (Verilator) against the golden model and the double
// references, for every hardware configuration of build_configs() (rom_image.hpp), each
// verilated with its parameters; then rtl/specular_stream. Run from the repository root
// (ROM paths are relative). Exit 0 when every check passes, 1 on any failure, 2 on bad
// arguments.
//   sim_regression                          full regression, every configuration, summary table
//   sim_regression --seed S --random N --config NAME|all --json FILE   (NAME: build_configs())
//   sim_regression --vcd-dir DIR --vcd-only DIR/line_l3.vcd (l = 3) and DIR/line_long.vcd
//   sim_regression --scenes-dir DIR --images-dir DIR   every DIR/*.json through specular_stream, PNGs
//   sim_regression --no-scenes                         regression lines only
//   sim_regression --system-spans N                    random geometry spans of the system stage (0: no
//                                                      system stage; system_stage.hpp)
//   sim_regression --setup-ii 1,8,16,32,64             the system stage once per specular_system SetupII
//                                                      (8, 32, 64: the build option SPECULAR_SYSTEM_SETUP_II)
//   sim_regression --scene-threads 1                   scene stage on one thread (default 2)
//   sim_regression --corrupt-span SCENE:SPAN           test only: a wrong register must fail the scene stage
//   sim_regression --stream-spans N                    random spans through specular_stream (0: skip)
//   sim_regression --digest FILE +verilator+rand+reset+2 +verilator+seed+N
//                                                      X-propagation: digest of every output, every cycle
//   sim_regression --coverage-dir DIR                  coverage build (make coverage): DIR/*.dat
#include "checks.hpp"
#include "harness.hpp"  // before the V*.h: wraps the Verilator headers in a warning guard

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wpedantic"  // anonymous structs in Verilator's public-parameter headers
#include "Vspecular_stream_default.h"
#include "Vspecular_stream_default_specular_stream.h"
#include "sim_configs.inc"  // every configuration's models (sim/CMakeLists.txt)
#pragma GCC diagnostic pop
#include "cli_parse.hpp"
#include "coefficients.hpp"
#include "rom_image.hpp"
#include "scanline_setup.hpp"
#include "scanlines.hpp"
#include "phong_stage.hpp"
#include "scene_stage.hpp"
#include "stream_stage.hpp"
#include "Vspecular_scene_rgb.h"
#include "Vspecular_scene_rgb_specular_stream.h"
#include "colour_stage.hpp"
#include "system_stage.hpp"
#include "system_blend.inc"  // SPECULAR_SYSTEM_BLEND (sim/CMakeLists.txt)

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace {

// One row of docs/pipeline.md#stage-counts: a configuration's stage counts from P, its
// sim/specular_pipeline.sv model.
template <class P>
std::string stage_row(const std::string& name) {
  std::ostringstream o;
  o << "| " << name << " | " << P::PsiMulFrac << " | " << P::CosDeltaBits << " | " << P::CosDataBits << " | "
    << P::Mul11Stages << " | " << P::Rom12Stages << " | " << P::BlendStages << " | " << P::Mul13Stages << " | "
    << P::PipeDepth << " | "
    << P::StreamLatency << " | " << P::UnitLatency << " | l + " << P::UnitLatency + 1 << " |\n";
  return o.str();
}

// The configurations this build verilated (sim/CMakeLists.txt, SPECULAR_SIM_CONFIGS), and "all".
std::vector<std::string> config_names() {
  std::vector<std::string> v;
#define SPECULAR_CONFIG_NAME(id, name) v.push_back(name);
  SPECULAR_SIM_CONFIGS(SPECULAR_CONFIG_NAME)
#undef SPECULAR_CONFIG_NAME
  v.push_back("all");
  return v;
}

using specular::device::Format;
using namespace specular::sim;

// Each configuration is verilated with the parameters roms/build_configs.cmake gives it
// (those that differ from the RTL defaults), which must be its Format: the golden model, the
// ROM generator and this harness all take their widths from Format. The parameters are
// /*verilator public*/, so the check reads them from the verilated model; for the default
// configuration (no flags) it checks the RTL's parameter defaults against its Format.
template <typename Root>
bool format_matches_rtl(const Format& f, std::string& why) {
  struct Item { const char* name; int model, rtl; };
  const Item items[] = {
      {"c_bits", f.c_bits, Root::CBits},              {"c_frac", f.c_frac, Root::CFrac},
      {"angle_bits", f.angle_bits, Root::AngleBits},  {"angle_frac", f.angle_frac, Root::AngleFrac},
      {"acc_bits", f.acc_bits, Root::AccBits},        {"n_bits", f.n_bits, Root::NBits},
      {"len_bits", f.len_bits, Root::LenBits},        {"coef_bits", f.coef_bits, Root::CoefBits},
      {"coef_frac", f.coef_frac, Root::CoefFrac},     {"psi_mul_frac", f.psi_mul_frac, Root::PsiMulFrac},
      {"cos_interp", f.cos_interp ? 1 : 0, static_cast<int>(Root::CosInterp)},
      {"cos_addr_bits", f.cos_addr_bits, Root::CosAddrBits},
      {"cos_data_bits", f.cos_data_bits, Root::CosDataBits},
      {"cos_delta_bits", f.cos_delta_bits, Root::CosDeltaBits},
      {"cos_frac_bits", f.cos_frac_bits, Root::CosFracBits},
      {"banks", static_cast<int>(f.banks.size()), Root::NumBanks},
      {"blend", f.blend ? 1 : 0, static_cast<int>(Root::Blend)},
      {"weight_bits", f.blend ? f.weight_bits : 0, f.blend ? Root::WeightBits : 0}};
  for (const auto& it : items)
    if (it.model != it.rtl) {
      why = std::string(it.name) + ": Format has " + std::to_string(it.model) + ", the RTL " + std::to_string(it.rtl);
      return false;
    }
  // BankMaxN: NumBanks fields of NBits, bank 0 in the least significant bits; wider than 64
  // bits it is a VlWide of 32-bit words.
  auto field = [&](size_t j) -> uint32_t {
    const size_t lo = j * static_cast<size_t>(f.n_bits);
    uint64_t v = 0;
    for (int b = 0; b < f.n_bits; ++b) {
      const size_t bit = lo + static_cast<size_t>(b);
      if constexpr (std::is_integral_v<std::decay_t<decltype(Root::BankMaxN)>>) {
        v |= ((static_cast<uint64_t>(Root::BankMaxN) >> bit) & 1ULL) << b;
      } else {
        v |= static_cast<uint64_t>((Root::BankMaxN[bit / 32] >> (bit % 32)) & 1U) << b;
      }
    }
    return static_cast<uint32_t>(v);
  };
  for (size_t j = 0; j < f.bank_max_n.size(); ++j)
    if (field(j) != static_cast<uint32_t>(f.bank_max_n[j])) {
      why = "decoder table (bank_max_n / BankMaxN) differs at bank " + std::to_string(j);
      return false;
    }
  return true;
}

specular::device::Registers vcd_line(const Format& f, int l) {
  // A highlight peak inside the span, n = 16 (bank k = 16): the intensity rises and falls.
  specular::ScanlineInput in;
  in.n1 = in.n2 = {0, 0, 1};
  in.h1 = {std::sin(-0.3), 0, std::cos(-0.3)};
  in.he = {std::sin(0.3), 0, std::cos(0.3)};
  in.n = 16;
  in.l = l;
  const auto s = specular::scanline_setup(in);
  return specular::device::load_registers(s, in.n, l, f).reg;
}

template <class V>
int write_vcds(const specular::BuildConfig& bc, const std::string& dir) {
  const Format& f = bc.f;
  std::filesystem::create_directories(dir);
  Harness<V> h("specular_unit", specular::load_device_model(f, bc.coef_hex(), bc.cos_hex()));
  std::mt19937_64 rng(1);
  for (auto [name, l] : {std::pair<const char*, int>{"line_l3.vcd", 3}, {"line_long.vcd", 40}}) {
    const std::string path = (std::filesystem::path(dir) / name).string();
    h.open_vcd(path);
    h.idle(2);
    const auto regs = vcd_line(f, l);
    const LineRun run = h.run_line(regs, WriteMode::before_start, 0.0, 3, rng);
    h.close_vcd();
    const auto expect = h.model().line(regs);
    if (!run.protocol_error.empty() || run.pixels != expect) {
      std::cerr << "sim_regression: " << path << ": line does not match the golden model"
                << (run.protocol_error.empty() ? "" : " (" + run.protocol_error + ")") << "\n";
      return 1;
    }
    std::cout << "wrote " << path << " (l = " << l << ", latency " << run.latency << " cycles)\n";
  }
  return 0;
}

// The stream: spans of l = 0, 1, 3, 0 back to back, then the same under px_ready_i
// toggling every clock, so the waveform shows the handshake and a stall.
int write_stream_vcd(const specular::BuildConfig& bc, const std::string& dir) {
  const Format& f = bc.f;
  std::filesystem::create_directories(dir);
  StreamHarness<Vspecular_stream_default> h("specular_stream",
                                            specular::load_device_model(f, bc.coef_hex(), bc.cos_hex()), 16);
  const std::string path = (std::filesystem::path(dir) / "stream.vcd").string();
  h.open_vcd(path);
  std::vector<specular::device::Span> spans;
  uint32_t tag = 0xa0;
  for (int pass = 0; pass < 2; ++pass)
    for (int l : {0, 1, 3, 0}) {
      specular::device::Span sp;
      sp.reg = vcd_line(f, l);
      sp.tag = tag++;
      spans.push_back(sp);
    }
  size_t next = 0;
  for (int c = 0; c < 2; ++c) h.cycle(nullptr, true);
  for (int c = 0; c < 60 && (next < spans.size() || !h.empty()); ++c) {
    const bool ready = next < 4 || (c & 1);
    if (h.cycle(next < spans.size() ? &spans[next] : nullptr, ready)) ++next;
  }
  for (int c = 0; c < 3; ++c) h.cycle(nullptr, true);
  h.close_vcd();
  const auto& k = h.counters();
  if (k.mismatches || k.protocol_errors || !h.empty()) {
    std::cerr << "sim_regression: " << path << ": stream does not match the golden model\n";
    return 1;
  }
  std::cout << "wrote " << path << " (" << spans.size() << " spans, " << k.pixels << " pixels)\n";
  return 0;
}

// The scene stage's options and which scene gets the test-only corrupted span.
struct SceneRunOptions {
  int threads = 2;
  std::string corrupt_scene;
  long corrupt_span = -1;
};

// The regression lines on specular_unit (V), then every scene through specular_stream (SV) of
// the same configuration, with the same checker and budgets; the scene images are written
// when images_dir is not empty.
// Pipeline: the configuration's stage counts (sim/specular_pipeline.sv from rtl/prim/specular_pkg.sv),
// where the expected latencies come from.
template <class V, class Root, class SV, class SRoot, class Pipeline>
PolicyStats run_config(const specular::BuildConfig& bc, const std::vector<Scanline>& det,
                       const std::vector<Scanline>& rnd, uint64_t seed, std::vector<LoadedScene>& scenes,
                       const std::string& images_dir, const SceneRunOptions& sro,
                       std::vector<SceneStats>& scene_stats) {
  const Format& f = bc.f;
  const std::string& policy = bc.name;
  std::string why;
  if (!format_matches_rtl<Root>(f, why))
    throw std::runtime_error("configuration " + bc.name + ": the verilated parameters differ from its device::Format: " +
                             why);
  // The budget is the configuration's (model/device/rom_image.hpp build_configs).
  const Budget budget{bc.budget.rel_epicenter, bc.budget.abs_lobe, bc.budget.n1_min_ref_lsb};
  PolicyStats st;
  st.policy = policy;
  st.budget = budget;
  st.expected_latency = static_cast<int>(Pipeline::UnitLatency);
  const auto t0 = std::chrono::steady_clock::now();
  const specular::device::DeviceModel model = specular::load_device_model(f, bc.coef_hex(), bc.cos_hex());
  // A blend build's ROM 9 comes from its fits, not a policy (the checker reads its words).
  const specular::CoefSpec spec = f.blend ? specular::CoefSpec{} : specular::parse_coef_spec(bc.policy);
  const Checker checker(model, spec, budget);
  std::mt19937_64 rng(seed ^ 0x5eed);
  {
    // The unit's harness ends before the stream's begins: Verilator 5.006 destroys a model
    // through the thread's current (last constructed) context (stream_harness.hpp).
    Harness<V> h("specular_unit", model);
    double sim_s = 0.0;
    auto run = [&](const Scanline& sl, WriteMode mode, double poke, int gap, bool random) {
      const auto s0 = std::chrono::steady_clock::now();
      const LineRun r = h.run_line(sl.reg, mode, poke, gap, rng);
      sim_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - s0).count();
      checker.check_line(sl, r, random, st);
    };
    size_t idx = 0;
    for (const auto* set : {&det, &rnd}) {
      const bool random = set == &rnd;
      for (const Scanline& sl : *set) {
        ++idx;
        const WriteMode mode = idx % 2 ? WriteMode::before_start : WriteMode::with_start;
        const int gap = idx % 5 == 0 ? 2 : 0;  // mostly back to back: a start in the first idle cycle
        if (idx % 16 == 0) {
          // Garbage writes and starts while busy, then the same line again without writing:
          // both must equal the golden line for the registers written before.
          run(sl, mode, 0.3, gap, random);
          run(sl, WriteMode::none, 0.0, gap, random);
        } else {
          run(sl, mode, 0.0, gap, random);
        }
      }
    }
    st.sim_seconds = sim_s;
  }
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!scenes.empty()) {
    if (!format_matches_rtl<SRoot>(f, why))
      throw std::runtime_error("configuration " + bc.name + ": specular_stream's verilated parameters differ from its "
                               "device::Format: " + why);
    StreamHarness<SV> sh("specular_stream", specular::load_device_model(f, bc.coef_hex(), bc.cos_hex()), 16);
    for (auto& ls : scenes) {
      SceneOptions opt;
      opt.images_dir = images_dir;
      opt.threads = sro.threads;
      if (ls.scene.name == sro.corrupt_scene) opt.corrupt_span = sro.corrupt_span;
      SceneStats ss = run_scene(sh, checker, policy, ls, opt);
      ss.checks.budget = budget;
      ss.checks.expected_latency = static_cast<int>(Pipeline::StreamLatency);
      scene_stats.push_back(std::move(ss));
    }
  }
  return st;
}

std::string pct(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.4f%%", 100 * v);
  return b;
}
std::string num(double v, const char* fmt = "%.3g") {
  char b[64];
  std::snprintf(b, sizeof b, fmt, v);
  return b;
}
std::string where(const Extreme& e) {
  if (e.kind.empty()) return "- (no pixel beyond the 1-LSB allowance)";
  char b[128];
  std::snprintf(b, sizeof b, "n=%u psi=%+.5f C=%.4f", e.n, e.psi, e.c);
  return b;
}

void print_table(const std::vector<PolicyStats>& all) {
  std::vector<std::pair<std::string, std::vector<std::string>>> rows;
  auto row = [&](const std::string& name, auto fn) {
    std::vector<std::string> cells;
    for (const auto& s : all) cells.push_back(fn(s));
    rows.emplace_back(name, cells);
  };
  row("line runs (det + random)", [](const PolicyStats& s) {
    return std::to_string(s.lines) + " (" + std::to_string(s.det_lines) + " + " + std::to_string(s.rnd_lines) + ")";
  });
  row("pixels (det + random)", [](const PolicyStats& s) {
    return std::to_string(s.pixels) + " (" + std::to_string(s.det_pixels) + " + " + std::to_string(s.rnd_pixels) + ")";
  });
  row("lines with C saturated", [](const PolicyStats& s) { return std::to_string(s.c_saturated_lines); });
  row("(a) golden mismatches", [](const PolicyStats& s) { return std::to_string(s.mismatches); });
  row("(b) max quantization err [LSB]", [](const PolicyStats& s) { return num(s.quant_lsb.value, "%.2f"); });
  row("(b) max err / format bound", [](const PolicyStats& s) { return num(s.quant_excess.value, "%.3f"); });
  row("(b) bound violations", [](const PolicyStats& s) { return std::to_string(s.quant_violations); });
  row("(c) budget rel / abs", [](const PolicyStats& s) {
    return pct(s.budget.rel_epicenter) + " / " + num(s.budget.abs_lobe, "%.3f") + " C";
  });
  row("(c) epicenter pixels", [](const PolicyStats& s) { return std::to_string(s.epicenter_pixels); });
  row("(c) max rel epi, +1 LSB, n >= 2", [](const PolicyStats& s) { return pct(s.rel_allow.value); });
  row("    at", [](const PolicyStats& s) { return where(s.rel_allow); });
  row("(c) max rel epi, no allowance, all n", [](const PolicyStats& s) { return pct(s.rel_raw.value); });
  row("    at", [](const PolicyStats& s) { return where(s.rel_raw); });
  row("(c) same, only ref >= 0.5", [](const PolicyStats& s) { return pct(s.rel_raw_big.value); });
  row("    at", [](const PolicyStats& s) { return where(s.rel_raw_big); });
  row("(c) n = 1: max rel epi, +1 LSB (enforced span)", [](const PolicyStats& s) { return pct(s.rel_allow_n1.value); });
  row("    at", [](const PolicyStats& s) { return where(s.rel_allow_n1); });
  row("(c) n = 1: budget holds for |psi| <", [](const PolicyStats& s) {
    return s.n1_rel_over_budget ? num(s.n1_budget_holds_below, "%.4f") + " (" + std::to_string(s.n1_rel_over_budget) + " px over)"
                                : std::string("pi/2 (everywhere)");
  });
  row("(c) max abs lobe / C, +1 LSB", [](const PolicyStats& s) { return num(s.abs_allow.value, "%.5f"); });
  row("    at", [](const PolicyStats& s) { return where(s.abs_allow); });
  row("(c) max abs lobe / C, no allow.", [](const PolicyStats& s) { return num(s.abs_raw.value, "%.5f"); });
  row("(c) max abs past pi/2 / C, +1 LSB", [](const PolicyStats& s) { return num(s.abs_outside.value, "%.5f"); });
  row("(c) rel / abs violations", [](const PolicyStats& s) {
    return std::to_string(s.rel_violations) + " / " + std::to_string(s.abs_violations);
  });
  row("(d) protocol errors", [](const PolicyStats& s) { return std::to_string(s.protocol_errors); });
  row("latency start->1st pixel [cyc]", [](const PolicyStats& s) {
    std::string t;
    for (const auto& [l, c] : s.latency) t += (t.empty() ? "" : ", ") + std::to_string(l) + " (" + std::to_string(c) + " lines)";
    return t;
  });
  row("cycles / pixel (all lines)", [](const PolicyStats& s) { return num(double(s.cycles) / s.pixels, "%.4f"); });
  row("cycles / pixel (l = 2047)", [](const PolicyStats& s) {
    return num(s.long_line_pixels ? double(s.long_line_cycles) / s.long_line_pixels : 0.0, "%.4f");
  });
  row("simulated pixels / s (RTL only)", [](const PolicyStats& s) { return num(s.pixels / s.sim_seconds, "%.3e"); });
  row("checked pixels / s (all checks)", [](const PolicyStats& s) { return num(s.pixels / s.seconds, "%.3e"); });
  // Where the wall time goes: RTL = Verilator eval/tick, golden = DeviceModel::trace,
  // reference = the double C cos^k(a psi) and C cos^n(psi); the rest is the comparisons.
  auto share = [](double part, double total) { return num(part, "%.2f") + " s (" + num(100 * part / total, "%.0f") + " %)"; };
  row("time: RTL (Verilator)", [&](const PolicyStats& s) { return share(s.sim_seconds, s.seconds); });
  row("time: golden model", [&](const PolicyStats& s) { return share(s.golden_seconds, s.seconds); });
  row("time: double reference", [&](const PolicyStats& s) { return share(s.reference_seconds, s.seconds); });
  row("time: checks, setup, rest", [&](const PolicyStats& s) {
    return share(s.seconds - s.sim_seconds - s.golden_seconds - s.reference_seconds, s.seconds);
  });
  row("result", [](const PolicyStats& s) { return std::string(s.ok() ? "PASS" : "FAIL"); });

  size_t w0 = 0;
  std::vector<size_t> w(all.size(), 0);
  for (const auto& [name, cells] : rows) {
    w0 = std::max(w0, name.size());
    for (size_t j = 0; j < cells.size(); ++j) w[j] = std::max(w[j], cells[j].size());
  }
  for (size_t j = 0; j < all.size(); ++j) w[j] = std::max(w[j], all[j].policy.size());
  auto line = [&](const std::string& name, const std::vector<std::string>& cells) {
    std::printf("| %-*s |", static_cast<int>(w0), name.c_str());
    for (size_t j = 0; j < cells.size(); ++j) std::printf(" %-*s |", static_cast<int>(w[j]), cells[j].c_str());
    std::printf("\n");
  };
  std::vector<std::string> head;
  for (const auto& s : all) head.push_back(s.policy);
  line("configuration", head);
  std::printf("|%s|", std::string(w0 + 2, '-').c_str());
  for (size_t j = 0; j < all.size(); ++j) std::printf("%s|", std::string(w[j] + 2, '-').c_str());
  std::printf("\n");
  for (const auto& [name, cells] : rows) line(name, cells);
}

}  // namespace

int main(int argc, char** argv) {
  const Format& f = specular::build_config("default").f;
  uint64_t seed = 20260522;
  int random_lines = 100000;
  std::string config = "all", vcd_dir, json_path, scenes_dir = "scenes", images_dir = "build/scenes";
  bool vcd_only = false, no_scenes = false;
  uint64_t stream_spans = 1000000;

  CLI::App app{"Verilator regression of specular_unit against the golden model"};
  app.add_option("--seed", seed, "seed of the random scanlines")->capture_default_str();
  app.add_option("--random", random_lines, "random scanlines per configuration")
      ->check(CLI::Range(0, 10000000))
      ->capture_default_str();
  app.add_option("--config", config, "hardware configuration to simulate (rom_image.hpp build_configs)")
      ->check(CLI::IsMember(config_names()))
      ->capture_default_str();
  bool stage_table = false;
  app.add_flag("--stage-table", stage_table,
               "print the stage counts of every configuration as docs/pipeline.md's table, and nothing else");
  app.add_option("--vcd-dir", vcd_dir, "write line_l3.vcd, line_long.vcd and stream.vcd (default build) into DIR");
  app.add_flag("--vcd-only", vcd_only, "only write the VCD files, no regression")->needs("--vcd-dir");
  app.add_option("--json", json_path, "also write the summary as JSON to FILE");
  app.add_option("--scenes-dir", scenes_dir, "run every DIR/*.json scene through specular_stream")->capture_default_str();
  app.add_option("--images-dir", images_dir, "write the scene PNGs into DIR (created if missing)")
      ->capture_default_str();
  app.add_flag("--no-scenes", no_scenes, "skip the scene stage");
  SceneRunOptions sro;
  app.add_option("--scene-threads", sro.threads,
                 "scene stage: 2 runs the golden model and the references beside the RTL, 1 after it")
      ->check(CLI::Range(1, 2))
      ->capture_default_str();
  std::string corrupt;
  app.add_option("--corrupt-span", corrupt,
                 "test only: flip bit 0 of dpsi of span SPAN of scene SCENE on its way to the RTL (SCENE:SPAN); "
                 "the scene stage must then fail")
      ->check([](const std::string& v) {
        const auto colon = v.rfind(':');
        if (colon == std::string::npos || colon == 0 || colon + 1 == v.size() ||
            v.find_first_not_of("0123456789", colon + 1) != std::string::npos)
          return std::string("expected SCENE:SPAN (SPAN a span index)");
        return std::string();
      });
  app.add_option("--stream-spans", stream_spans, "random spans through specular_stream (0: skip the stream stage)")
      ->check(CLI::Range(uint64_t{0}, uint64_t{100000000}))
      ->capture_default_str();
  uint64_t system_spans = 5000;
  app.add_option("--system-spans", system_spans,
                 "random geometry spans through specular_system under backpressure and resets, after every scene "
                 "(0: skip the system stage)")
      ->check(CLI::Range(uint64_t{0}, uint64_t{100000000}))
      ->capture_default_str();
  std::vector<int> setup_iis{1};
  app.add_option("--setup-ii", setup_iis,
                 "run the system stage once per SetupII of specular_system in this comma-separated list (1, 8, 16, "
                 "32, 64; 8 to 64 need the build option SPECULAR_SYSTEM_SETUP_II, make sim-setup-ii)")
      ->delimiter(',')
      ->check(CLI::IsMember({1, 8, 16, 32, 64}))
      ->capture_default_str();
  std::string system_config = "default";
  app.add_option("--system-config", system_config,
                 "the configuration of specular_system in the system stage: default, or a blend build (verilated "
                 "at SetupII 16 only; docs/display_exact.md)")
      ->capture_default_str();
  std::string digest_path, coverage_dir;
  app.add_option("--digest", digest_path,
                 "write the digest of every output of every model in every cycle to FILE (X-propagation runs: "
                 "+verilator+rand+reset+2 +verilator+seed+N must not change it)");
  app.add_option("--coverage-dir", coverage_dir, "write each model's coverage as DIR/*.dat (coverage build only)");
  // Verilator runtime arguments (+verilator+seed+N, +verilator+rand+reset+N, ...) go to every
  // model's context, the rest to CLI11.
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (i > 0 && std::string_view(argv[i]).starts_with("+verilator+"))
      verilator_runtime().args.emplace_back(argv[i]);
    else
      args.push_back(argv[i]);
  }
  if (const auto exit_code =
          specular::parse_command_line(app, static_cast<int>(args.size()), args.data(), "sim_regression"))
    return *exit_code;
  if (stage_table) {
    std::cout << "| configuration | PsiMulFrac | CosDeltaBits | CosDataBits | multiplier 11 | ROM 12 | blend | "
                 "multiplier 13 | PipeDepth | L_s | L | clocks per line of l + 1 pixels |\n"
                 "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
#define SPECULAR_STAGE_ROW(id, name) std::cout << stage_row<Vspecular_pipeline_##id##_specular_pipeline>(name);
    SPECULAR_SIM_CONFIGS(SPECULAR_STAGE_ROW)
#undef SPECULAR_STAGE_ROW
    return 0;
  }
  if (!coverage_dir.empty()) {
#if VM_COVERAGE
    std::filesystem::create_directories(coverage_dir);
    verilator_runtime().coverage_dir = coverage_dir;
#else
    std::cerr << "sim_regression: --coverage-dir needs the coverage build (cmake -DSPECULAR_COVERAGE=ON, make coverage)\n";
    return 2;
#endif
  }

  // The RTL defaults are the default configuration's Format (the others are checked as they
  // run, against their own).
  std::string why;
  if (!format_matches_rtl<Vspecular_unit_default_specular_unit>(f, why)) {
    std::cerr << "sim_regression: the RTL parameter defaults differ from the default configuration's Format: " << why
              << "\n";
    return 1;
  }
  if (!corrupt.empty()) {
    const auto colon = corrupt.rfind(':');
    sro.corrupt_scene = corrupt.substr(0, colon);
    sro.corrupt_span = std::stol(corrupt.substr(colon + 1));
  }
  for (const int k : setup_iis) {
    if (!system_setup_ii_built(k)) {
      std::cerr << "sim_regression: --setup-ii " << k
                << ": specular_system with this SetupII is not built (allowed here: 1 and 16; configure with "
                   "-DSPECULAR_SYSTEM_SETUP_II=ON, or run make sim-setup-ii, for 8, 32 and 64)\n";
      return 2;
    }
  }
  {
    // The system at a blend build exists at SetupII 16 only (sim/CMakeLists.txt).
    bool known = system_config == "default";
#define SPECULAR_SYSTEM_CONFIG_KNOWN(id, cfg_name) known = known || system_config == cfg_name;
    SPECULAR_SYSTEM_BLEND(SPECULAR_SYSTEM_CONFIG_KNOWN)
#undef SPECULAR_SYSTEM_CONFIG_KNOWN
    if (!known || (system_config != "default" && (setup_iis.size() != 1 || setup_iis[0] != 16))) {
      std::cerr << "sim_regression: --system-config " << system_config
                << ": specular_system is built for default (SetupII 1 and 16) and for each blend build at SetupII 16 "
                   "(give --setup-ii 16)\n";
      return 2;
    }
  }
  if (scenes_dir.empty() || images_dir.empty()) {
    std::cerr << "sim_regression: --scenes-dir and --images-dir must not be empty\n";
    return 2;
  }
  // Scenes are loaded before anything runs: a bad scene file stops the run with nothing written.
  std::vector<LoadedScene> scenes;
  const auto t_run = std::chrono::steady_clock::now();
  if (!no_scenes && !vcd_only) {
    try {
      scenes = load_scenes(scenes_dir);
    } catch (const specular::SceneError& e) {
      std::cerr << "sim_regression: --scenes-dir " << scenes_dir << ": " << e.what() << "\n";
      return 2;
    } catch (const std::exception& e) {
      std::cerr << "sim_regression: --scenes-dir " << scenes_dir
                << ": expected a directory of scene JSON files (scenes/README.md): " << e.what() << "\n";
      return 2;
    }
    if (scenes.empty()) {
      std::cerr << "sim_regression: --scenes-dir " << scenes_dir << ": no *.json scene files (or pass --no-scenes)\n";
      return 2;
    }
  }
  if (!sro.corrupt_scene.empty()) {
    const auto it = std::find_if(scenes.begin(), scenes.end(),
                                 [&](const LoadedScene& ls) { return ls.scene.name == sro.corrupt_scene; });
    if (it == scenes.end() || static_cast<size_t>(sro.corrupt_span) >= it->raster.spans.size()) {
      std::cerr << "sim_regression: --corrupt-span " << corrupt << ": "
                << (it == scenes.end() ? "no such scene" : "the scene has " + std::to_string(it->raster.spans.size()) + " spans")
                << "\n";
      return 2;
    }
    std::cout << "test only: dpsi of span " << sro.corrupt_span << " of scene " << sro.corrupt_scene
              << " goes to the RTL with bit 0 flipped; the scene stage must fail\n";
  }
  try {
    if (!vcd_dir.empty()) {
      int rc = write_vcds<Vspecular_unit_default>(specular::build_config("default"), vcd_dir);
      if (rc == 0) rc = write_stream_vcd(specular::build_config("default"), vcd_dir);
      if (rc != 0 || vcd_only) return rc;
    }

    std::cout << "seed: " << seed << " (override with --seed), random scanlines per configuration: " << random_lines
              << "\n";
    const auto det = deterministic_scanlines(f);
    const auto rnd = random_scanlines(f, seed, random_lines);
    std::cout << "deterministic scanlines: " << det.size() << "\n";
    if (!scenes.empty()) std::cout << "scenes: " << scenes.size() << " from " << scenes_dir << ", images into " << images_dir << "\n";
    std::vector<PolicyStats> all;
    std::vector<SceneStats> scene_stats;
    // Budgets (fractions of C cos^n and of C; n = 1 enforced where the reference is at least
    // 4 LSB): the goals of the interpolated builds, the patent's 1.2 % with n = 1 reported only.
    // Images come from the first configuration simulated; scenes run on default and patent.
    const bool every = config == "all";
    auto want = [&](const std::string& name) { return every || config == name; };
    std::vector<LoadedScene> none;
    std::string images = images_dir;
    auto take_images = [&]() {
      std::string d = images;
      images.clear();
      return d;
    };
    // Every verilated configuration in build_configs() order; the scenes run on those marked
    // for them (BuildConfig::scenes) or on the one asked for.
#define SPECULAR_RUN_CONFIG(id, cfg_name)                                                                      \
  if (bc.name == cfg_name)                                                                                     \
    all.push_back(run_config<Vspecular_unit_##id, Vspecular_unit_##id##_specular_unit, Vspecular_scene_##id,   \
                             Vspecular_scene_##id##_specular_stream, Vspecular_pipeline_##id##_specular_pipeline>( \
        bc, det, rnd, seed, every && !bc.scenes ? none : scenes, take_images(), sro, scene_stats));
    for (const auto& bc : specular::build_configs()) {
      if (!want(bc.name.c_str())) continue;
      SPECULAR_SIM_CONFIGS(SPECULAR_RUN_CONFIG)
    }
#undef SPECULAR_RUN_CONFIG
    if (all.empty()) throw std::runtime_error("no verilated configuration is named '" + config + "'");
    print_table(all);
    if (!scene_stats.empty()) {
      std::cout << "\nScenes (every span through specular_stream, back to back, registers from the batched setup;\n"
                   "device error = RTL - C cos^n(psi_i) from the loaded registers, interpolation error = float model -\n"
                   "per-pixel Phong, intensities, C < 2; setup error = C cos^n(psi_i) from the batch registers against\n"
                   "those from the scalar setup's, max relative in the epicenter and absolute in LSB of C):\n";
      print_scene_table(scene_stats);
      for (const auto& s : scene_stats)
        if (!s.images.empty()) {
          std::cout << "images (" << s.policy << "): " << images_dir << "/<scene>_{phong,float,rtl,device_error,interp_error}.png\n";
          break;
        }
    }
    // Colour stage (colour_stage.hpp): every scene composed in colour by the RGB core (the default
    // build with Channels = 3), against the composition around the material's BRDF.
    std::vector<ColourStats> colours;
    if (!scenes.empty() && want("default")) {
      const auto& bc = specular::build_config("default");
      const specular::device::DeviceModel dm = specular::load_device_model(bc.f, bc.coef_hex(), bc.cos_hex());
      if (std::string why_rgb; !format_matches_rtl<Vspecular_scene_rgb_specular_stream>(bc.f, why_rgb))
        throw std::runtime_error("the RGB core's parameters differ from device::Format: " + why_rgb);
      for (const auto& ls : scenes)
        colours.push_back(run_colour_scene<Vspecular_scene_rgb>(ls, dm, bc.name + " rgb", images_dir));
      print_colour_table(colours);
    }
    // Stream stage: random spans (default build). The scenes went through the stream in the
    // scene stage; their rows (first configuration) set the stream's clocks per pixel against
    // the register interface's l + L + 1 per line, L + 1 measured per line in the line stage.
    StreamStats stream;
    std::vector<SceneStreamStats> scene_streams;
    for (const auto& ss : scene_stats) {
      if (ss.policy != scene_stats.front().policy) break;
      double per_line = 0.0;
      for (const auto& p : all)
        if (p.policy == ss.policy && p.lines > 0) per_line = double(p.cycles - p.pixels) / double(p.lines);
      SceneStreamStats x;
      x.name = ss.name;
      x.spans = ss.spans;
      x.pixels = ss.checks.pixels;
      x.stream_cycles = ss.stream_cycles;
      x.register_cycles = ss.checks.pixels + static_cast<uint64_t>(std::llround(per_line * double(ss.spans)));
      x.mismatches = ss.checks.mismatches;
      x.protocol_errors = ss.checks.protocol_errors;
      scene_streams.push_back(x);
    }
    if (stream_spans > 0) {
      const auto& bc = specular::build_config("default");
      if (std::string why_stream; !format_matches_rtl<Vspecular_stream_default_specular_stream>(bc.f, why_stream))
        throw std::runtime_error("specular_stream's parameter defaults differ from device::Format: " + why_stream);
      StreamHarness<Vspecular_stream_default> sh("specular_stream",
                                                 specular::load_device_model(bc.f, bc.coef_hex(), bc.cos_hex()), 16);
      stream = run_stream_stage(sh, seed, stream_spans);
    }
    if (stream_spans > 0 || !scene_streams.empty()) print_stream_summary(stream, scene_streams);
    // The other blend builds (docs/display_exact.md) under the same random stream, a tenth of its spans,
    // on their scene models (specular_stream at the build's parameters; the line stage ran them
    // with the RTL's assertions live).
    std::vector<std::pair<std::string, StreamStats>> blend_streams;
    // At least 20,000 spans (or all of them): the throughput bursts need enough spans to carry
    // the fill latency within their 0.99 pixels per clock.
    const uint64_t blend_spans = std::max(stream_spans / 10, std::min<uint64_t>(stream_spans, 20000));
#define SPECULAR_BLEND_STREAM(id, cfg_name)                                                                     \
  if (bc.f.blend && bc.name == cfg_name && bc.name != "default") {                                             \
    StreamHarness<Vspecular_scene_##id> bh("specular_stream", specular::load_device_model(bc.f, bc.coef_hex(), \
                                                                                          bc.cos_hex()), 16);  \
    blend_streams.emplace_back(bc.name, run_stream_stage(bh, seed, blend_spans));  \
  }
    if (stream_spans > 0)
      for (const auto& bc : specular::build_configs())
        if (want(bc.name)) {
          SPECULAR_SIM_CONFIGS(SPECULAR_BLEND_STREAM)
        }
#undef SPECULAR_BLEND_STREAM
    for (const auto& [name, bs] : blend_streams) print_stream_summary(bs, {}, name);
    // Phong stage (docs/phong_hw.md): every scene through phong_stream, when every
    // configuration runs.
    std::vector<PhongSceneStats> phong_stats;
    if (every && !scenes.empty()) {
      phong_stats = run_phong_stage(scenes);
      print_phong_table(phong_stats);
    }
    // System stage: geometry spans through specular_system (the setup in hardware).
    std::vector<SystemStats> systems;
    if (system_spans > 0) {
      for (const int k : setup_iis) {
        systems.push_back(run_system_stage(scenes, specular::build_config(system_config), seed, system_spans, k));
        print_system_summary(systems.back());
      }
    }
    const double run_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_run).count();
    double rtl_total = 0, golden_total = 0, ref_total = 0;
    for (const auto& s : all) {
      rtl_total += s.sim_seconds;
      golden_total += s.golden_seconds;
      ref_total += s.reference_seconds;
    }
    for (const auto& s : scene_stats) {
      std::printf("scene %s on %s: %.2f M checked pixels/s (%llu pixels in %.1f ms wall; CPU %.1f ms: RTL's thread "
                  "%.1f, other %.1f; RTL %.1f ms, golden %.1f, references %.1f, compare %.1f, setup %.1f + check %.1f)\n",
                  s.name.c_str(), s.policy.c_str(), s.checked_mpix_per_s(), (unsigned long long)s.checks.pixels,
                  1e3 * s.stage_seconds, 1e3 * s.cpu_seconds, 1e3 * s.rtl_thread_cpu_seconds,
                  1e3 * s.side_thread_cpu_seconds, 1e3 * s.checks.sim_seconds, 1e3 * s.checks.golden_seconds,
                  1e3 * s.checks.reference_seconds, 1e3 * s.compare_seconds, 1e3 * s.setup_seconds,
                  1e3 * s.setup_check_seconds);
      rtl_total += s.checks.sim_seconds;
      golden_total += s.checks.golden_seconds;
      ref_total += s.checks.reference_seconds;
    }
    std::printf("run time %.2f s: RTL %.2f s (%.0f %%), golden model %.2f s (%.0f %%), double reference %.2f s (%.0f %%), "
                "rest (checks, scanline and scene setup, images) %.2f s\n",
                run_seconds, rtl_total, 100 * rtl_total / run_seconds, golden_total, 100 * golden_total / run_seconds,
                ref_total, 100 * ref_total / run_seconds, run_seconds - rtl_total - golden_total - ref_total);
    bool ok = true;
    for (const auto& s : all) {
      ok = ok && s.ok();
      for (const auto& msg : s.failures) std::cout << "FAIL " << msg << "\n";
      for (const auto& [n, cnt] : s.rel_violations_by_n)
        std::cout << "FAIL " << s.policy << ": " << cnt << " epicenter pixels over budget at n = " << n << "\n";
      if (s.latency.size() != 1 || s.latency.begin()->first != s.expected_latency)
        std::cout << "FAIL " << s.policy << ": latency not the documented " << s.expected_latency << " clocks\n";
    }
    for (const auto& s : scene_stats) {
      ok = ok && s.ok();
      for (const auto& msg : s.checks.failures) std::cout << "FAIL " << msg << "\n";
      if (!s.setup.ok())
        std::cout << "FAIL " << s.checks.policy << ": setup error over the tolerance (0.01 % + 1 LSB) in "
                  << s.setup.violations << " spans, setup status differs in " << s.setup.status_mismatches << "\n";
      if (s.checks.latency.size() > 1 || (s.checks.latency.size() == 1 &&
                                          s.checks.latency.begin()->first != s.checks.expected_latency))
        std::cout << "FAIL " << s.checks.policy << ": latency not the documented " << s.checks.expected_latency
                  << " clocks\n";
      if (s.checks.lines == 0) std::cout << "FAIL " << s.checks.policy << ": no spans\n";
    }
    if (stream_spans > 0) {
      ok = ok && stream.ok();
      if (!stream.ok()) std::cout << "FAIL stream stage: see the stream summary\n";
    }
    for (const auto& c : colours) {
      ok = ok && c.ok();
      if (!c.ok()) std::cout << "FAIL colour " << c.scene << ": " << c.mismatches << " mismatches, " << c.protocol_errors
                             << " protocol errors\n";
    }
    for (const auto& [name, bs] : blend_streams) {
      ok = ok && bs.ok();
      if (!bs.ok()) std::cout << "FAIL stream stage " << name << ": see its stream summary\n";
    }
    for (const auto& s : scene_streams) {
      ok = ok && s.ok();
      if (!s.ok()) std::cout << "FAIL stream scene " << s.name << "\n";
    }
    for (const auto& s : phong_stats) {
      ok = ok && s.ok();
      for (const auto& msg : s.failures) std::cout << "FAIL phong " << s.config << " " << msg << "\n";
    }
    for (const auto& system : systems) {
      ok = ok && system.ok();
      if (!system.ok()) std::cout << "FAIL system stage, SetupII " << system.setup_ii << ": see the system summary\n";
    }
    if (!json_path.empty()) {
      nlohmann::json j = {{"seed", seed}, {"random_lines_per_config", random_lines}, {"ok", ok}};
      for (const auto& s : all) j["configs"][s.policy] = s.to_json();
      // scenes.<name>: the first configuration's figures at the top level, every one under by_config.
      for (const auto& s : scene_stats) {
        nlohmann::json& sj = j["scenes"][s.name];
        if (sj.is_null()) sj = s.to_json();
        sj["by_config"][s.policy] = s.to_json();
      }
      if (!scene_stats.empty()) {
        j["scenes_dir"] = scenes_dir;
        j["images_dir"] = images_dir;
      }
      if (stream_spans > 0) j["stream"] = stream.to_json();
      for (const auto& [name, bs] : blend_streams) j["stream_by_config"][name] = bs.to_json();
      for (const auto& c : colours) j["colour"][c.scene] = c.to_json();
      for (const auto& s : scene_streams) j["scenes_stream"][s.name] = s.to_json();
      // phong: the textbook form (n1000); phong_cross: the cancellation-free form (cross_n1000).
      for (const auto& s : phong_stats)
        j[s.config == "n1000" ? "phong" : "phong_cross"][s.name] = {{"spans", s.spans}, {"pixels", s.pixels}, {"cycles", s.cycles},
                              {"mismatches", s.mismatches}, {"epicenter_pixels", s.epicenter_pixels},
                              {"rel_lsb", s.rel_lsb}, {"abs_lsb", s.abs_lsb}, {"rel_lsb_truth", s.rel_lsb_truth},
                              {"abs_lsb_truth", s.abs_lsb_truth}, {"rel_violations", s.rel_violations},
                              {"abs_violations", s.abs_violations}};
      // system: SetupII 1 (the default); system_setup_ii.<k>: every SetupII run, 1 included.
      for (const auto& system : systems) {
        for (const auto& r : system.runs) {
          const nlohmann::json rj = {{"spans", r.spans}, {"pixels", r.pixels}, {"mismatches", r.mismatches},
                                     {"px_per_clock_fill", r.px_per_clock_fill()}, {"px_per_clock_steady", r.px_per_clock_steady()},
                                     {"setup_rel_epicenter", r.setup_rel}, {"setup_lsb", r.setup_lsb},
                                     {"e2e_rel_epicenter", r.e2e_rel}, {"e2e_lsb", r.e2e_lsb}, {"e2e_worst", r.e2e_worst}, {"ok", r.ok()}};
          if (system.setup_ii == 1) j["system"][r.name] = rj;
          j["system_setup_ii"][std::to_string(system.setup_ii)][r.name] = rj;
        }
      }
      j["run_seconds"] = run_seconds;
      j["rtl_seconds"] = rtl_total;
      j["golden_seconds"] = golden_total;
      j["reference_seconds"] = ref_total;
      const std::string tmp = json_path + ".tmp";
      {
        std::ofstream out(tmp);
        out << j.dump(2) << "\n";
        if (!out) throw std::runtime_error("cannot write " + tmp);
      }
      std::filesystem::rename(tmp, json_path);
      std::cout << "wrote " << json_path << "\n";
    }
    {
      // Output digests (X-propagation): the whole run, then each model in construction order.
      const auto& rt = verilator_runtime();
      auto hex = [](uint64_t v) {
        char d[32];
        std::snprintf(d, sizeof d, "%016llx", static_cast<unsigned long long>(v));
        return std::string(d);
      };
      std::cout << "output digest: " << hex(rt.total.hash) << " (" << rt.total.cycles << " model cycles)\n";
      if (!digest_path.empty()) {
        std::ofstream out(digest_path);
        out << hex(rt.total.hash) << " " << rt.total.cycles << " " << rt.total.model << "\n";
        for (const auto& d : rt.per_model) out << hex(d.hash) << " " << d.cycles << " " << d.model << "\n";
        if (!out) throw std::runtime_error("cannot write " + digest_path);
      }
    }
    std::cout << (ok ? "sim_regression: PASS" : "sim_regression: FAIL") << "\n";
    return ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "sim_regression: " << e.what() << "\n";
    return 1;
  }
}
