// SPDX-License-Identifier: Apache-2.0
// setup_romgen: the ROM images of the hardware setup (rtl/setup/specular_setup.sv,
// docs/setup_hw.md#widths), written from the golden model's tables
// (model/host/setup_fixed.hpp) as $readmemh files: one hex word per line, word 0 first.
//
//   setup_romgen --out DIR     write DIR/{rsqrt_seed,log_recip,log_value,exp2,recip_len}.hex
//   setup_romgen --check DIR   exit 1 unless every file in DIR equals what --out writes
//   setup_romgen --consts      print the constants of rtl/setup/specular_setup_pkg.sv
//   setup_romgen --lean-consts print the lines of rtl/setup/specular_setup_lean_pkg.sv that
//                              carry the lean golden model's widths and constants
//                              (model/host/setup_lean.hpp)
//   setup_romgen --check-lean-pkg FILE  exit 1 unless FILE holds every one of those lines
// The lean setup's seed table (rsqrt_seed_lean.hex) is among the images of --out and --check.
#include "setup_fixed.hpp"
#include "setup_lean.hpp"

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
namespace hl = specular::host::lean;

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
  return {{"rsqrt_seed.hex", hex_lines(hf::rsqrt_seed_table(), hf::kRsqrtSeedFrac + 1)},
          {"log_recip.hex", hex_lines(hf::log_recip_table(), hf::kLogRecipFrac)},
          {"log_value.hex", hex_lines(hf::log_value_table(), hf::kLogFrac + 1)},
          {"exp2.hex", hex_lines(hf::exp2_table(), hf::kLogFrac + 1)},
          {"recip_len.hex", hex_lines(hf::recip_len_table(), hf::kRecipLenFrac + 1)},
          // rtl/setup/specular_setup_lean_norm.sv: 385 words, Q18 in (2^18, 2^19]: 20 bits.
          {"rsqrt_seed_lean.hex", hex_lines(hl::seed_table(), hl::kSeedFrac + 2)}};
}

// The lean package's lines (rtl/setup/specular_setup_lean_pkg.sv), each as the file writes it.
std::vector<std::string> lean_pkg_lines() {
  const hl::Widths w;
  auto lp = [](const char* name, long long v) { return std::string("  localparam int ") + name + " = " + std::to_string(v) + ";"; };
  std::vector<std::string> v = {
      lp("Frac", w.frac),
      lp("SeedAddrBits", hl::kSeedAddrBits),
      lp("SeedInterpBits", hl::kSeedInterpBits),
      lp("SeedFrac", hl::kSeedFrac),
      lp("SeedWords", static_cast<long long>(hl::seed_table().size())),
      lp("FlatLog2", hl::kFlatLog2),
      lp("OppHalfLog2", hl::kOppHalfLog2),
      lp("OppNormLog2", hl::kOppNormLog2),
      lp("RsqrtInBits", w.rsqrt_in_bits()),
      lp("RsqrtFrac", w.rsqrt_frac()),
      lp("BlockBits", w.block_bits()),
      lp("CordicFrac", w.cordic_frac()),
      lp("CordicIters", w.cordic_iters()),
      lp("CordicW", w.cordic_bits()),
      lp("GammaFrac", hf::kGammaFrac),
      lp("RecipLenFrac", hf::kRecipLenFrac),
      lp("LogFrac", hf::kLogFrac),
      lp("LogUnitFrac", hf::kUnitFrac),
      "  localparam logic signed [63:0] Pi = 64'sd" + std::to_string(hl::pi_word(w.cordic_frac())) + ";"};
  for (int i = 0; i < w.cordic_iters(); ++i)
    v.push_back("      " + std::to_string(i) + ": atan_word = 64'sd" + std::to_string(hl::atan_word(i, w.cordic_frac())) + ";");
  return v;
}
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ROM images of the hardware setup (docs/setup_hw.md)"};
  std::string out, check, check_lean;
  bool consts = false, lean_consts = false;
  app.add_option("--out", out, "directory to write the .hex files into");
  app.add_option("--check", check, "directory whose .hex files must equal the generated ones");
  app.add_flag("--consts", consts, "print the constants of rtl/setup/specular_setup_pkg.sv");
  app.add_flag("--lean-consts", lean_consts, "print the constant lines of rtl/setup/specular_setup_lean_pkg.sv");
  app.add_option("--check-lean-pkg", check_lean, "a specular_setup_lean_pkg.sv that must hold every --lean-consts line");
  CLI11_PARSE(app, argc, argv);
  if (out.empty() && check.empty() && !consts && !lean_consts && check_lean.empty()) {
    std::cerr << "setup_romgen: give --out DIR, --check DIR, --consts, --lean-consts or --check-lean-pkg FILE\n";
    return 2;
  }
  if (lean_consts)
    for (const auto& l : lean_pkg_lines()) std::cout << l << '\n';
  if (!check_lean.empty()) {
    std::ifstream f(check_lean);
    const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    if (!f) {
      std::cerr << "setup_romgen: cannot read " << check_lean << '\n';
      return 1;
    }
    int missing = 0;
    for (const auto& l : lean_pkg_lines()) {
      if (text.find(l + "\n") == std::string::npos) {
        std::cerr << "setup_romgen: " << check_lean << " lacks the line \"" << l << "\"\n";
        ++missing;
      }
    }
    if (missing != 0) return 1;
  }
  if (consts) {
    std::cout << "InvGain = 64'sd" << hf::cordic_inv_gain() << "\nPi = 64'sd" << hf::cordic_pi() << '\n';
    const hf::PolyConsts& c = hf::poly_consts();
    std::cout << "L1 " << c.l1 << " L2 " << c.l2 << " L3 " << c.l3 << " E1 " << c.e1 << " E2 " << c.e2 << " E3 " << c.e3 << '\n';
    for (size_t i = 0; i < hf::atan_table().size(); ++i) std::cout << "64'sd" << hf::atan_table()[i] << (i + 1 < hf::atan_table().size() ? ",\n" : "\n");
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
