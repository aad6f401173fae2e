// SPDX-License-Identifier: Apache-2.0
// Unit tests of the golden model (model/device/device_model) and the ROM images (model/device/rom_image)
// against hand-computed values of the header contract, with synthetic ROMs whose contents
// make every stage visible (identity cos ROM, power-of-two coefficients).
#include "decoder_table.hpp"
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

// The patent's build (direct ROM 12, 4096 entries, coefficient words with 15 fraction bits):
// every coefficient word = `coef`; ROM 12 word = its own address within the bank plus
// bank * 10000 (so the bank is visible in the output too: values stay below 2^16).
DeviceModel synthetic(uint32_t coef, const Format& f = Format::patent()) {
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

TEST_CASE("decoder 10 follows the patent table in the patent build", "[golden]") {
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

TEST_CASE("datapath stages by hand (patent build)", "[golden]") {
  const Format f = Format::patent();
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
  // cos is even: -psi gives the same pixel (its one's complement magnitude is one code
  // below |psi|, 2^-28 rad, far below the address step).
  Registers neg = r;
  neg.psi0 = -r.psi0;
  CHECK(m.trace(neg, 0).abs_psi == (uint64_t{1} << 26) - 1);
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

TEST_CASE("|psi| >= pi/2 is zero exactly, both signs, whatever a", "[golden]") {
  // a * 2/pi = 1/8 (a < 1): without the test the lobe of cos^k(a psi) would run far past
  // pi/2, where N.H < 0 and the reference is 0.
  for (const Format& f : {Format::patent(), Format{}}) {
    const uint32_t coef = 1u << (f.coef_frac - 3);
    std::vector<uint32_t> c(f.coef_rom_depth(), coef);
    std::vector<uint32_t> k(f.cos_rom_depth(), f.cos_interp ? (1u << (f.cos_data_bits - 1)) << f.cos_delta_bits : 1000u);
    const DeviceModel m(f, c, k);
    // ceil(pi/2 * 2^28), from the decimal expansion of pi/2 = 1.5707963267948966...
    const int64_t h = 421657429;
    REQUIRE(f.half_pi_code() == h);
    REQUIRE(std::ldexp(static_cast<double>(h - 1), -28) < std::numbers::pi / 2);
    REQUIRE(std::ldexp(static_cast<double>(h), -28) > std::numbers::pi / 2);
    Registers r;
    r.c = 32768;
    r.n = 1000;
    for (int sign : {1, -1}) {
      INFO("interp " << f.cos_interp << ", sign " << sign);
      r.psi0 = sign * h;
      CHECK(m.trace(r, 0).far);
      CHECK(m.pixel(r, 0) == 0u);
      r.psi0 = sign * (h - 1);
      CHECK_FALSE(m.trace(r, 0).far);
      CHECK(m.pixel(r, 0) != 0u);  // a * psi = pi/16 < pi/2: the ROM word decides
      r.psi0 = sign * (int64_t{8} << 28);
      CHECK(m.trace(r, 0).far);
    }
  }
}

TEST_CASE("interpolated ROM 12: address, weight and cos^k = v - d t by hand", "[golden]") {
  const Format f;  // interpolated: 256 entries, 12-bit weight, 18 fraction bits
  REQUIRE(f.cos_interp);
  // Coefficient word 2^18: a * 2/pi = 1, zeta = |psi| (quarter turns per radian).
  std::vector<uint32_t> c(f.coef_rom_depth(), 1u << 18);
  // Every word: v = 2^17 + bank, d = 1000.
  std::vector<uint32_t> k(f.cos_rom_depth());
  for (size_t i = 0; i < k.size(); ++i) k[i] = ((1u << 17) + static_cast<uint32_t>(i >> 8)) << 12 | 1000u;
  const DeviceModel m(f, c, k);
  Registers r;
  r.c = 32768;
  r.n = 1;
  // psi = (37 + 1/4) / 256 rad: address 37, weight 1024 of 4096.
  r.psi0 = (int64_t{37} << 20) + (int64_t{1} << 18);
  auto t = m.trace(r, 0);
  CHECK(t.addr == 37u);
  CHECK(t.frac == 1024u);
  CHECK(t.cosk == (1u << 17) - 250u);  // v - round(1000 * 1024 / 4096)
  CHECK(t.intensity == (32768u * ((1u << 17) - 250u) + (1u << 17)) >> 18);
  // Half a weight LSB rounds up: d t = 1000 * 2 = 2000 -> 2000/4096 = 0.49 rounds to 0;
  // t = 3 -> 0.73 rounds to 1.
  r.psi0 = (int64_t{37} << 20) + (int64_t{2} << 8);
  CHECK(m.trace(r, 0).cosk == (1u << 17));
  r.psi0 = (int64_t{37} << 20) + (int64_t{3} << 8);
  CHECK(m.trace(r, 0).cosk == (1u << 17) - 1u);
  // Bank of n = 1000 (k = 16, the last of 8 banks) adds 7 in this synthetic ROM.
  r.n = 1000;
  r.psi0 = int64_t{37} << 20;
  CHECK(m.trace(r, 0).cosk == (1u << 17) + 7u);
  // One quarter turn: zeta = 1 is past the table, the pixel is 0.
  r.psi0 = int64_t{1} << 28;
  CHECK(m.trace(r, 0).overflow);
  CHECK(m.pixel(r, 0) == 0u);
  // C x 1 is exact: v = 2^18 (cos^k(0) = 1) gives I = C for every C.
  std::vector<uint32_t> one(f.cos_rom_depth(), (1u << 18) << 12);
  const DeviceModel m1(f, c, one);
  r.psi0 = 0;
  for (uint32_t cc : {1u, 32768u, 40000u, 65535u}) {
    r.c = cc;
    CHECK(m1.pixel(r, 0) == cc);
  }
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
  // psi = 0 at i = 256: address 0 of bank 3 -> synthetic word 30000, and multiplier 13 of
  // the patent's format (16 fraction bits, round half up): I = (C * 30000 + 2^15) >> 16.
  CHECK(m.trace(r, 256).cosk == 30000u);
  CHECK(line[256] == (40000u * 30000u + (1u << 15)) >> 16);
  CHECK(line[256] == 18311u);
  r.n = 0;
  for (uint32_t v : m.line(r)) CHECK(v == 0u);
  // Register widths: len is cut to 11 bits, dpsi sign-extended from 32 bits.
  r.n = 16;
  r.len = 2048 + 3;
  CHECK(m.line(r).size() == 4u);
  r.dpsi = 0xFFFFFFFFLL;  // the 32-bit code of -1 LSB
  CHECK(m.trace(r, 1).psi == r.psi0 - 1);
}

TEST_CASE("ROM 12 image (patent, direct) matches cos^k closed forms", "[rom]") {
  const Format f = Format::patent();
  const auto img = cos_rom_image(f);
  REQUIRE(img.size() == 4u * 4096u);
  CHECK(img[0] == 65535u);                 // cos^1(0) = 1 saturates
  CHECK(img[4096 + 2048] == 32768u);       // cos^2(pi/4) = 1/2
  CHECK(img[2 * 4096 + 2048] == 16384u);   // cos^4(pi/4) = 1/4
  CHECK(img[3 * 4096 + 2048] == 256u);     // cos^16(pi/4) = 2^-8
  CHECK(img[4096 - 1] == static_cast<uint32_t>(std::lround(std::sin(std::numbers::pi / 8192) * 65536)));
  CHECK(img[2731] == static_cast<uint32_t>(std::lround(std::cos(std::numbers::pi / 2 * 2731 / 4096) * 65536)));
}

TEST_CASE("ROM 12 image (single-bank build, interpolated) matches cos^k closed forms", "[rom]") {
  const Format f;
  const auto img = cos_rom_image(f);
  REQUIRE(img.size() == 8u * 256u);
  auto v = [&](int bank, int i) { return img[bank * 256 + i] >> 12; };
  auto d = [&](int bank, int i) { return img[bank * 256 + i] & 4095u; };
  // Banks k = 1, 2, 3, 4, 6, 8, 12, 16. cos^k(0) = 1 exactly (2^18, no saturation).
  for (int b = 0; b < 8; ++b) CHECK(v(b, 0) == (1u << 18));
  CHECK(v(1, 128) == (1u << 17));   // cos^2(pi/4) = 1/2
  CHECK(v(3, 128) == (1u << 16));   // cos^4(pi/4) = 1/4
  CHECK(v(7, 128) == (1u << 10));   // cos^16(pi/4) = 2^-8
  CHECK(v(2, 128) == static_cast<uint32_t>(std::lround(std::pow(std::sqrt(0.5), 3) * 262144)));
  // The step is the difference to the next entry; past the last entry cos^k(pi/2) = 0.
  for (int b = 0; b < 8; ++b) {
    for (int i = 0; i < 255; ++i) REQUIRE(d(b, i) == v(b, i) - v(b, i + 1));
    CHECK(d(b, 255) == v(b, 255));
  }
  CHECK(v(0, 255) == static_cast<uint32_t>(std::lround(std::sin(std::numbers::pi / 512) * 262144)));
}

TEST_CASE("ROM 9 image: maclaurin words are sqrt(n/k) * 2/pi, bad coefficients are rejected", "[rom]") {
  const Format f = Format::patent();
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
  CHECK_THROWS_WITH(read_hex(p, 16, 4), Catch::Matchers::Contains(p + ":1: '00000' has 5 hex digits, expected 4"));
  CHECK_THROWS_WITH(read_hex(p, 21, 4), Catch::Matchers::Contains(p + ":1: '00000' has 5 hex digits, expected 6"));
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
  const Format f = Format::patent();
  // Working directory = repository root (ctest WORKING_DIRECTORY).
  const auto m = load_device_model(f, kPatentCoefHex, kPatentCosHex);
  Registers r;
  r.c = 32768;
  r.n = 2;  // k = 2, a = 1: I = cos^2(psi)
  r.psi0 = device::quantize_angle(std::numbers::pi / 4, f);
  CHECK(m.pixel(r, 0) == 16384u);  // cos^2(pi/4) / 2^... = 0.5 * C
  // Every build configuration's committed files load with its format; a file of the wrong
  // length or width is refused with its name.
  for (const auto& bc : build_configs()) {
    INFO(bc.name);
    CHECK_NOTHROW(load_device_model(bc.f, bc.coef_hex(), bc.cos_hex()));
  }
  CHECK_THROWS_WITH(load_device_model(Format{}, kCoefMinimaxHex, kPatentCosHex),
                    Catch::Matchers::Contains(kPatentCosHex));
  CHECK_THROWS_WITH(load_device_model(Format{}, kPatentCoefHex, kCosHex), Catch::Matchers::Contains(kPatentCoefHex));
  // The single-bank build: n = 2 is bank k = 2 with a = 1 (minimax of cos^2 for cos^2 is exact).
  const Format d;
  const auto md = load_device_model(d, kCoefMinimaxHex, kCosHex);
  r.psi0 = device::quantize_angle(std::numbers::pi / 4, d);
  CHECK(md.pixel(r, 0) == 16384u);
}

TEST_CASE("the single-bank decoder table is the one derived from its bank set", "[golden]") {
  const Format f;
  CHECK(f.bank_max_n == derive_bank_max_n(f.banks, parse_coef_spec("minimax")));
  const Format p = Format::patent();
  CHECK(p.bank_max_n == derive_bank_max_n(p.banks, parse_coef_spec("maclaurin")));
  CHECK(p.bank_max_n == std::vector<int>{1, 2, 6, 1000});  // patent UA 71489
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
