// SPDX-License-Identifier: Apache-2.0
// setup_romgen: the ROM images of the hardware setup (rtl/setup/specular_setup.sv,
// docs/setup_hw.md#widths), written from the golden model's tables
// (model/host/setup_fixed.hpp) as $readmemh files: one hex word per line, word 0 first.
//
//   setup_romgen --out DIR     write DIR/{rsqrt_seed,log_recip,log_value,exp2,recip_len}.hex
//   setup_romgen --check DIR   exit 1 unless every file in DIR equals what --out writes
//   setup_romgen --consts      print the constants of rtl/setup/specular_setup_pkg.sv
#include "setup_fixed.hpp"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
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
  return {{"rsqrt_seed.hex", hex_lines(hf::rsqrt_seed_table(), hf::kRsqrtSeedFrac + 1)},
          {"log_recip.hex", hex_lines(hf::log_recip_table(), hf::kLogRecipFrac)},
          {"log_value.hex", hex_lines(hf::log_value_table(), hf::kLogFrac + 1)},
          {"exp2.hex", hex_lines(hf::exp2_table(), hf::kLogFrac + 1)},
          {"recip_len.hex", hex_lines(hf::recip_len_table(), hf::kRecipLenFrac + 1)}};
}
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ROM images of the hardware setup (docs/setup_hw.md)"};
  std::string out, check;
  bool consts = false;
  app.add_option("--out", out, "directory to write the .hex files into");
  app.add_option("--check", check, "directory whose .hex files must equal the generated ones");
  app.add_flag("--consts", consts, "print the constants of rtl/setup/specular_setup_pkg.sv");
  CLI11_PARSE(app, argc, argv);
  if (out.empty() && check.empty() && !consts) {
    std::cerr << "setup_romgen: give --out DIR, --check DIR or --consts\n";
    return 2;
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
