// SPDX-License-Identifier: Apache-2.0
// ROM images of the device (docs/device.md): ROM 9 (coefficients a(n), addressed by n)
// and ROM 12 (cos^k, one bank per k), built from the golden-model formats in
// device_model.hpp so that the generator, the RTL and the testbench share one definition.
//
// Hex file format (what $readmemh in rtl/ reads): one word per line, lowercase hex,
// zero-padded to ceil(bits/4) digits, no comments, no @addresses, '\n' line ends,
// exactly `depth` lines. Address 0 is the first line.
//   ROM 9  word n (0 <= n < 2^n_bits): round(a(n) * 2/pi * 2^coef_frac), a(n) from the
//          coefficient policy for k = bank k of n; 0 where n = 0 or n > max_n (unused:
//          decoder 10 forces those pixels to 0).
//   ROM 12 word bank * 2^cos_addr_bits + addr, h = pi/2 / 2^cos_addr_bits:
//     interpolated  {v, d}: v = round(cos^k(addr * h) * 2^cos_data_bits) in the top
//                   cos_data_bits + 1 bits, d = v - v(addr + 1) in the low cos_delta_bits
//                   (v(2^cos_addr_bits) = 0); a step that does not fit throws
//     direct        min(round(cos^k(addr * h) * 2^cos_data_bits), 2^cos_data_bits - 1)
#pragma once

#include "coefficients.hpp"
#include "device_model.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace specular {

// File names (relative to the repository root) of the single-bank build "single" (Format{}):
// minimax ROM 9, interpolated ROM 12 of banks {1,2,3,4,6,8,12,16}. The default build's are
// build_config("default").coef_hex() and cos_hex().
inline constexpr const char* kCoefMinimaxHex = "roms/coef_minimax.hex";
inline constexpr const char* kCosHex = "roms/cos_k_1_2_3_4_6_8_12_16_interp256.hex";
// The patent's build (Format::patent()): maclaurin ROM 9, direct ROM 12 of banks {1,2,4,16}.
inline constexpr const char* kPatentCoefHex = "roms/patent/coef_maclaurin.hex";
inline constexpr const char* kPatentCosHex = "roms/patent/cos_k_1_2_4_16.hex";

// The hardware configurations this repository builds, simulates (sim_regression verilates
// each with its parameters) and reports: name, formats, ROM 9 policy, and where romgen
// writes their ROM files (`romgen --all`). The first, "default", is the RTL default (the blend
// that meets B2, docs/display_exact.md), the second the patent's own configuration, the third
// "single" the single-bank build of Format{}.
// The device error a configuration must meet (the regression's check (c), sim/README.md):
// |err| <= rel_epicenter * ref + 1 LSB in the epicenter, |err| <= abs_lobe * C + 1 LSB over
// the lobe; n = 1 is held to the relative budget where ref >= n1_min_ref_lsb output LSBs
// (0: n = 1 is only reported, as for a direct table).
struct ErrorBudget {
  double rel_epicenter = 0.0;
  double abs_lobe = 0.0;
  double n1_min_ref_lsb = 0.0;
};

struct BuildConfig {
  std::string name;
  device::Format f;
  std::string policy;  // ROM 9 coefficient policy (parse_coef_spec), or "blend" (f.blend: the fits)
  std::string dir;     // relative to the repository root
  ErrorBudget budget;
  bool scenes = true;  // the full regression runs the scene stage on it (sim/README.md)
  std::string coef_hex() const;
  std::string cos_hex() const;
};
const std::vector<BuildConfig>& build_configs();
// Throws std::invalid_argument naming the known configurations.
const BuildConfig& build_config(const std::string& name);

// A configuration as the RTL takes it (docs/pipeline.md#build-configurations): the
// parameters of specular_unit / specular_stream in Verilog syntax, as Verilator's -G takes
// them (strings quoted, BankMaxN a sized hex literal).
struct RtlParameter {
  std::string name, value;
  bool operator==(const RtlParameter&) const = default;
};
std::vector<RtlParameter> rtl_parameters(const BuildConfig& bc);
// A C identifier for the configuration's name ("banks4-interp" -> "banks4_interp").
std::string config_id(const std::string& name);
// The CMake fragment roms/build_configs.cmake that `romgen --all` writes beside the ROMs: per
// configuration its name, identifier, -G flags (the parameters that differ from the first
// configuration's, which are the RTL defaults) and the -G flags of sim/specular_pipeline.sv.
std::string build_configs_cmake();

// "cos_k_1_2_4_16.hex" (direct) or "cos_k_1_2_4_16_interp256.hex" for the ROM 12 of `f`.
std::string cos_rom_file_name(const device::Format& f);

// ROM 9 word for coefficient a: round(a * 2/pi * 2^coef_frac). Throws std::invalid_argument
// when a*2/pi is not in [1/8, 2^(coef_bits - coef_frac)): above it the word does not fit;
// below 1/8 no policy gives a sane coefficient (a < pi/16 would spread the lobe far past pi/2).
uint32_t coef_word(double a, const device::Format& f);

// Throws std::invalid_argument (naming n and k) when a policy gives an unusable coefficient.
std::vector<uint32_t> coef_rom_image(const device::Format& f, const CoefSpec& spec);
std::vector<uint32_t> cos_rom_image(const device::Format& f);

// Writes to a temporary file next to `path` and renames it, so a failure never leaves a
// half-written ROM. Throws std::runtime_error on I/O errors or a word wider than `bits`.
void write_hex(const std::string& path, const std::vector<uint32_t>& image, int bits);
// Throws std::runtime_error naming the file and line on bad content (not hex, too many
// digits, word wider than `bits`, empty line, or not exactly `depth` lines), and
// std::invalid_argument when `bits` is not in 1..32 or `depth` is negative.
std::vector<uint32_t> read_hex(const std::string& path, int bits, int depth);
// The same for words of up to 64 bits (ROM 9 of a blend build: {a1, a2, w}, blend_rom.hpp).
void write_hex_wide(const std::string& path, const std::vector<uint64_t>& image, int bits);
std::vector<uint64_t> read_hex_wide(const std::string& path, int bits, int depth);

// Golden model from ROM files (default format paths relative to the working directory); a blend
// format (Format::blend) reads ROM 9 as words {a1, a2, w} (blend_rom.hpp).
device::DeviceModel load_device_model(const device::Format& f, const std::string& coef_hex,
                                      const std::string& cos_hex);

}  // namespace specular
