// Unit tests of the golden model (model/device_model) and the ROM images (model/rom_image)
// against hand-computed values of the header contract, with synthetic ROMs whose contents
// make every stage visible (identity cos ROM, power-of-two coefficients).
#define CATCH_CONFIG_MAIN  // single-file test executable
#include "device_model.hpp"
#include "rom_image.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>

using namespace specular;
using device::DeviceModel;
using device::Format;
using device::Registers;

namespace {

// Every coefficient word = `coef`; ROM 12 word = its own address within the bank plus
// bank * 10000 (so the bank is visible in the output too: values stay below 2^16).
DeviceModel synthetic(uint32_t coef, const Format& f = Format{}) {
  std::vector<uint32_t> c(f.coef_rom_depth(), coef);
  std::vector<uint32_t> k(f.cos_rom_depth());
  for (size_t i = 0; i < k.size(); ++i) k[i] = static_cast<uint32_t>((i & 4095) + (i >> 12) * 10000);
  return DeviceModel(f, c, k);
}

std::string temp_path(const char* name) {
  return (std::filesystem::temp_directory_path() / (std::string("specular_golden_") + name)).string();
}

}  // namespace

TEST_CASE("quantize_c rounds to nearest and saturates", "[golden]") {
  const Format f;
  bool sat = true;
  CHECK(device::quantize_c(0.5, f, &sat) == 16384u);
  CHECK_FALSE(sat);
  CHECK(device::quantize_c(1.5 / 32768, f) == 2u);   // 1.5 LSB -> 2 (ties away from zero)
  CHECK(device::quantize_c(1.49 / 32768, f) == 1u);
  CHECK(device::quantize_c(2.0, f, &sat) == 65535u);
  CHECK(sat);
  CHECK(device::quantize_c(-0.1, f, &sat) == 0u);
  CHECK(sat);
  CHECK(device::quantize_c(std::nan(""), f, &sat) == 0u);
  CHECK(sat);
}

TEST_CASE("quantize_angle rounds to nearest and saturates", "[golden]") {
  const Format f;
  bool sat = true;
  CHECK(device::quantize_angle(std::numbers::pi, f, &sat) == 843314857);  // pi * 2^28 = 843314856.53
  CHECK_FALSE(sat);
  CHECK(device::quantize_angle(-std::numbers::pi, f) == -843314857);
  CHECK(device::quantize_angle(8.0, f, &sat) == 2147483647);
  CHECK(sat);
  CHECK(device::quantize_angle(-8.0, f, &sat) == -2147483648LL);
  CHECK_FALSE(sat);  // -8 is exactly the most negative code
  CHECK(device::angle_value(-843314857, f) == Approx(-std::numbers::pi).epsilon(1e-9));
}

TEST_CASE("decoder 10 follows the patent table", "[golden]") {
  const auto m = synthetic(1u << 15);
  CHECK(m.bank_of(0) == -1);
  CHECK(m.bank_of(1) == 0);
  CHECK(m.bank_of(2) == 1);
  CHECK(m.bank_of(3) == 2);
  CHECK(m.bank_of(6) == 2);
  CHECK(m.bank_of(7) == 3);
  CHECK(m.bank_of(1000) == 3);
  CHECK(m.bank_of(1001) == -1);
  CHECK(m.bank_of(1023) == -1);
}

TEST_CASE("datapath stages by hand", "[golden]") {
  const Format f;
  // coef word 2^15 means a * 2/pi = 1: zeta = |psi| in quarter turns per radian.
  const auto m = synthetic(1u << 15);
  Registers r;
  r.c = 32768;  // C = 1
  r.n = 1;      // bank 0
  r.psi0 = int64_t{1} << 26;  // 0.25 rad
  const auto t = m.trace(r, 0);
  CHECK(t.abs_psi_t == (uint64_t{1} << 18));         // 0.25 with 20 fraction bits
  CHECK(t.zeta == (uint64_t{1} << 33));              // 0.25 with 35 fraction bits
  CHECK(t.addr == 1024u);                            // 0.25 * 4096
  CHECK(t.cosk == 1024u);                            // identity ROM, bank 0
  CHECK(t.intensity == 512u);                        // 32768 * 1024 / 65536
  // Bank 3 (n = 7..1000) adds 30000 in the synthetic ROM: (32768 * 31024 + 2^15) >> 16.
  r.n = 500;
  CHECK(m.pixel(r, 0) == 15512u);
  // cos is even: -psi gives the same pixel.
  Registers neg = r;
  neg.psi0 = -r.psi0;
  CHECK(m.pixel(neg, 0) == m.pixel(r, 0));
}

TEST_CASE("ROM 12 address rounds half up and overflows at a*psi = pi/2", "[golden]") {
  const auto m = synthetic(1u << 15);
  Registers r;
  r.c = 65535;
  r.n = 1;
  // |psi|_t LSB is 2^-20 rad, the address LSB 2^-12 quarter turn: with coef = 1 one address
  // step is 2^8 psi_t LSBs = 2^16 angle LSBs. Half a step (2^15 angle codes) rounds up.
  r.psi0 = (int64_t{5} << 16) + (int64_t{1} << 15);
  CHECK(m.trace(r, 0).addr == 6u);
  r.psi0 -= int64_t{1} << 8;  // one psi_t LSB below the tie
  CHECK(m.trace(r, 0).addr == 5u);
  // Just below 1 quarter turn: address 4095 is the last entry; the tie above it overflows.
  r.psi0 = (int64_t{4095} << 16) + (int64_t{1} << 15) - (int64_t{1} << 8);
  auto t = m.trace(r, 0);
  CHECK(t.addr == 4095u);
  CHECK_FALSE(t.overflow);
  r.psi0 += int64_t{1} << 8;
  t = m.trace(r, 0);
  CHECK(t.overflow);
  CHECK(t.intensity == 0u);
}

TEST_CASE("|psi| >= 8 rad is zero without the multiplier; below it the product decides", "[golden]") {
  const auto m = synthetic(1u << 12);  // a * 2/pi = 1/8, the smallest coefficient allowed
  Registers r;
  r.c = 65535;
  r.n = 1000;
  r.psi0 = (int64_t{8} << 28) - (int64_t{1} << 10);  // 8 rad - 2^-18
  auto t = m.trace(r, 0);
  CHECK_FALSE(t.far);
  CHECK(t.addr == 4096u);  // zeta = 1 - 2^-21 rounds to the overflow address
  CHECK(t.intensity == 0u);
  r.psi0 = int64_t{8} << 28;
  t = m.trace(r, 0);
  CHECK(t.far);
  CHECK(t.intensity == 0u);
  // 7 rad / 8 = 0.875 quarter turn -> address 3584, bank 3 word 3584 + 30000.
  r.psi0 = int64_t{7} << 28;
  CHECK(m.trace(r, 0).addr == 3584u);
}

TEST_CASE("accumulator adds dpsi exactly, line has len + 1 pixels, invalid n gives zeros", "[golden]") {
  const auto m = synthetic(1u << 15);
  Registers r;
  r.c = 40000;
  r.n = 16;
  r.psi0 = -(int64_t{1} << 28);  // -1 rad
  r.dpsi = int64_t{1} << 20;     // 2^-8 rad
  r.len = 2047;
  for (int i : {0, 1, 256, 2047}) CHECK(m.trace(r, i).psi == -(int64_t{1} << 28) + int64_t{i} * (int64_t{1} << 20));
  const auto line = m.line(r);
  REQUIRE(line.size() == 2048u);
  CHECK(line[256] == m.pixel(r, 256));
  // psi = 0 at i = 256: address 0 of bank 3 -> synthetic word 30000.
  CHECK(m.trace(r, 256).cosk == 30000u);
  r.n = 0;
  for (uint32_t v : m.line(r)) CHECK(v == 0u);
  // Register widths: len is cut to 11 bits, dpsi sign-extended from 32 bits.
  r.n = 16;
  r.len = 2048 + 3;
  CHECK(m.line(r).size() == 4u);
  r.dpsi = 0xFFFFFFFFLL;  // the 32-bit code of -1 LSB
  CHECK(m.trace(r, 1).psi == r.psi0 - 1);
}

TEST_CASE("ROM 12 image matches cos^k closed forms", "[rom]") {
  const Format f;
  const auto img = cos_rom_image(f);
  REQUIRE(img.size() == 4u * 4096u);
  CHECK(img[0] == 65535u);                 // cos^1(0) = 1 saturates
  CHECK(img[4096 + 2048] == 32768u);       // cos^2(pi/4) = 1/2
  CHECK(img[2 * 4096 + 2048] == 16384u);   // cos^4(pi/4) = 1/4
  CHECK(img[3 * 4096 + 2048] == 256u);     // cos^16(pi/4) = 2^-8
  CHECK(img[4096 - 1] == static_cast<uint32_t>(std::lround(std::sin(std::numbers::pi / 8192) * 65536)));
  CHECK(img[2731] == static_cast<uint32_t>(std::lround(std::cos(std::numbers::pi / 2 * 2731 / 4096) * 65536)));
}

TEST_CASE("ROM 9 image: maclaurin words are sqrt(n/k) * 2/pi, bad coefficients are rejected", "[rom]") {
  const Format f;
  const auto img = coef_rom_image(f, parse_coef_spec("maclaurin"));
  REQUIRE(img.size() == 1024u);
  CHECK(img[0] == 0u);
  CHECK(img[1001] == 0u);
  CHECK(img[1] == 20861u);     // a = 1: round(2/pi * 2^15)
  CHECK(img[16] == 20861u);    // n = k = 16
  CHECK(img[1000] == 164919u); // sqrt(62.5) * 2/pi * 2^15 = 164918.9
  CHECK(img[3] == static_cast<uint32_t>(std::lround(std::sqrt(0.75) * 2 / std::numbers::pi * 32768)));
  CHECK_THROWS_AS(coef_word(std::numbers::pi / 16 * 0.999, f), std::invalid_argument);
  CHECK(coef_word(std::numbers::pi / 16, f) == 4096u);
  CHECK_THROWS_AS(coef_word(4 * std::numbers::pi, f), std::invalid_argument);  // a*2/pi = 8
}

TEST_CASE("hex files: round trip, exact format, errors name file and line", "[rom]") {
  const std::string p = temp_path("rt.hex");
  write_hex(p, {0, 1, 0x3ffff, 0xabc}, 18);
  {
    std::ifstream in(p);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(text == "00000\n00001\n3ffff\n00abc\n");
  }
  CHECK(read_hex(p, 18, 4) == std::vector<uint32_t>{0, 1, 0x3ffff, 0xabc});
  CHECK_THROWS_WITH(read_hex(p, 18, 5), Catch::Matchers::Contains("4 words, expected 5"));
  CHECK_THROWS_WITH(read_hex(p, 17, 4), Catch::Matchers::Contains(p + ":3: word 3ffff is wider"));
  CHECK_THROWS_WITH(read_hex(p, 16, 4), Catch::Matchers::Contains(p + ":1: '00000' has more than 4"));
  CHECK_THROWS_AS(write_hex(p, {0x40000}, 18), std::runtime_error);
  CHECK(read_hex(p, 18, 4).size() == 4u);  // the failed write left the old file intact
  {
    std::ofstream out(p);
    out << "0000\nzz\n";
  }
  CHECK_THROWS_WITH(read_hex(p, 16, 2), Catch::Matchers::Contains(p + ":2"));
  CHECK_THROWS_WITH(read_hex(temp_path("missing.hex"), 16, 2), Catch::Matchers::Contains("cannot open"));
  std::remove(p.c_str());
}

TEST_CASE("committed ROMs load into the golden model", "[rom]") {
  const Format f;
  // Working directory = repository root (ctest WORKING_DIRECTORY).
  const auto m = load_device_model(f, kCoefMaclaurinHex, kCosHex);
  Registers r;
  r.c = 32768;
  r.n = 2;  // k = 2, a = 1: I = cos^2(psi)
  r.psi0 = device::quantize_angle(std::numbers::pi / 4, f);
  CHECK(m.pixel(r, 0) == 16384u);  // cos^2(pi/4) / 2^... = 0.5 * C
  CHECK_NOTHROW(load_device_model(f, kCoefMinimaxHex, kCosHex));
}

TEST_CASE("load_registers: the host's register writes for one scanline", "[golden]") {
  const device::Format f;
  specular::ScanlineSetup s;
  s.C = 0.75;
  s.psi0 = -0.5;
  s.dpsi = 0.001;
  auto load = device::load_registers(s, 5.6, 3, f);
  CHECK(load.reg.c == 24576u);                  // 0.75 * 2^15
  CHECK(load.reg.psi0 == -134217728LL);         // -0.5 * 2^28
  CHECK(load.reg.dpsi == 268435LL);             // round(0.001 * 2^28 = 268435.456)
  CHECK(load.reg.n == 6u);                      // nearest integer exponent
  CHECK(load.reg.len == 3u);
  CHECK_FALSE(load.c_saturated);
  CHECK_FALSE(load.angle_saturated);
  CHECK(device::load_registers(s, 0.0, 0, f).reg.n == 0u);       // invalid n stays invalid
  CHECK(device::load_registers(s, 1500.0, 0, f).reg.n == 1023u);  // and > 1000 too
  CHECK(device::load_registers(s, 7.0, 5000, f).reg.len == 2047u);
  s.C = 2.5;
  s.psi0 = 9.0;
  load = device::load_registers(s, 7.0, 1, f);
  CHECK(load.c_saturated);
  CHECK(load.reg.c == 65535u);
  CHECK(load.angle_saturated);
}
