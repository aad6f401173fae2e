// SPDX-License-Identifier: Apache-2.0
// ROM images and hex files; the format is documented in rom_image.hpp and roms/README.md.
#include "rom_image.hpp"

#include "decoder_table.hpp"

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
    v.push_back({"default", device::Format{}, "minimax", "roms", {0.0010, 0.01, 4.0}});
    v.push_back({"patent", device::Format::patent(), "maclaurin", "roms/patent", {0.012, 0.025, 0.0}});
    // The default datapath with the patent's bank set: what the bank set buys.
    device::Format b4;
    b4.banks = {1, 2, 4, 16};
    b4.bank_max_n = derive_bank_max_n(b4.banks, parse_coef_spec("minimax"));
    v.push_back({"banks4-interp", b4, "minimax", "roms/variants/banks4-interp", {0.0020, 0.02, 4.0}});
    // Half the ROM 12 entries: what the table size buys.
    device::Format i128;
    i128.cos_addr_bits = 7;
    i128.cos_delta_bits = 13;
    v.push_back({"interp128", i128, "minimax", "roms/variants/interp128", {0.0010, 0.01, 4.0}});
    return v;
  }();
  return configs;
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
    const int k = f.banks[probe.bank_of(static_cast<uint32_t>(n))];
    try {
      img[n] = coef_word(coefficient(n, k, spec), f);
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
  for (int k : f.banks) {
    // long double so that the rounding of the committed words does not hinge on the last
    // bit of a double cos(); entry per_bank (x = pi/2) is 0 exactly.
    auto entry = [&](int addr) -> long double {
      if (addr >= per_bank) return 0.0L;
      const long double x = std::numbers::pi_v<long double> / 2.0L * addr / per_bank;
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

void write_hex(const std::string& path, const std::vector<uint32_t>& image, int bits) {
  const int digits = (bits + 3) / 4;
  std::string text;
  text.reserve(image.size() * (digits + 1));
  char buf[16];
  for (size_t a = 0; a < image.size(); ++a) {
    if (bits < 32 && (image[a] >> bits) != 0)
      throw std::runtime_error(path + ": word " + std::to_string(a) + " does not fit " + std::to_string(bits) +
                               " bits");
    std::snprintf(buf, sizeof buf, "%0*x\n", digits, image[a]);
    text += buf;
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

std::vector<uint32_t> read_hex(const std::string& path, int bits, int depth) {
  // Found by fuzzing (tests/fuzz/corpus/rom_hex/crash_bits35): a width above 32 let a
  // 9-digit word pass the width test and be truncated into the uint32_t image.
  if (bits < 1 || bits > 32 || depth < 0)
    throw std::invalid_argument(path + ": word width " + std::to_string(bits) + " or depth " + std::to_string(depth) +
                                " not supported (width 1..32 bits, depth >= 0)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  const int digits = (bits + 3) / 4;
  std::vector<uint32_t> img;
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
    if ((v >> bits) != 0) fail("word " + line + " is wider than " + std::to_string(bits) + " bits");
    if (lineno > depth) fail("more than " + std::to_string(depth) + " words");
    img.push_back(static_cast<uint32_t>(v));
  }
  if (static_cast<int>(img.size()) != depth)
    throw std::runtime_error(path + ": " + std::to_string(img.size()) + " words, expected " + std::to_string(depth));
  return img;
}

device::DeviceModel load_device_model(const device::Format& f, const std::string& coef_hex,
                                      const std::string& cos_hex) {
  return device::DeviceModel(f, read_hex(coef_hex, f.coef_bits, f.coef_rom_depth()),
                             read_hex(cos_hex, f.cos_word_bits(), f.cos_rom_depth()));
}

}  // namespace specular
