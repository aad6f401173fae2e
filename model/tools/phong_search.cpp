// SPDX-License-Identifier: Apache-2.0
// phong_search: the configuration search of phong_stream by measurement on its golden model
// (docs/phong_hw.md#configuration-search).
//   phong_search --n-max 1000                 the narrowest configuration meeting the device's
//                                             budget for every n in 1..n-max, then its error per n
//   --form cross                              the cancellation-free form (its own fields and start)
//   --budget b2                               budget B1 (default), B2, B3 or B4 (docs/metrics.md#budgets)
//   phong_search --eval --op-bits 24 ...      the error per n of one configuration
//   phong_search --measure n64 --n-step 10    the error of a preset configuration (the names of
//                                             roms/phong/phong_configs.cmake) on n = 1, 1+S, ...,
//                                             1000, one seed: make report's hardware plane
//   --json FILE                               the result (configuration, widths, error per n)
// Widths are reduced one at a time, largest cost first (passes until none changes), each to the smallest value whose
// configuration still meets 90 % of the budget on every n of 1..n-max; the result is then
// measured at the budget on the sweeps of two other seeds, and where it misses, widened one
// field at a time (the one that meets, cheapest first, or else the one that helps most).
#include "cli_parse.hpp"
#include "narrow_fields.hpp"
#include "phong_error.hpp"
#include "phong_model.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <set>
#include <string>
#include <utility>
#include <vector>

using specular::device::PixelBudget;
using specular::device::PhongError;
using specular::device::PhongForm;
using specular::device::PhongFormat;
using specular::device::PhongModel;

namespace {

// The search holds a configuration to 90 % of the budget on its sweep, so that the result
// meets the budget itself on the sweeps of two other seeds.
constexpr double kMargin = 0.9;

using Field = specular::SearchField<PhongFormat>;

const std::vector<Field>& cross_fields() {
  // The cross form (docs/phong_hw.md#the-cancellation-free-form): the fifteen operand products
  // first, then the scaled cross product's squares, the reciprocal and the power unit, then the
  // ROM sizes.
  static const std::vector<Field> v{
      {"op_bits", &PhongFormat::op_bits, 8},
      {"u_bits", &PhongFormat::u_bits, 4},
      {"norm_bits", &PhongFormat::norm_bits, 8},
      {"rcp_bits", &PhongFormat::rcp_bits, 8},
      {"s_frac", &PhongFormat::s_frac, 8},
      {"log_bits", &PhongFormat::log_bits, 8},
      {"exp_bits", &PhongFormat::exp_bits, 8},
      {"dm_frac", &PhongFormat::dm_frac, 4},
      {"cos_frac", &PhongFormat::cos_frac, 8},
      {"g_bits", &PhongFormat::g_bits, 4},
      {"rcp_addr_bits", &PhongFormat::rcp_addr_bits, 2},
      {"g_addr_bits", &PhongFormat::g_addr_bits, 1},
      {"log_addr_bits", &PhongFormat::log_addr_bits, 1},
      {"exp_addr_bits", &PhongFormat::exp_addr_bits, 1},
      {"rcp_frac_bits", &PhongFormat::rcp_frac_bits, 1},
      {"g_frac_bits", &PhongFormat::g_frac_bits, 1},
      {"log_frac_bits", &PhongFormat::log_frac_bits, 1},
      {"exp_frac_bits", &PhongFormat::exp_frac_bits, 1},
  };
  return v;
}

// The budget and form of this run (main sets them before any search).
PixelBudget g_budget = PixelBudget::b1();
bool g_cross = false;

const std::vector<Field>& search_fields() {
  if (g_cross) return cross_fields();
  // Order: what drives the cost most first (the nine dot-product multipliers, then the
  // normalization's multipliers, the power unit's), then the ROM sizes.
  static const std::vector<Field> v{
      {"op_bits", &PhongFormat::op_bits, 8},
      {"norm_bits", &PhongFormat::norm_bits, 8},
      {"cos_frac", &PhongFormat::cos_frac, 8},
      {"log_bits", &PhongFormat::log_bits, 8},
      {"exp_bits", &PhongFormat::exp_bits, 8},
      {"newton", &PhongFormat::newton, 0},
      {"rsqrt_addr_bits", &PhongFormat::rsqrt_addr_bits, 2},
      {"log_addr_bits", &PhongFormat::log_addr_bits, 1},
      {"exp_addr_bits", &PhongFormat::exp_addr_bits, 1},
      {"log_frac_bits", &PhongFormat::log_frac_bits, 1},
      {"exp_frac_bits", &PhongFormat::exp_frac_bits, 1},
  };
  return v;
}

bool valid(const PhongFormat& f) {
  try {
    f.validate();
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

struct Sweep {
  std::vector<PhongError> per_n;
  double rel_lsb = 0.0, abs_lsb = 0.0, abs_raw = 0.0;
  bool meets = true;
};

Sweep sweep(const PhongFormat& f, const std::vector<int>& ns, uint64_t seed, bool stop_early, double margin = 1.0) {
  const PhongModel m(f);
  Sweep s;
  for (int n : ns) {
    const PhongError e = specular::device::phong_error(m, n, seed);
    s.per_n.push_back(e);
    s.rel_lsb = std::max(s.rel_lsb, e.rel_lsb);
    s.abs_lsb = std::max(s.abs_lsb, e.abs_lsb);
    s.abs_raw = std::max(s.abs_raw, e.abs_raw);
    if (!e.meets(g_budget, margin)) {
      s.meets = false;
      if (stop_early) break;
    }
  }
  return s;
}

// Every n of 1..n_max, largest first (the error grows with n, so a failing configuration
// usually fails on the first few).
std::vector<int> search_set(int n_max) {
  std::vector<int> v;
  for (int n = n_max; n >= 1; --n) v.push_back(n);
  return v;
}

nlohmann::json format_json(const PhongFormat& f) {
  nlohmann::json j;
  j["form"] = f.form == PhongForm::cross ? "cross" : "dot";
  j["const_h"] = f.const_h;
  for (const Field& fd : search_fields()) j[fd.name] = f.*(fd.member);
  return j;
}

// The presets by the names of roms/phong/phong_configs.cmake (phong_configs()).
const std::vector<std::pair<std::string, PhongFormat>>& presets() {
  static const std::vector<std::pair<std::string, PhongFormat>> v = [] {
    std::vector<std::pair<std::string, PhongFormat>> r;
    for (const auto& c : specular::device::phong_configs()) r.emplace_back(c.name, c.f);
    return r;
  }();
  return v;
}

// --measure: the error of one preset on the n grid 1, 1+S, ..., 1000 (report_data's grid).
int measure_preset(const std::string& name, int n_step, uint64_t seed, const std::string& json_out) {
  const auto& ps = presets();
  const auto it = std::find_if(ps.begin(), ps.end(), [&](const auto& p) { return p.first == name; });
  if (it == ps.end()) {
    std::string all;
    for (const auto& p : ps) all += (all.empty() ? "" : ", ") + p.first;
    std::cerr << "phong_search: error: --measure '" << name << "' is not a configuration; allowed: " << all << "\n";
    return 2;
  }
  if (n_step < 1 || n_step > 999) {
    std::cerr << "phong_search: error: --n-step must be in 1..999 (got " << n_step << ")\n";
    return 2;
  }
  std::vector<int> ns;
  for (int n = 1; n <= 1000; n += n_step) ns.push_back(n);
  if (ns.back() != 1000) ns.push_back(1000);
  const Sweep s = sweep(it->second, ns, seed, false);
  std::printf("%s (%s): n 1..1000 step %d: max rel epicenter (|err| - 1 LSB)/ref %.3e, max abs (|err| - 1 LSB)/C %.3e\n",
              name.c_str(), it->second.describe().c_str(), n_step, s.rel_lsb, s.abs_lsb);
  if (!json_out.empty()) {
    nlohmann::json j;
    j["name"] = name;
    j["format"] = format_json(it->second);
    j["describe"] = it->second.describe();
    j["seed"] = seed;
    j["n_step"] = n_step;
    for (const PhongError& e : s.per_n) {
      j["n"].push_back(e.n);
      j["rel_lsb"].push_back(e.rel_lsb);
      j["abs_lsb"].push_back(e.abs_lsb);
      j["abs_raw"].push_back(e.abs_raw);
    }
    std::ofstream out(json_out);
    out << j.dump(1) << "\n";
    if (!out) {
      std::cerr << "phong_search: error: cannot write " << json_out << "\n";
      return 1;
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // --form is read first: it picks the start configuration and the fields the options set.
  std::string form = "dot", budget = "b1";
  for (int i = 1; i + 1 < argc; ++i)
    if (std::string(argv[i]) == "--form") form = argv[i + 1];
  if (form != "dot" && form != "cross") {
    std::cerr << "phong_search: error: --form must be dot or cross (got '" << form << "')\n";
    return 2;
  }
  g_cross = form == "cross";
  PhongFormat f = g_cross ? PhongFormat::cross() : PhongFormat{};
  int n_max = 1000;
  bool eval = false;
  std::string measure;
  int n_step = 1;
  uint64_t seed = 1;
  std::string json_out;
  CLI::App app{"Find the narrowest phong_stream configuration that meets the device's error budget"};
  app.add_option("--n-max", n_max, "largest exponent the configuration must serve (1..1000)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  app.add_flag("--eval", eval, "measure the given configuration on every n instead of searching");
  std::string names;
  for (const auto& p : presets()) names += (names.empty() ? "" : ", ") + p.first;
  app.add_option("--measure", measure,
                 "measure this configuration of roms/phong/phong_configs.cmake on n = 1, 1+S, ..., 1000 (one "
                 "seed) instead of searching: " + names);
  app.add_option("--n-step", n_step, "with --measure: the step S of the n grid (1..999)")->capture_default_str();
  app.add_option("--seed", seed, "seed of the sweep's random frames")->capture_default_str();
  app.add_option("--json", json_out, "write the result to this file");
  app.add_flag("--const-h", f.const_h, "constant H (He = H1)");
  app.add_option("--form", form, "dot (the textbook normalized dot product) or cross (the cancellation-free form)")
      ->capture_default_str();
  app.add_option("--budget", budget, "the error budget (docs/metrics.md#budgets): b1, b2, b3 or b4")
      ->check(CLI::IsMember({"b1", "b2", "b3", "b4"}))
      ->capture_default_str();
  for (const Field& fd : search_fields())
    app.add_option(std::string("--") + [&] {
                     std::string s = fd.name;
                     std::replace(s.begin(), s.end(), '_', '-');
                     return s;
                   }(),
                   f.*(fd.member), "start value (search) or value (eval)")
        ->capture_default_str();
  if (auto rc = specular::parse_command_line(app, argc, argv, "phong_search")) return *rc;
  g_budget = PixelBudget::named(budget);
  if (!measure.empty()) return measure_preset(measure, n_step, seed, json_out);
  try {
    f.validate();
  } catch (const std::invalid_argument& e) {
    std::cerr << "phong_search: error: " << e.what() << "\n";
    return 2;
  }

  std::vector<int> all;
  for (int n = 1; n <= n_max; ++n) all.push_back(n);
  if (!eval) {
    const std::vector<int> ns = search_set(n_max);
    if (!sweep(f, ns, seed, true, kMargin).meets) {
      std::cerr << "phong_search: error: the start configuration (" << f.describe()
                << ") does not meet the budget; start wider\n";
      return 1;
    }
    // Passes until none narrows a field: a field bounded by another (log_frac_bits by
    // cos_frac, exp_frac_bits by log_bits) can shrink once the other has.
    specular::narrow_fields(
        f, search_fields(), [&](const PhongFormat& g) { return valid(g) && sweep(g, ns, seed, true, kMargin).meets; },
        [](const Field& fd, const PhongFormat& g) {
          std::cerr << fd.name << " = " << g.*(fd.member) << "   (" << g.describe() << ")\n";
        });
  }
  // The result on every n with two other seeds, at the budget itself. When the search's
  // result misses it there (the sweep of one seed did not hit the worst geometry), one field
  // is widened by one, the cheapest first, until both other seeds meet the budget.
  auto confirm = [&](const PhongFormat& g, double margin) {
    Sweep full = sweep(g, all, seed + 1, false, margin);
    const Sweep other = sweep(g, all, seed + 2, false, margin);
    for (size_t i = 0; i < full.per_n.size(); ++i) {
      PhongError& e = full.per_n[i];
      const PhongError& o = other.per_n[i];
      e.rel_lsb = std::max(e.rel_lsb, o.rel_lsb);
      e.abs_lsb = std::max(e.abs_lsb, o.abs_lsb);
      e.abs_raw = std::max(e.abs_raw, o.abs_raw);
      e.rel_raw = std::max(e.rel_raw, o.rel_raw);
      e.rel_lsb_truth = std::max(e.rel_lsb_truth, o.rel_lsb_truth);
      e.abs_lsb_truth = std::max(e.abs_lsb_truth, o.abs_lsb_truth);
    }
    full.rel_lsb = std::max(full.rel_lsb, other.rel_lsb);
    full.abs_lsb = std::max(full.abs_lsb, other.abs_lsb);
    full.abs_raw = std::max(full.abs_raw, other.abs_raw);
    full.meets = full.meets && other.meets;
    return full;
  };
  // The fraction of the budget a sweep uses (its worst bound).
  auto used = [&](const Sweep& w) {
    return std::max({w.rel_lsb / g_budget.rel_lsb, w.abs_lsb / g_budget.abs_lsb, w.abs_raw / g_budget.abs_raw});
  };
  Sweep full = confirm(f, 1.0);
  // Each round widens the one field (by one) that meets the budget, the cheapest first, or
  // else the one that lowers the used fraction most, and goes round again.
  for (int round = 0; round < 8 && !eval && !full.meets; ++round) {
    const auto& fields = search_fields();
    PhongFormat best = f;
    Sweep best_s = full;
    std::string best_name;
    for (auto it = fields.rbegin(); it != fields.rend(); ++it) {
      PhongFormat g = f;
      g.*(it->member) += 1;
      if (!valid(g)) continue;
      const Sweep s = confirm(g, 1.0);
      if (s.meets || used(s) < used(best_s)) {
        best = g;
        best_s = s;
        best_name = it->name;
        if (s.meets) break;
      }
    }
    if (best_name.empty()) {  // no single field helps: widen the operands
      best.op_bits += 1;
      best_s = confirm(best, 1.0);
      best_name = "op_bits";
    }
    f = best;
    full = best_s;
    std::cerr << "widened " << best_name << " to " << f.*(std::find_if(fields.begin(), fields.end(), [&](const Field& x) {
                                                            return best_name == x.name;
                                                          })->member)
              << " (" << f.describe() << "), " << used(full) << " of the budget\n";
  }
  std::printf("configuration: %s\n", f.describe().c_str());
  std::printf("n 1..%d: max rel epicenter (|err| - 1 LSB)/ref %.3e, max abs (|err| - 1 LSB)/C %.3e, max |err|/C %.3e, "
              "%s %s\n",
              n_max, full.rel_lsb, full.abs_lsb, full.abs_raw, full.meets ? "meets the budget" : "OVER BUDGET",
              g_budget.name);
  double rt = 0, at = 0, raw = 0;
  for (const PhongError& e : full.per_n) {
    rt = std::max(rt, e.rel_lsb_truth);
    at = std::max(at, e.abs_lsb_truth);
    raw = std::max(raw, e.rel_raw);
  }
  std::printf("raw rel epicenter (n > 1) %.3e; against phong_truth: rel %.3e abs %.3e\n", raw, rt, at);
  if (!json_out.empty()) {
    nlohmann::json j;
    j["format"] = format_json(f);
    j["describe"] = f.describe();
    j["n_max"] = n_max;
    j["budget"] = g_budget.name;
    j["abs_raw"] = full.abs_raw;
    j["rel_lsb"] = full.rel_lsb;
    j["abs_lsb"] = full.abs_lsb;
    j["meets"] = full.meets;
    for (const PhongError& e : full.per_n)
      j["per_n"].push_back({{"n", e.n}, {"rel_lsb", e.rel_lsb}, {"rel_raw", e.rel_raw}, {"abs_lsb", e.abs_lsb},
                            {"abs_raw", e.abs_raw},
                            {"rel_lsb_truth", e.rel_lsb_truth}, {"abs_lsb_truth", e.abs_lsb_truth}});
    std::ofstream(json_out) << j.dump(1) << "\n";
  }
  return full.meets ? 0 : 1;
}
