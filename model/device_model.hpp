// Bit-accurate golden model of the device datapath (patent UA 71489), SPEC sections 5, 6, 9.
//
// One definition of every width and rounding rule, shared by the ROM generator
// (model/tools/romgen.cpp), the Verilator testbench (sim/) and the report. The RTL
// (rtl/specular_unit.sv) has the same parameters with the same defaults; the build
// passes the values of `Format` to Verilator as -G overrides so the two cannot drift.
//
// Datapath, per pixel (block numbers of the patent):
//   reg 8 (accumulator)  psi   signed AccBits, AngleFrac fraction bits; psi0 then psi + dpsi
//   |psi|                      cos is even; |psi| >= 8 rad  -> pixel is 0 ("far")
//   multiplier 11        zeta  = coef(n) * |psi|_t  where |psi|_t keeps 3 integer bits and
//                              PsiMulFrac fraction bits (truncated) and coef is a(n)*2/pi
//                              (unsigned, CoefBits, CoefFrac fraction bits), so zeta is in
//                              quarter turns: zeta >= 1 means a*|psi| >= pi/2
//   ROM 12 address             addr = round-half-up(zeta * 2^CosAddrBits);
//                              addr >= 2^CosAddrBits -> pixel is 0
//   ROM 12               cosk  = cos_k_rom[bank * 2^CosAddrBits + addr], CosDataBits fraction
//                              bits, entry = min(round(cos^k(addr * pi/2 / 2^CosAddrBits) * 2^CosDataBits),
//                              2^CosDataBits - 1)   (cos^k(0) = 1 saturates deliberately)
//   multiplier 13        I     = (C * cosk + 2^(CosDataBits-1)) >> CosDataBits   (same format as C)
//   decoder 10           bank  from n (bank_max_n table); n = 0 or n > 1000 -> every pixel 0
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace specular::device {

struct Format {
  int c_bits = 16, c_frac = 15;            // reg 1 and the output: unsigned, 0 <= C < 2
  int angle_bits = 32, angle_frac = 28;    // reg 2 (dpsi) and reg 3 (psi0): signed radians
  int acc_bits = 44;                       // reg 8: angle_bits + 12, cannot overflow over 2048 adds
  int n_bits = 10;                         // reg 4
  int len_bits = 11;                       // counter 5
  int coef_bits = 18, coef_frac = 15;      // ROM 9 words: a(n) * 2/pi
  int psi_mul_frac = 20;                   // fraction bits of |psi| kept at multiplier 11
  int cos_addr_bits = 12;                  // ROM 12 address bits per bank
  int cos_data_bits = 16;                  // ROM 12 word width (all fraction bits)
  std::vector<int> banks{1, 2, 4, 16};     // k of each ROM 12 bank
  std::vector<int> bank_max_n{1, 2, 6, 1000};  // decoder 10: bank j serves bank_max_n[j-1] < n <= bank_max_n[j]

  int max_n() const { return 1000; }
  int coef_rom_depth() const { return 1 << n_bits; }
  int cos_rom_depth() const { return static_cast<int>(banks.size()) << cos_addr_bits; }
};

// Register contents as the device holds them (raw two's complement / unsigned codes).
struct Registers {
  uint32_t c = 0;      // reg 1
  int64_t dpsi = 0;    // reg 2 (sign-extended value)
  int64_t psi0 = 0;    // reg 3 (sign-extended value)
  uint32_t n = 0;      // reg 4
  uint32_t len = 0;    // counter 5: the line has len + 1 pixels
};

}  // namespace specular::device
