// SPDX-License-Identifier: Apache-2.0
// device_search: the device's narrowest build configuration for an error budget, by measurement
// on its golden model (docs/device.md#configurations-per-budget, docs/display_exact.md#search).
//   device_search --budget b1|b2|b3|b4 [--n-max N] [--blend off|on|both] [--json FILE]
// For each ROM 12 bank set (decoder 10's table derived from it), one bank per n (blend off:
// kSingleSets, minimax coefficients in ROM 9) and two blended banks per n (blend on: kBlendSets,
// the minimax fit of model/reference/blend.hpp, each bank over its own domain), the widths are
// narrowed one at a time, the one that moves the most ROM bits first, each to the smallest value
// whose configuration meets the budget on every n of 1..n-max (device_error: three scanlines of
// 2048 pixels per n; deterministic, so no second sweep), in passes until none narrows. The result
// per bank set, "best": the one with the fewest ROM bits that the RTL and romgen build (one bank
// per n, every bank over [0, pi/2): the first five single sets), and "best_blend": the blend with
// the fewest (ROM 9's integer bits as many as its largest word needs); with the worst error per n
// and in 8-bit sRGB codes. A configuration the model refuses (a ROM word that does not fit) is
// reported with the reason. Exit 1 when no bank set meets the budget (the JSON is written all the
// same).
#include "blend.hpp"
#include "blend_rom.hpp"
#include "cli_parse.hpp"
#include "decoder_table.hpp"
#include "device_error.hpp"
#include "device_model.hpp"
#include "narrow_fields.hpp"
#include "phong_error.hpp"
#include "rom_image.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using specular::device::Format;
using specular::device::PixelBudget;

namespace {

// The bank sets tried with one bank per n: the patent's, the default build's, two between them, one
// past k = 16 (cos^k(a x) departs from cos^n by about 1/(12 k) of the pixel at the epicenter's end),
// and one up to k = 1024 (banks past 16 over their own domains: no longer built by romgen).
const std::vector<std::vector<int>> kSingleSets{{1, 2, 4, 16},
                                                {1, 2, 4, 8, 16},
                                                {1, 2, 3, 4, 6, 8, 16},
                                                {1, 2, 3, 4, 6, 8, 12, 16},
                                                {1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64},
                                                {1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 128, 256, 512, 1024}};
constexpr size_t kRtlSets = 5;  // the first five: every shift 0, what the RTL and romgen build
// The bank sets tried blended (docs/display_exact.md#measured): two quoted there, sparser ones past
// n = 16 (the blend's own error there is far below every budget, down to the last bank read twice
// at two angles), and denser ones below 16 (the worst n are 3 and 5).
const std::vector<std::vector<int>> kBlendSets{{1, 2, 4, 16, 64, 256, 1024},
                                               {1, 2, 3, 4, 8, 16, 64, 256, 1024},
                                               {1, 2, 3, 4, 8, 16, 256},
                                               {1, 2, 3, 4, 8, 16},
                                               {1, 2, 3, 4, 6, 8, 16},
                                               {1, 2, 3, 4, 8},
                                               {1, 2, 4, 8, 16},
                                               {1, 2, 4, 8}};

using Field = specular::SearchField<Format>;

// The integer bits of ROM 9's words stay those of the default build; coef_frac follows coef_bits.
const std::vector<Field>& fields() {
  static const std::vector<Field> v{
      {"cos_addr_bits", &Format::cos_addr_bits, 2},  {"cos_data_bits", &Format::cos_data_bits, 4},
      {"cos_delta_bits", &Format::cos_delta_bits, 1}, {"coef_bits", &Format::coef_bits, 6},
      {"cos_frac_bits", &Format::cos_frac_bits, 1},  {"psi_mul_frac", &Format::psi_mul_frac, 2},
  };
  return v;
}
// Blend mode narrows the weight too.
const std::vector<Field>& blend_fields() {
  static const std::vector<Field> v = [] {
    std::vector<Field> w = fields();
    w.push_back({"weight_bits", &Format::weight_bits, 2});
    return w;
  }();
  return v;
}

long rom_bits(const Format& f) {
  return static_cast<long>(f.coef_rom_depth()) * f.coef_word_bits() +
         static_cast<long>(f.cos_rom_depth()) * f.cos_word_bits();
}

// The coefficients of a bank set, computed once per run (they do not depend on the widths):
// single: coefficient(n, k) of every bank of every n; blend: the fits of n in 1..n_max.
struct Coefs {
  std::map<std::pair<int, int>, double> single;
  std::vector<specular::BlendCoef> blend;
};

std::vector<uint32_t> single_coef_rom(const Format& f, const specular::CoefSpec& spec, Coefs& c) {
  std::vector<uint32_t> img(f.coef_rom_depth(), 0);
  for (int n = 1; n <= f.max_n(); ++n) {
    const int j = specular::decoder_bank(f.bank_max_n, n);
    const int k = f.banks[j];
    auto it = c.single.find({n, k});
    if (it == c.single.end()) it = c.single.emplace(std::make_pair(n, k), specular::coefficient(n, k, spec)).first;
    img[n] = specular::coef_word(std::ldexp(it->second, f.shift_of(j)), f);  // as coef_rom_image
  }
  return img;
}

struct Result {
  bool meets = false;
  double rel_lsb = 0.0, abs_lsb = 0.0, abs_raw = 0.0;
  int worst_n = 0;
  double used = 0.0;                  // the largest fraction of a budget bound used, over n
  int srgb8 = 0;                      // worst difference in 8-bit sRGB codes
  std::string refused;                // why the model or its ROMs refused the configuration
  std::vector<double> abs_raw_n;      // per n (1..n_max) when asked for
  std::vector<int> srgb8_n;
};

// The budget on every n of 1..n_max (largest first: the error grows with n); stop_early ends at
// the first n that misses. A configuration the model or its ROMs refuse does not meet it.
// ROM 12's step field grows where the address narrows: cos_delta_bits is raised (in f) to the
// smallest width that holds every step of the table.
std::vector<uint32_t> cos_rom_fitted(Format& f) {
  for (;;) {
    try {
      return specular::cos_rom_image(f);
    } catch (const std::invalid_argument& e) {
      if (std::string(e.what()).find("does not fit") == std::string::npos || f.cos_word_bits() >= 32) throw;
      ++f.cos_delta_bits;
    }
  }
}

specular::device::DeviceModel model(Format& f, const specular::CoefSpec& spec, Coefs& c) {
  std::vector<uint32_t> cos_rom = cos_rom_fitted(f);
  if (f.blend) return specular::blend_device_model(f, c.blend, std::move(cos_rom));
  return specular::device::DeviceModel(f, single_coef_rom(f, spec, c), std::move(cos_rom));
}

Result measure(Format& f, const specular::CoefSpec& spec, Coefs& c, int n_max, const PixelBudget& b, bool stop_early,
               bool per_n = false) {
  Result r;
  if (per_n) {
    r.abs_raw_n.assign(n_max, 0.0);
    r.srgb8_n.assign(n_max, 0);
  }
  try {
    const specular::device::DeviceModel dm = model(f, spec, c);
    const double lsb = std::ldexp(1.0, -f.c_frac);
    r.meets = true;
    double worst = -1.0;
    for (int n = n_max; n >= 1; --n) {
      const specular::DeviceError e = specular::device_error(dm, n);
      r.srgb8 = std::max(r.srgb8, e.max_srgb8_codes);
      if (per_n) {
        r.abs_raw_n[n - 1] = e.max_abs_lobe;
        r.srgb8_n[n - 1] = e.max_srgb8_codes;
      }
      const double abs_lsb = std::max(0.0, e.max_abs_lobe - lsb);
      r.rel_lsb = std::max(r.rel_lsb, e.max_rel_epicenter_lsb);
      r.abs_lsb = std::max(r.abs_lsb, abs_lsb);
      r.abs_raw = std::max(r.abs_raw, e.max_abs_lobe);
      const double used = std::max({e.max_rel_epicenter_lsb / b.rel_lsb, abs_lsb / b.abs_lsb, e.max_abs_lobe / b.abs_raw});
      if (used > worst) {
        worst = used;
        r.worst_n = n;
        r.used = used;
      }
      if (used > 1.0) {
        r.meets = false;
        if (stop_early) break;
      }
    }
  } catch (const std::invalid_argument& e) {
    r.meets = false;
    r.refused = e.what();
  } catch (const std::logic_error& e) {
    r.meets = false;
    r.refused = e.what();
  }
  return r;
}

// A configuration as JSON; the single-bank one in the form scripts/budget_roms.py reads (as
// before), a blend one with "blend", "bank_shift" and "weight_bits" besides.
nlohmann::json format_json(const Format& f) {
  nlohmann::json j;
  j["banks"] = f.banks;
  j["bank_max_n"] = f.bank_max_n;
  for (const Field& fd : fields()) j[fd.name] = f.*(fd.member);
  j["coef_frac"] = f.coef_frac;
  j["rom_bits"] = rom_bits(f);
  if (f.blend) {
    j["blend"] = true;
    j["weight_bits"] = f.weight_bits;
  }
  if (!f.bank_shift.empty()) j["bank_shift"] = f.bank_shift;
  return j;
}

// The method's own error before any quantization (double, docs/display_exact.md#measured): the
// largest |F(x) - cos^n(x)| over n in 1..n_max, x sampled at 4000 points of [0, min(pi/2,
// sqrt(40/n))] (past it every term is below e^-20), F = cos^k(a x) with the minimax a of decoder
// 10's bank, or the blend fit.
double float_error(const Format& f, const specular::CoefSpec& spec, Coefs& c, int n_max) {
  double worst = 0.0;
  for (int n = 1; n <= n_max; ++n) {
    specular::BlendCoef bc;
    if (f.blend) {
      bc = c.blend[n - 1];
    } else {
      const int k = f.banks[specular::decoder_bank(f.bank_max_n, n)];
      auto it = c.single.find({n, k});
      if (it == c.single.end()) it = c.single.emplace(std::make_pair(n, k), specular::coefficient(n, k, spec)).first;
      bc = {n, k, k, it->second, it->second, 0.0, 0.0};
    }
    const double end = std::min(std::numbers::pi / 2, std::sqrt(40.0 / n));
    for (int i = 0; i <= 4000; ++i) {
      const double x = end * i / 4000;
      worst = std::max(worst, std::abs(specular::blend_value(bc, x) - std::pow(std::cos(x), n)));
    }
  }
  return worst;
}

// The largest ROM 9 coefficient of a blend format in quarter turns, a * 2^shift * 2/pi, over both
// fields of every n (the fits of `table`, blend_maclaurin past it, as blend_rom_fields fills them).
double max_coef_quarter_turns(const Format& f, const std::vector<specular::BlendCoef>& table) {
  double top = 0.0;
  for (int n = 1; n <= f.max_n(); ++n) {
    const int j = specular::decoder_bank(f.bank_max_n, n);
    const int j2 = std::min(j + 1, static_cast<int>(f.banks.size()) - 1);
    const specular::BlendCoef c = n <= static_cast<int>(table.size())
                                      ? table[n - 1]
                                      : specular::blend_maclaurin(n, f.banks[j], f.banks[j2]);
    top = std::max({top, std::ldexp(c.a1, f.shift_of(j)) * 2 / std::numbers::pi,
                    std::ldexp(c.a2, f.shift_of(j2)) * 2 / std::numbers::pi});
  }
  return top;
}

// Four significant digits: the per-n arrays stay readable.
double sig4(double v) {
  if (v == 0.0) return 0.0;
  const double p = std::pow(10.0, 3 - static_cast<int>(std::floor(std::log10(std::abs(v)))));
  return std::round(v * p) / p;
}

std::string set_text(const std::vector<int>& banks) {
  std::string set;
  for (int k : banks) set += (set.empty() ? "" : ",") + std::to_string(k);
  return set;
}

// --sweep: the dense absolute error of a build configuration per n (dense_abs_error), from its
// committed ROM files (working directory: the repository root), on every core.
int run_sweep(const std::string& name, int n_max, int points, const std::string& json_out) {
  const specular::BuildConfig* bc = nullptr;
  try {
    bc = &specular::build_config(name);
  } catch (const std::invalid_argument& e) {
    std::cerr << "device_search: --sweep: " << e.what() << "\n";
    return 2;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const specular::device::DeviceModel dm = specular::load_device_model(bc->f, bc->coef_hex(), bc->cos_hex());
  std::vector<specular::DenseError> per_n(static_cast<size_t>(n_max));
  const unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1U, 16U);
  auto work = [&](unsigned id) {
    for (int n = 1 + static_cast<int>(id); n <= n_max; n += static_cast<int>(threads)) {
      const double end = std::min(std::numbers::pi / 2, std::sqrt(40.0 / n));
      const auto step = std::max<int64_t>(1, std::llround(std::ldexp(end, bc->f.angle_frac) / points));
      per_n[n - 1] = specular::dense_abs_error(dm, n, step);
    }
  };
  std::vector<std::thread> pool;
  for (unsigned id = 1; id < threads; ++id) pool.emplace_back(work, id);
  work(0);
  for (auto& t : pool) t.join();
  const double bound = bc->budget.abs_lobe;
  int worst_n = 1;
  long pixels = 0;
  nlohmann::json abs_n = nlohmann::json::array();
  for (int n = 1; n <= n_max; ++n) {
    if (per_n[n - 1].max_abs > per_n[worst_n - 1].max_abs) worst_n = n;
    pixels += per_n[n - 1].pixels;
    abs_n.push_back(sig4(per_n[n - 1].max_abs));
  }
  const specular::DenseError& w = per_n[worst_n - 1];
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const bool ok = w.max_abs <= bound;
  std::printf("device_search --sweep %s: n <= %d, %ld pixels (%d angles per n over the lobe), C = 1: worst |err| "
              "%.6g C at n = %d, psi = %.5f: %.4f of the budget %.6g C, %s (%.1f s)\n",
              name.c_str(), n_max, pixels, points, w.max_abs, worst_n, w.psi, w.max_abs / bound, bound,
              ok ? "meets it" : "OVER BUDGET", secs);
  if (!json_out.empty()) {
    const nlohmann::json j{{"config", name},      {"n_max", n_max},          {"angles_per_n", points},
                           {"pixels", pixels},    {"budget_abs", bound},     {"worst_abs", w.max_abs},
                           {"worst_n", worst_n},  {"worst_psi", w.psi},      {"budget_used", w.max_abs / bound},
                           {"meets", ok},         {"abs_per_n", abs_n}};
    std::ofstream o(json_out);
    o << j.dump(1) << "\n";
    if (!o) {
      std::cerr << "device_search: cannot write " << json_out << "\n";
      return 1;
    }
  }
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::string budget = "b1", json_out, blend = "both";
  int n_max = 1000;
  CLI::App app{"Find the device's narrowest build configuration for an error budget (docs/metrics.md#budgets)"};
  app.add_option("--budget", budget, "b1, b2, b3 or b4")
      ->check(CLI::IsMember({"b1", "b2", "b3", "b4"}))
      ->capture_default_str();
  app.add_option("--n-max", n_max, "largest exponent the configuration must serve (1..1000)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  app.add_option("--blend", blend, "off: one bank per n, on: two blended banks (docs/display_exact.md), both")
      ->check(CLI::IsMember({"off", "on", "both"}))
      ->capture_default_str();
  app.add_option("--json", json_out, "write the result to this file");
  std::string sweep;
  int sweep_points = 200000;
  app.add_option("--sweep", sweep,
                 "instead of a search: sweep build configuration NAME (rom_image.hpp build_configs(), its committed "
                 "ROM files) densely for every n of 1..n-max against its absolute budget; exit 1 when over it");
  app.add_option("--sweep-points", sweep_points, "--sweep: angles per n over the lobe")
      ->check(CLI::Range(1000, 100000000))
      ->capture_default_str();
  if (auto rc = specular::parse_command_line(app, argc, argv, "device_search")) return *rc;
  if (!sweep.empty()) return run_sweep(sweep, n_max, sweep_points, json_out);
  const auto t_start = std::chrono::steady_clock::now();
  const PixelBudget b = PixelBudget::named(budget);
  const specular::BuildConfig& start = specular::build_config("single");
  const specular::CoefSpec spec = specular::parse_coef_spec(start.policy);
  const int coef_int = start.f.coef_bits - start.f.coef_frac;

  struct Plan {
    std::vector<int> banks;
    bool blend;
    bool rtl;
  };
  std::vector<Plan> plans;
  if (blend != "on")
    for (size_t i = 0; i < kSingleSets.size(); ++i) plans.push_back({kSingleSets[i], false, i < kRtlSets});
  if (blend != "off")
    for (const auto& s : kBlendSets) plans.push_back({s, true, false});

  nlohmann::json runs = nlohmann::json::array();
  struct Best {
    Format f;
    long bits = -1;
    Result r;
  } best, best_blend;
  Coefs single_coefs;  // shared by the single-bank sets
  for (const Plan& plan : plans) {
    Format f = start.f;
    Coefs blend_coefs;
    int plan_coef_int = coef_int;
    if (plan.blend) {
      f = specular::blend_format(start.f, plan.banks);
      blend_coefs.blend = specular::blend_minimax_table(plan.banks, n_max);
      // ROM 9's integer bits: the default build's, or as many as the blend's largest word needs (the
      // last bank read twice at two angles for n far above it takes a > sqrt(n / k)).
      const double top = max_coef_quarter_turns(f, blend_coefs.blend);
      while (std::ldexp(1.0, plan_coef_int) <= top) ++plan_coef_int;
      f.coef_bits = f.coef_frac + plan_coef_int;
    } else {
      f.banks = plan.banks;
      f.bank_max_n = specular::derive_bank_max_n(plan.banks, spec);
      if (!plan.rtl) f.bank_shift = specular::derive_bank_shift(plan.banks);
    }
    Coefs& coefs = plan.blend ? blend_coefs : single_coefs;
    const std::string set = set_text(plan.banks);
    const char* mode = plan.blend ? "blend" : "single";
    const double float_abs = float_error(f, spec, coefs, n_max);
    if (!measure(f, spec, coefs, n_max, b, true).meets) {
      // Its errors at the default widths, every n: why it is out.
      const Result m = measure(f, spec, coefs, n_max, b, false);
      if (!m.refused.empty()) {
        std::printf("%s banks {%s}: refused at the default widths: %s\n", mode, set.c_str(), m.refused.c_str());
        std::fflush(stdout);
        nlohmann::json j{{"banks", plan.banks}, {"meets", false}, {"refused", m.refused}, {"float_abs", float_abs}};
        if (plan.blend) j["blend"] = true;
        runs.push_back(j);
        continue;
      }
      std::printf("%s banks {%s}: misses at the default widths: rel %.3e abs %.3e raw %.3e sRGB %d (worst at n = %d); "
                  "unquantized %.3e\n",
                  mode, set.c_str(), m.rel_lsb, m.abs_lsb, m.abs_raw, m.srgb8, m.worst_n, float_abs);
      std::fflush(stdout);
      nlohmann::json j{{"banks", plan.banks}, {"meets", false}, {"rel_lsb", m.rel_lsb}, {"abs_lsb", m.abs_lsb},
                       {"abs_raw", m.abs_raw}, {"worst_n", m.worst_n}, {"srgb8_codes", m.srgb8},
                       {"float_abs", float_abs}};
      if (plan.blend) j["blend"] = true;
      runs.push_back(j);
      continue;
    }
    // ROM 9's fraction follows its width; a table keeps the step width it needed.
    specular::narrow_fields(
        f, plan.blend ? blend_fields() : fields(),
        [&](Format& g) {
          g.coef_frac = g.coef_bits - plan_coef_int;
          return measure(g, spec, coefs, n_max, b, true).meets;
        },
        [](const Field&, const Format&) {});
    const Result r = measure(f, spec, coefs, n_max, b, false, true);
    std::printf("%s banks {%s}: addr %d data %d delta %d frac %d coef %d/%d psi %d%s: %ld ROM bits; rel %.3e abs %.3e "
                "raw %.3e sRGB %d (worst at n = %d, %.3f of the budget) %s; unquantized %.3e\n",
                mode, set.c_str(), f.cos_addr_bits, f.cos_data_bits, f.cos_delta_bits, f.cos_frac_bits, f.coef_bits,
                f.coef_frac, f.psi_mul_frac, plan.blend ? (" weight " + std::to_string(f.weight_bits)).c_str() : "",
                rom_bits(f), r.rel_lsb, r.abs_lsb, r.abs_raw, r.srgb8, r.worst_n, r.used,
                r.meets ? "meets" : "OVER BUDGET", float_abs);
    std::fflush(stdout);
    nlohmann::json j = format_json(f);
    j["meets"] = r.meets;
    j["rel_lsb"] = r.rel_lsb;
    j["abs_lsb"] = r.abs_lsb;
    j["abs_raw"] = r.abs_raw;
    j["worst_n"] = r.worst_n;
    j["srgb8_codes"] = r.srgb8;
    j["budget_used"] = r.used;
    j["float_abs"] = float_abs;
    runs.push_back(j);
    Best& slot = plan.blend ? best_blend : best;
    if (r.meets && (plan.blend || plan.rtl) && (slot.bits < 0 || rom_bits(f) < slot.bits)) slot = {f, rom_bits(f), r};
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  if (best.bits < 0 && best_blend.bits < 0)
    std::cerr << "device_search: no bank set meets budget " << budget << " for n <= " << n_max << "\n";
  if (best.bits >= 0) std::printf("fewest ROM bits: %ld (banks of %zu)\n", best.bits, best.f.banks.size());
  if (best_blend.bits >= 0)
    std::printf("fewest ROM bits blended: %ld (banks {%s}), worst %.3f of the budget (n = %d), %d sRGB codes\n",
                best_blend.bits, set_text(best_blend.f.banks).c_str(), best_blend.r.used, best_blend.r.worst_n,
                best_blend.r.srgb8);
  std::printf("search time %.1f s\n", secs);
  if (!json_out.empty()) {
    auto with_errors = [&](const Best& x) {
      if (x.bits < 0) return nlohmann::json(nullptr);
      nlohmann::json j = format_json(x.f);
      j["abs_raw"] = x.r.abs_raw;
      j["budget_used"] = x.r.used;
      j["worst_n"] = x.r.worst_n;
      j["srgb8_codes"] = x.r.srgb8;
      std::vector<double> raw;
      for (double v : x.r.abs_raw_n) raw.push_back(sig4(v));
      j["abs_raw_per_n"] = raw;  // index n - 1
      j["srgb8_per_n"] = x.r.srgb8_n;
      return j;
    };
    nlohmann::json j;
    j["budget"] = budget;
    j["n_max"] = n_max;
    j["policy"] = start.policy;
    j["blend_mode"] = blend;
    j["seconds"] = std::round(secs);
    j["runs"] = runs;
    j["best"] = best.bits < 0 ? nlohmann::json(nullptr) : format_json(best.f);
    j["best_errors"] = with_errors(best);
    j["best_blend"] = with_errors(best_blend);
    std::ofstream out(json_out);
    out << j.dump(1) << "\n";
    if (!out) {
      std::cerr << "device_search: error: cannot write " << json_out << "\n";
      return 1;
    }
  }
  return best.bits < 0 && best_blend.bits < 0 ? 1 : 0;
}
