// SPDX-License-Identifier: Apache-2.0
// device_search: the device's narrowest build configuration for an error budget, by measurement
// on its golden model (docs/device.md#configurations-per-budget).
//   device_search --budget b1|b2|b3 [--n-max N] [--json FILE]
// For each ROM 12 bank set of kBankSets (decoder 10's table derived from it, minimax coefficients
// in ROM 9), the widths are narrowed one at a time, the one that moves the most ROM bits first,
// each to the smallest value whose configuration meets the budget on every n of 1..n-max
// (device_error: three scanlines of 2048 pixels per n; deterministic, so no second sweep), in
// passes until none narrows. The result per bank set and the one with the fewest ROM bits; exit 1
// when no bank set meets the budget (the JSON is written all the same).
#include "cli_parse.hpp"
#include "decoder_table.hpp"
#include "device_error.hpp"
#include "device_model.hpp"
#include "narrow_fields.hpp"
#include "phong_error.hpp"
#include "rom_image.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

using specular::device::Format;
using specular::device::PixelBudget;

namespace {

// The bank sets tried: the patent's, the default build's, two between them, and one past k = 16
// (cos^k(a x) departs from cos^n by about 1/(12 k) of the pixel at the epicenter's end).
const std::vector<std::vector<int>> kBankSets{{1, 2, 4, 16},
                                              {1, 2, 4, 8, 16},
                                              {1, 2, 3, 4, 6, 8, 16},
                                              {1, 2, 3, 4, 6, 8, 12, 16},
                                              {1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64}};

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

long rom_bits(const Format& f) {
  return static_cast<long>(f.coef_rom_depth()) * f.coef_bits + static_cast<long>(f.cos_rom_depth()) * f.cos_word_bits();
}

struct Result {
  bool meets = false;
  double rel_lsb = 0.0, abs_lsb = 0.0, abs_raw = 0.0;
  int worst_n = 0;
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

Result measure(Format& f, const specular::CoefSpec& spec, int n_max, const PixelBudget& b, bool stop_early) {
  Result r;
  try {
    std::vector<uint32_t> cos_rom = cos_rom_fitted(f);
    const specular::device::DeviceModel dm(f, specular::coef_rom_image(f, spec), std::move(cos_rom));
    const double lsb = std::ldexp(1.0, -f.c_frac);
    r.meets = true;
    double worst = -1.0;
    for (int n = n_max; n >= 1; --n) {
      const specular::DeviceError e = specular::device_error(dm, n);
      const double abs_lsb = std::max(0.0, e.max_abs_lobe - lsb);
      r.rel_lsb = std::max(r.rel_lsb, e.max_rel_epicenter_lsb);
      r.abs_lsb = std::max(r.abs_lsb, abs_lsb);
      r.abs_raw = std::max(r.abs_raw, e.max_abs_lobe);
      const double used = std::max({e.max_rel_epicenter_lsb / b.rel_lsb, abs_lsb / b.abs_lsb, e.max_abs_lobe / b.abs_raw});
      if (used > worst) {
        worst = used;
        r.worst_n = n;
      }
      if (used > 1.0) {
        r.meets = false;
        if (stop_early) break;
      }
    }
  } catch (const std::invalid_argument&) {
    r.meets = false;
  } catch (const std::logic_error&) {
    r.meets = false;
  }
  return r;
}

nlohmann::json format_json(const Format& f) {
  nlohmann::json j;
  j["banks"] = f.banks;
  j["bank_max_n"] = f.bank_max_n;
  for (const Field& fd : fields()) j[fd.name] = f.*(fd.member);
  j["coef_frac"] = f.coef_frac;
  j["rom_bits"] = rom_bits(f);
  return j;
}

}  // namespace

int main(int argc, char** argv) {
  std::string budget = "b1", json_out;
  int n_max = 1000;
  CLI::App app{"Find the device's narrowest build configuration for an error budget (docs/metrics.md#budgets)"};
  app.add_option("--budget", budget, "b1, b2 or b3")->check(CLI::IsMember({"b1", "b2", "b3"}))->capture_default_str();
  app.add_option("--n-max", n_max, "largest exponent the configuration must serve (1..1000)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  app.add_option("--json", json_out, "write the result to this file");
  if (auto rc = specular::parse_command_line(app, argc, argv, "device_search")) return *rc;
  const PixelBudget b = PixelBudget::named(budget);
  const specular::BuildConfig& start = specular::build_config("default");
  const specular::CoefSpec spec = specular::parse_coef_spec(start.policy);
  const int coef_int = start.f.coef_bits - start.f.coef_frac;

  nlohmann::json runs = nlohmann::json::array();
  Format best;
  long best_bits = -1;
  for (const std::vector<int>& banks : kBankSets) {
    Format f = start.f;
    f.banks = banks;
    f.bank_max_n = specular::derive_bank_max_n(banks, spec);
    std::string set;
    for (int k : banks) set += (set.empty() ? "" : ",") + std::to_string(k);
    if (!measure(f, spec, n_max, b, true).meets) {
      // Its errors at the default widths, every n: why it is out.
      const Result m = measure(f, spec, n_max, b, false);
      std::printf("banks {%s}: misses at the default widths: rel %.3e abs %.3e raw %.3e (worst at n = %d)\n",
                  set.c_str(), m.rel_lsb, m.abs_lsb, m.abs_raw, m.worst_n);
      runs.push_back({{"banks", banks}, {"meets", false}, {"rel_lsb", m.rel_lsb}, {"abs_lsb", m.abs_lsb},
                      {"abs_raw", m.abs_raw}, {"worst_n", m.worst_n}});
      continue;
    }
    // ROM 9's fraction follows its width; a table keeps the step width it needed.
    specular::narrow_fields(
        f, fields(),
        [&](Format& g) {
          g.coef_frac = g.coef_bits - coef_int;
          return measure(g, spec, n_max, b, true).meets;
        },
        [](const Field&, const Format&) {});
    const Result r = measure(f, spec, n_max, b, false);
    std::printf("banks {%s}: addr %d data %d delta %d frac %d coef %d/%d psi %d: %ld ROM bits; rel %.3e abs %.3e "
                "raw %.3e (worst at n = %d) %s\n",
                set.c_str(), f.cos_addr_bits, f.cos_data_bits, f.cos_delta_bits, f.cos_frac_bits, f.coef_bits,
                f.coef_frac, f.psi_mul_frac, rom_bits(f), r.rel_lsb, r.abs_lsb, r.abs_raw, r.worst_n,
                r.meets ? "meets" : "OVER BUDGET");
    nlohmann::json j = format_json(f);
    j["meets"] = r.meets;
    j["rel_lsb"] = r.rel_lsb;
    j["abs_lsb"] = r.abs_lsb;
    j["abs_raw"] = r.abs_raw;
    j["worst_n"] = r.worst_n;
    runs.push_back(j);
    if (r.meets && (best_bits < 0 || rom_bits(f) < best_bits)) {
      best = f;
      best_bits = rom_bits(f);
    }
  }
  if (best_bits < 0)
    std::cerr << "device_search: no bank set meets budget " << budget << " for n <= " << n_max << "\n";
  else
    std::printf("fewest ROM bits: %ld (banks of %zu)\n", best_bits, best.banks.size());
  if (!json_out.empty()) {
    nlohmann::json j;
    j["budget"] = budget;
    j["n_max"] = n_max;
    j["policy"] = start.policy;
    j["runs"] = runs;
    j["best"] = best_bits < 0 ? nlohmann::json(nullptr) : format_json(best);
    std::ofstream out(json_out);
    out << j.dump(1) << "\n";
    if (!out) {
      std::cerr << "device_search: error: cannot write " << json_out << "\n";
      return 1;
    }
  }
  return best_bits < 0 ? 1 : 0;
}
