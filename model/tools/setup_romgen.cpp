// SPDX-License-Identifier: Apache-2.0
// setup_romgen: the ROM images and package constants of the hardware setup
// (rtl/setup/specular_setup.sv, docs/setup_hw.md#widths), written from the golden model's tables
// (model/host/setup_fixed.hpp, setup_tables.hpp); the ROMs as $readmemh files, one hex word per
// line, word 0 first.
//
//   setup_romgen --out DIR     write DIR/{rsqrt_seed,log_recip,log_value,exp2,recip_len}.hex
//   setup_romgen --check DIR   exit 1 unless every file in DIR equals what --out writes
//   setup_romgen --consts      print the lines of rtl/setup/specular_setup_pkg.sv that carry the
//                              golden model's widths and constants
//   setup_romgen --check-pkg FILE  exit 1 unless FILE holds every one of those lines
#include "setup_fixed.hpp"
#include "setup_tables.hpp"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {
namespace hf = specular::host::fixed;

// Lowercase hex, zero-padded to ceil(bits / 4) digits (roms/README.md#file-format-what-readmemh-reads).
template <class T>
std::string hex_lines(const std::vector<T>& words, int bits) {
  std::ostringstream s;
  for (T w : words) {
    if (bits < 64 && static_cast<uint64_t>(w) >> bits) throw std::logic_error("setup_romgen: a word wider than its ROM");
    s << std::hex << std::setw((bits + 3) / 4) << std::setfill('0') << static_cast<uint64_t>(w) << '\n';
  }
  return s.str();
}

std::vector<std::pair<std::string, std::string>> images() {
  // The ROM widths of the RTL (rtl/setup/specular_setup_norm.sv, _log2.sv, _exp2.sv, specular_setup.sv).
  return {{"rsqrt_seed.hex", hex_lines(hf::seed_table(), hf::kSeedFrac + 2)},  // 385 words in (2^18, 2^19]
          {"log_recip.hex", hex_lines(hf::log_recip_table(), hf::kLogRecipFrac)},
          {"log_value.hex", hex_lines(hf::log_value_table(), hf::kLogFrac + 1)},
          {"exp2.hex", hex_lines(hf::exp2_table(), hf::kLogFrac + 1)},
          {"recip_len.hex", hex_lines(hf::recip_len_table(), hf::kRecipLenFrac + 1)}};
}

// The package's lines (rtl/setup/specular_setup_pkg.sv), each as the file writes it.
std::vector<std::string> pkg_lines() {
  const hf::Widths w;
  auto lp = [](const char* name, long long v) { return std::string("  localparam int ") + name + " = " + std::to_string(v) + ";"; };
  auto lq = [](const char* name, long long v) {
    return std::string("  localparam logic signed [63:0] ") + name + " = " + (v < 0 ? "-" : "") + "64'sd" +
           std::to_string(v < 0 ? -v : v) + ";";
  };
  std::vector<std::string> v = {
      lp("Frac", w.frac),
      lp("SeedAddrBits", hf::kSeedAddrBits),
      lp("SeedInterpBits", hf::kSeedInterpBits),
      lp("SeedFrac", hf::kSeedFrac),
      lp("SeedWords", static_cast<long long>(hf::seed_table().size())),
      lp("FlatLog2", hf::kFlatLog2),
      lp("OppHalfLog2", hf::kOppHalfLog2),
      lp("OppNormLog2", hf::kOppNormLog2),
      lp("RsqrtInBits", w.rsqrt_in_bits()),
      lp("RsqrtFrac", w.rsqrt_frac()),
      lp("BlockBits", w.block_bits()),
      lp("CordicFrac", w.cordic_frac()),
      lp("CordicIters", w.cordic_iters()),
      lp("CordicW", w.cordic_bits()),
      lp("GammaFrac", hf::kGammaFrac),
      lp("RecipLenFrac", hf::kRecipLenFrac),
      lp("LogFrac", hf::kLogFrac),
      lp("LogUnitFrac", hf::kLogUnitFrac),
      "  localparam logic signed [63:0] Pi = 64'sd" + std::to_string(hf::pi_word(w.cordic_frac())) + ";",
      lp("AtanFrac", hf::kAtanFrac),
      lp("AtanIters", hf::kAtanIters),
      lq("PiQ50", hf::atan_pi())};
  const hf::PolyConsts& c = hf::poly_consts();
  for (const auto& [name, k] : {std::pair{"L1", c.l1}, {"L2", c.l2}, {"L3", c.l3}, {"E1", c.e1}, {"E2", c.e2}, {"E3", c.e3}})
    v.push_back(lq(name, k));
  for (int i = 0; i < w.cordic_iters(); ++i)
    v.push_back("      " + std::to_string(i) + ": atan_word = 64'sd" + std::to_string(hf::atan_word(i, w.cordic_frac())) + ";");
  // atan_q50 lists its words up to i = 16; from 17 on it is 2^(50 - i), which the table must be.
  const auto& at = hf::atan_table();
  for (int i = 0; i <= 16; ++i)
    v.push_back("      " + std::to_string(i) + (i < 10 ? ":  " : ": ") + "atan_q50 = 64'sd" + std::to_string(at[static_cast<size_t>(i)]) + ";");
  v.push_back("      default: atan_q50 = 64'sd1 <<< (AtanFrac - i);");
  for (int i = 17; i < hf::kAtanIters; ++i)
    if (at[static_cast<size_t>(i)] != int64_t{1} << (hf::kAtanFrac - i))
      throw std::logic_error("setup_romgen: atan(2^-" + std::to_string(i) + ") is not 2^-" + std::to_string(i) + " in Q50");
  return v;
}
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ROM images and package constants of the hardware setup (docs/setup_hw.md)"};
  std::string out, check, check_pkg;
  bool consts = false;
  app.add_option("--out", out, "directory to write the .hex files into");
  app.add_option("--check", check, "directory whose .hex files must equal the generated ones");
  app.add_flag("--consts", consts, "print the constant lines of rtl/setup/specular_setup_pkg.sv");
  app.add_option("--check-pkg", check_pkg, "a specular_setup_pkg.sv that must hold every --consts line");
  CLI11_PARSE(app, argc, argv);
  if (out.empty() && check.empty() && !consts && check_pkg.empty()) {
    std::cerr << "setup_romgen: give --out DIR, --check DIR, --consts or --check-pkg FILE\n";
    return 2;
  }
  if (consts)
    for (const auto& l : pkg_lines()) std::cout << l << '\n';
  if (!check_pkg.empty()) {
    std::ifstream f(check_pkg);
    const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    if (!f) {
      std::cerr << "setup_romgen: cannot read " << check_pkg << '\n';
      return 1;
    }
    int missing = 0;
    for (const auto& l : pkg_lines()) {
      if (text.find(l + "\n") == std::string::npos) {
        std::cerr << "setup_romgen: " << check_pkg << " lacks the line \"" << l << "\"\n";
        ++missing;
      }
    }
    if (missing != 0) return 1;
  }
  int bad = 0;
  for (const auto& [name, text] : images()) {
    if (!out.empty()) {
      std::ofstream f(out + "/" + name);
      if (!(f << text)) {
        std::cerr << "setup_romgen: cannot write " << out << "/" << name << '\n';
        return 1;
      }
    }
    if (!check.empty()) {
      std::ifstream f(check + "/" + name);
      std::stringstream s;
      s << f.rdbuf();
      if (!f || s.str() != text) {
        std::cerr << "setup_romgen: " << check << "/" << name << " differs from the golden model's table (regenerate with --out)\n";
        ++bad;
      }
    }
  }
  return bad == 0 ? 0 : 1;
}
