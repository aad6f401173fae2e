// ROM 9 (coefficients) and ROM 12 (cos^k), entry by entry: the RTL ROMs load the
// committed hex files with $readmemh (paths relative to the repository root, the
// working directory of this test) and must return the generator's images
// (model/rom_image.hpp) at every address, one synchronous read per clock.
#include "Vcoef_rom_maclaurin.h"
#include "Vcoef_rom_minimax.h"
#include "Vcos_k_rom.h"
#include "rtl_harness.hpp"

#include "device_model.hpp"
#include "rom_image.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <cstdint>
#include <vector>

using specular::rtl_test::tick;

namespace {

template <class Rom>
void check_coef_rom(Rom& dut, const std::vector<uint32_t>& image) {
  REQUIRE(image.size() == 1024);
  int mismatches = 0;
  for (unsigned n = 0; n < 1024; ++n) {
    dut.n_i = n;
    tick(dut);  // registered read: the word appears after the edge
    if (static_cast<uint32_t>(dut.coef_o) != image[n]) {
      if (++mismatches <= 10) {
        UNSCOPED_INFO("n = " << n << ": rtl " << dut.coef_o << ", generator " << image[n]);
      }
    }
  }
  CHECK(mismatches == 0);
}

}  // namespace

TEST_CASE("ROM 9 (minimax) matches the generator at all 1024 addresses", "[rtl][rom]") {
  const specular::device::Format f;
  specular::CoefSpec spec;
  spec.policy = specular::CoefPolicy::minimax;
  Vcoef_rom_minimax dut;
  dut.en_i = 1;
  check_coef_rom(dut, specular::coef_rom_image(f, spec));
}

TEST_CASE("ROM 9 (maclaurin) matches the generator at all 1024 addresses", "[rtl][rom]") {
  const specular::device::Format f;
  specular::CoefSpec spec;
  spec.policy = specular::CoefPolicy::maclaurin;
  const auto image = specular::coef_rom_image(f, spec);
  // Independent spot checks of the generator itself: a = sqrt(n/k), word = a*2/pi*2^15.
  for (unsigned n : {1u, 2u, 3u, 6u, 7u, 100u, 1000u}) {
    const int k = n == 1 ? 1 : n == 2 ? 2 : n <= 6 ? 4 : 16;
    const double word = std::sqrt(static_cast<double>(n) / k) * 2.0 / std::numbers::pi * 32768.0;
    INFO("n = " << n);
    CHECK(static_cast<double>(image[n]) == Approx(std::round(word)).margin(0.0));
  }
  Vcoef_rom_maclaurin dut;
  dut.en_i = 1;
  check_coef_rom(dut, image);
}

TEST_CASE("ROM 12 matches the generator in every bank and entry", "[rtl][rom]") {
  const specular::device::Format f;
  const auto image = specular::cos_rom_image(f);
  REQUIRE(image.size() == 4u * 4096u);
  Vcos_k_rom dut;
  dut.en_i = 1;
  int mismatches = 0;
  for (unsigned bank = 0; bank < 4; ++bank) {
    for (unsigned i = 0; i < 4096; ++i) {
      dut.bank_i = 1u << bank;  // one-hot from decoder 10
      dut.addr_i = i;
      tick(dut);
      const uint32_t want = image[bank * 4096 + i];
      if (static_cast<uint32_t>(dut.cosk_o) != want) {
        if (++mismatches <= 10) {
          UNSCOPED_INFO("bank " << bank << " entry " << i << ": rtl " << dut.cosk_o
                                << ", generator " << want);
        }
      }
    }
  }
  CHECK(mismatches == 0);
  // Independent anchors: cos^k(0) saturates to 0xffff; cos(pi/4)^2 = 1/2 exactly.
  dut.bank_i = 0b0010;
  dut.addr_i = 2048;
  tick(dut);
  CHECK(dut.cosk_o == 0x8000);
  for (unsigned bank = 0; bank < 4; ++bank) {
    dut.bank_i = 1u << bank;
    dut.addr_i = 0;
    tick(dut);
    CHECK(dut.cosk_o == 0xffff);
  }
  // No bank selected (invalid n) reads bank 0; the pixel is zeroed downstream.
  dut.bank_i = 0;
  dut.addr_i = 1000;
  tick(dut);
  CHECK(static_cast<uint32_t>(dut.cosk_o) == image[1000]);
}
