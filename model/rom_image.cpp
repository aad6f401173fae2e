// ROM images and hex files; the format is documented in rom_image.hpp and roms/README.md.
#include "rom_image.hpp"

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
  return name + ".hex";
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
  const long double top = std::ldexp(1.0L, f.cos_data_bits) - 1.0L;
  std::vector<uint32_t> img;
  img.reserve(f.cos_rom_depth());
  for (int k : f.banks) {
    for (int addr = 0; addr < per_bank; ++addr) {
      // long double so that the rounding of the committed words does not hinge on the last
      // bit of a double cos().
      const long double x = std::numbers::pi_v<long double> / 2.0L * addr / per_bank;
      long double v = std::round(std::pow(std::cos(x), static_cast<long double>(k)) *
                                 std::ldexp(1.0L, f.cos_data_bits));
      if (v > top) v = top;  // cos^k(0) = 1 saturates deliberately
      img.push_back(static_cast<uint32_t>(v));
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
    if (static_cast<int>(line.size()) > digits)
      fail("'" + line + "' has more than " + std::to_string(digits) + " hex digits");
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
                             read_hex(cos_hex, f.cos_data_bits, f.cos_rom_depth()));
}

}  // namespace specular
