// SPDX-License-Identifier: Apache-2.0
// ROM images and hex files; the format is documented in rom_image.hpp and roms/README.md.
#include "rom_image.hpp"

#include "blend_rom.hpp"
#include "decoder_table.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace specular {

std::string cos_rom_file_name(const device::Format& f) {
  std::string name = "cos_k";
  for (int k : f.banks) {
    name += '_';
    name += std::to_string(k);
  }
  // The interpolated table is a different format from the patent's direct one.
  if (f.cos_interp) name += "_interp" + std::to_string(1 << f.cos_addr_bits);
  return name + ".hex";
}

std::string BuildConfig::coef_hex() const {
  std::string p = policy;
  for (char& ch : p)
    if (ch == ':') ch = '_';
  return dir + "/coef_" + p + ".hex";
}
std::string BuildConfig::cos_hex() const { return dir + "/" + cos_rom_file_name(f); }

const std::vector<BuildConfig>& build_configs() {
  static const std::vector<BuildConfig> configs = [] {
    std::vector<BuildConfig> v;
    // The default build (docs/display_exact.md): the blend of banks {1, 2, 4, 8} that meets B2
    // (|err| <= 2^-9 C, an 8-bit display) for every n <= 1000, the cheapest blend device_search
    // found ("best_blend" of docs/measured/device_search.json, which scripts/budget_roms.py checks
    // these fields against) with one more ROM 12 data bit (and the step field it needs): the dense
    // sweep (device_search --sweep) puts the search's widths at 1.057 of B2, one bit more at 0.96.
    // Absolute budget only: the relative one of the epicenter is the single-bank builds'
    // (sim/README.md).
    device::Format b2 = blend_format(device::Format{}, {1, 2, 4, 8});
    b2.coef_bits = 13, b2.coef_frac = 9, b2.psi_mul_frac = 15, b2.weight_bits = 10;
    b2.cos_addr_bits = 7, b2.cos_data_bits = 12, b2.cos_delta_bits = 7, b2.cos_frac_bits = 7;
    v.push_back({"default", b2, "blend", "roms/blend/b2", {1.0, std::ldexp(1.0, -9), 0.0}});
    v.push_back({"patent", device::Format::patent(), "maclaurin", "roms/patent", {0.012, 0.025, 0.0}});
    // The single-bank build (Format{}, the default until the blend met B2): B1 for every n.
    v.push_back({"single", device::Format{}, "minimax", "roms", {0.0010, 0.01, 4.0}});
    // The single-bank datapath with the patent's bank set: what the bank set buys.
    device::Format p4;
    p4.banks = {1, 2, 4, 16};
    p4.bank_max_n = derive_bank_max_n(p4.banks, parse_coef_spec("minimax"));
    v.push_back({"banks4-interp", p4, "minimax", "roms/variants/banks4-interp", {0.0020, 0.02, 4.0}, false});
    // Half the ROM 12 entries: what the table size buys.
    device::Format i128;
    i128.cos_addr_bits = 7;
    i128.cos_delta_bits = 13;
    v.push_back({"interp128", i128, "minimax", "roms/variants/interp128", {0.0010, 0.01, 4.0}, false});
    // The blend that meets B4 (|err| <= 2^-11 C, a 10-bit display), chosen as the default's: the
    // search's widths at 1.038 of B4, one ROM 12 data bit more at 0.90.
    device::Format b4 = blend_format(device::Format{}, {1, 2, 3, 4, 8, 16});
    b4.coef_bits = 15, b4.coef_frac = 12, b4.psi_mul_frac = 19, b4.weight_bits = 9;
    b4.cos_addr_bits = 7, b4.cos_data_bits = 14, b4.cos_delta_bits = 9, b4.cos_frac_bits = 10;
    v.push_back({"blend-b4", b4, "blend", "roms/blend/b4", {1.0, std::ldexp(1.0, -11), 0.0}});
    return v;
  }();
  return configs;
}

namespace {
// A Verilog string literal (the ROM paths have no quote or backslash).
std::string quoted(const std::string& s) {
  std::string q(1, '"');
  q += s;
  q += '"';
  return q;
}
}  // namespace

std::vector<RtlParameter> rtl_parameters(const BuildConfig& bc) {
  const device::Format& f = bc.f;
  // Decoder 10 in RTL has one entry per bank (a blend set whose last bank is past 1000 would
  // have one fewer, docs/display_exact.md#datapath): such a set has no RTL build.
  if (f.bank_max_n.size() != f.banks.size())
    throw std::invalid_argument(bc.name + ": the RTL's decoder 10 needs one bank_max_n entry per bank (" +
                                std::to_string(f.banks.size()) + " banks, " + std::to_string(f.bank_max_n.size()) +
                                " entries)");
  auto i = [](int v) { return std::to_string(v); };
  // BankMaxN: NumBanks fields of NBits, bank 0 in the least significant bits.
  const int width = static_cast<int>(f.bank_max_n.size()) * f.n_bits;
  std::string hex((width + 3) / 4, '0');
  for (size_t j = 0; j < f.bank_max_n.size(); ++j)
    for (int b = 0; b < f.n_bits; ++b)
      if ((f.bank_max_n[j] >> b) & 1) {
        const int bit = static_cast<int>(j) * f.n_bits + b;
        const size_t digit = hex.size() - 1 - static_cast<size_t>(bit / 4);
        const int v = (hex[digit] <= '9' ? hex[digit] - '0' : hex[digit] - 'a' + 10) | (1 << (bit % 4));
        hex[digit] = "0123456789abcdef"[v];
      }
  return {{"CBits", i(f.c_bits)},
          {"CFrac", i(f.c_frac)},
          {"AngleBits", i(f.angle_bits)},
          {"AngleFrac", i(f.angle_frac)},
          {"AccBits", i(f.acc_bits)},
          {"NBits", i(f.n_bits)},
          {"LenBits", i(f.len_bits)},
          {"CoefBits", i(f.coef_bits)},
          {"CoefFrac", i(f.coef_frac)},
          {"PsiMulFrac", i(f.psi_mul_frac)},
          {"CosInterp", f.cos_interp ? "1'b1" : "1'b0"},
          {"CosAddrBits", i(f.cos_addr_bits)},
          {"CosDataBits", i(f.cos_data_bits)},
          {"CosDeltaBits", i(f.cos_delta_bits)},
          {"CosFracBits", i(f.cos_frac_bits)},
          {"NumBanks", i(static_cast<int>(f.banks.size()))},
          {"BankMaxN", std::to_string(width) + "'h" + hex},
          {"Blend", f.blend ? "1'b1" : "1'b0"},
          {"WeightBits", i(f.weight_bits)},
          {"CoefRomFile", quoted(bc.coef_hex())},
          {"CosRomFile", quoted(bc.cos_hex())}};
}

std::string config_id(const std::string& name) {
  std::string id = name;
  for (char& ch : id)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return id;
}

std::string build_configs_cmake() {
  // A -G flag as one CMake list element: quoted, with the quotes of a string value escaped.
  auto flag = [](const RtlParameter& p) {
    std::string v;
    for (char ch : p.value) v += ch == '"' ? std::string("\\\"") : std::string(1, ch);
    return "\"-G" + p.name + "=" + v + "\"";
  };
  std::ostringstream o;
  o << "# SPDX-License-Identifier: Apache-2.0\n"
       "# Generated by `make roms` (romgen --all) from build_configs() in model/device/rom_image.cpp;\n"
       "# do not edit (docs/pipeline.md#build-configurations). The ctest roms_up_to_date checks it.\n"
       "# SPECULAR_BUILD_CONFIGS: the identifiers (the name with - as _); <ID>_NAME: the name;\n"
       "# <ID>_RTL_ARGS: the -G flags of specular_unit / specular_stream (parameters that differ\n"
       "# from the first configuration's, which are the RTL defaults); <ID>_ALL_ARGS: every parameter's\n"
       "# flag; <ID>_ROM_BITS: ROM 9 and ROM 12\n"
       "# together (Format::coef_word_bits, cos_word_bits); <ID>_PIPELINE_ARGS: those\n"
       "# of sim/specular_pipeline.sv (the widths the stage counts depend on).\n";
  const auto& configs = build_configs();
  o << "set(SPECULAR_BUILD_CONFIGS";
  for (const auto& bc : configs) o << " " << config_id(bc.name);
  o << ")\n";
  const std::vector<RtlParameter> base = rtl_parameters(configs.front());
  for (const auto& bc : configs) {
    const std::string key = "SPECULAR_BUILD_CONFIG_" + config_id(bc.name);
    o << "set(" << key << "_NAME " << bc.name << ")\n";
    o << "set(" << key << "_RTL_ARGS";
    const std::vector<RtlParameter> ps = rtl_parameters(bc);
    for (size_t j = 0; j < ps.size(); ++j)
      if (!(ps[j] == base[j])) o << " " << flag(ps[j]);
    o << ")\n";
    o << "set(" << key << "_ALL_ARGS";
    for (const auto& p : ps) o << " " << flag(p);
    o << ")\n";
    const auto& f = bc.f;
    o << "set(" << key << "_ROM_BITS "
      << int64_t{f.coef_rom_depth()} * f.coef_word_bits() + int64_t{f.cos_rom_depth()} * f.cos_word_bits() << ")\n";
    o << "set(" << key << "_PIPELINE_ARGS";
    for (const auto& p : ps)
      if (p.name == "PsiMulFrac" || p.name == "CosDeltaBits" || p.name == "CosDataBits" || p.name == "Blend")
        o << " " << flag(p);
    o << ")\n";
  }
  return o.str();
}

const BuildConfig& build_config(const std::string& name) {
  std::string known;
  for (const auto& c : build_configs()) {
    if (c.name == name) return c;
    known += (known.empty() ? "" : ", ") + c.name;
  }
  throw std::invalid_argument("unknown hardware configuration '" + name + "' (known: " + known + ")");
}

uint32_t coef_word(double a, const device::Format& f) {
  const double q = a * 2.0 / std::numbers::pi;  // quarter turns per radian
  const double top = std::ldexp(1.0, f.coef_bits - f.coef_frac);
  if (!(q >= 0.125 && q < top)) {
    std::ostringstream m;
    m << "coefficient a = " << a << " gives a*2/pi = " << q << ", outside [1/8, " << top << ")";
    throw std::invalid_argument(m.str());
  }
  const double w = std::round(std::ldexp(q, f.coef_frac));
  if (w >= std::ldexp(1.0, f.coef_bits)) {
    std::ostringstream m;
    m << "coefficient a = " << a << " rounds to " << w << ", wider than " << f.coef_bits << " bits";
    throw std::invalid_argument(m.str());
  }
  return static_cast<uint32_t>(w);
}

std::vector<uint32_t> coef_rom_image(const device::Format& f, const CoefSpec& spec) {
  // Decoder 10 of the golden model decides k, so a non-default bank set is honoured.
  const device::DeviceModel probe(f, std::vector<uint32_t>(f.coef_rom_depth(), 0),
                                  std::vector<uint32_t>(f.cos_rom_depth(), 0));
  std::vector<uint32_t> img(f.coef_rom_depth(), 0);
  for (int n = 1; n <= f.max_n(); ++n) {
    const int j = probe.bank_of(static_cast<uint32_t>(n));
    const int k = f.banks[j];
    try {
      // A bank with its own domain (Format::bank_shift) scales a by 2^shift (exact; 0 by default).
      img[n] = coef_word(std::ldexp(coefficient(n, k, spec), f.shift_of(j)), f);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("ROM 9 entry n = " + std::to_string(n) + ", k = " + std::to_string(k) + ": " +
                                  e.what());
    }
  }
  return img;
}

std::vector<uint32_t> cos_rom_image(const device::Format& f) {
  const int per_bank = 1 << f.cos_addr_bits;
  const long double one = std::ldexp(1.0L, f.cos_data_bits);
  std::vector<uint32_t> img;
  img.reserve(f.cos_rom_depth());
  for (size_t j = 0; j < f.banks.size(); ++j) {
    const int k = f.banks[j];
    // The bank's domain: [0, pi/2 * 2^-shift) (Format::bank_shift; the ldexp is exact).
    const long double span = std::ldexp(std::numbers::pi_v<long double> / 2.0L, -f.shift_of(static_cast<int>(j)));
    // long double so that the rounding of the committed words does not hinge on the last
    // bit of a double cos(); entry per_bank (the domain's end) is 0 exactly.
    auto entry = [&](int addr) -> long double {
      if (addr >= per_bank) return 0.0L;
      const long double x = span * addr / per_bank;
      return std::round(std::pow(std::cos(x), static_cast<long double>(k)) * one);
    };
    for (int addr = 0; addr < per_bank; ++addr) {
      const long double v = entry(addr);
      if (!f.cos_interp) {
        img.push_back(static_cast<uint32_t>(std::min(v, one - 1.0L)));  // cos^k(0) = 1 saturates (patent table)
        continue;
      }
      const long double d = v - entry(addr + 1);
      if (d < 0 || d >= std::ldexp(1.0L, f.cos_delta_bits))
        throw std::invalid_argument("ROM 12 bank k = " + std::to_string(k) + ", entry " + std::to_string(addr) +
                                    ": step " + std::to_string(static_cast<double>(d)) + " does not fit " +
                                    std::to_string(f.cos_delta_bits) + " bits (--cos-delta-bits)");
      img.push_back((static_cast<uint32_t>(v) << f.cos_delta_bits) | static_cast<uint32_t>(d));
    }
  }
  return img;
}

namespace {
template <class Word>
void write_hex_words(const std::string& path, const std::vector<Word>& image, int bits) {
  if (bits < 1 || bits > 64) throw std::invalid_argument(path + ": word width " + std::to_string(bits) + " (1..64)");
  const int digits = (bits + 3) / 4;
  std::string text;
  text.reserve(image.size() * (digits + 1));
  for (size_t a = 0; a < image.size(); ++a) {
    const uint64_t w = image[a];
    if (bits < 64 && (w >> bits) != 0)
      throw std::runtime_error(path + ": word " + std::to_string(a) + " does not fit " + std::to_string(bits) +
                               " bits");
    for (int d = digits - 1; d >= 0; --d) text += "0123456789abcdef"[(w >> (4 * d)) & 0xF];
    text += '\n';
  }
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot open " + tmp + " for writing");
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) {
      std::remove(tmp.c_str());
      throw std::runtime_error("cannot write " + tmp);
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot rename " + tmp + " to " + path + ": " + ec.message());
  }
}

std::vector<uint64_t> read_hex_words(const std::string& path, int bits, int depth, int max_bits) {
  // Found by fuzzing (tests/fuzz/corpus/rom_hex/crash_bits35): a width above 32 let a
  // 9-digit word pass the width test and be truncated into the uint32_t image.
  if (bits < 1 || bits > max_bits || depth < 0)
    throw std::invalid_argument(path + ": word width " + std::to_string(bits) + " or depth " + std::to_string(depth) +
                                " not supported (width 1.." + std::to_string(max_bits) + " bits, depth >= 0)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  const int digits = (bits + 3) / 4;
  std::vector<uint64_t> img;
  img.reserve(depth);
  std::string line;
  int lineno = 0;
  auto fail = [&](const std::string& why) {
    throw std::runtime_error(path + ":" + std::to_string(lineno) + ": " + why);
  };
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty()) fail("empty line");
    // Exactly ceil(bits/4) digits (the documented zero padding): a file written for another
    // word width is refused even when its words would fit.
    if (static_cast<int>(line.size()) != digits)
      fail("'" + line + "' has " + std::to_string(line.size()) + " hex digits, expected " + std::to_string(digits) +
           " (words of " + std::to_string(bits) + " bits)");
    uint64_t v = 0;
    for (char ch : line) {
      int d;
      if (ch >= '0' && ch <= '9') d = ch - '0';
      else if (ch >= 'a' && ch <= 'f') d = ch - 'a' + 10;
      else if (ch >= 'A' && ch <= 'F') d = ch - 'A' + 10;
      else fail("'" + line + "' is not a hex word");
      v = v * 16 + static_cast<uint64_t>(d);
    }
    if (bits < 64 && (v >> bits) != 0) fail("word " + line + " is wider than " + std::to_string(bits) + " bits");
    if (lineno > depth) fail("more than " + std::to_string(depth) + " words");
    img.push_back(v);
  }
  if (static_cast<int>(img.size()) != depth)
    throw std::runtime_error(path + ": " + std::to_string(img.size()) + " words, expected " + std::to_string(depth));
  return img;
}

}  // namespace

void write_hex(const std::string& path, const std::vector<uint32_t>& image, int bits) {
  write_hex_words(path, image, bits);
}

void write_hex_wide(const std::string& path, const std::vector<uint64_t>& image, int bits) {
  write_hex_words(path, image, bits);
}

std::vector<uint32_t> read_hex(const std::string& path, int bits, int depth) {
  const std::vector<uint64_t> w = read_hex_words(path, bits, depth, 32);
  return std::vector<uint32_t>(w.begin(), w.end());
}

std::vector<uint64_t> read_hex_wide(const std::string& path, int bits, int depth) {
  return read_hex_words(path, bits, depth, 64);
}

device::DeviceModel load_device_model(const device::Format& f, const std::string& coef_hex,
                                      const std::string& cos_hex) {
  std::vector<uint32_t> cos = read_hex(cos_hex, f.cos_word_bits(), f.cos_rom_depth());
  if (f.blend) {
    std::vector<uint32_t> coef;
    device::BlendRoms b = unpack_blend_coef(f, read_hex_wide(coef_hex, f.coef_word_bits(), f.coef_rom_depth()), coef);
    return device::DeviceModel(f, std::move(coef), std::move(cos), std::move(b));
  }
  return device::DeviceModel(f, read_hex(coef_hex, f.coef_bits, f.coef_rom_depth()), std::move(cos));
}

}  // namespace specular
