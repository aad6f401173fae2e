// SPDX-License-Identifier: Apache-2.0
// Bit-accurate golden model of the device datapath (patent UA 71489), docs/device.md and docs/interfaces.md.
//
// One definition of every width and rounding rule, shared by the ROM generator
// (model/tools/romgen.cpp), the Verilator testbench (sim/) and the report. The RTL
// (rtl/core/specular_unit.sv) has the same parameters with the same defaults; the build
// passes the values of `Format` to Verilator as -G overrides so the two cannot drift.
//
// Datapath, per pixel (block numbers of the patent):
//   reg 8 (accumulator)  psi   signed AccBits, AngleFrac fraction bits; psi0 then psi + dpsi
//   |psi|                      one's complement magnitude: psi >= 0 ? psi : ~psi (= |psi| - 1
//                              code; cos is even, the code is 2^-AngleFrac rad below |psi|)
//   far                        |psi| >= pi/2 exactly (N.H < 0 there, the reference is 0):
//                              |psi| code >= ceil(pi/2 * 2^AngleFrac)  -> pixel is 0
//   multiplier 11        zeta  = coef(n) * |psi|_t where |psi|_t keeps 1 integer bit and
//                              PsiMulFrac fraction bits (truncated) and coef is a(n)*2/pi
//                              (unsigned, CoefBits, CoefFrac fraction bits), so zeta is in
//                              quarter turns: zeta >= 1 means a*|psi| >= pi/2 -> pixel is 0
//   ROM 12, interpolated (cos_interp, the default build):
//                        addr  = the CosAddrBits bits of zeta below the binary point,
//                        t     = the next CosFracBits bits (the rest is truncated);
//                        word  = cos_k_rom[bank * 2^CosAddrBits + addr] = {v, d}:
//                              v = round(cos^k(addr * h) * 2^CosDataBits), h = pi/2 / 2^CosAddrBits
//                              (CosDataBits + 1 bits: cos^k(0) = 1 is exact), d = v - v(addr + 1)
//                              (CosDeltaBits bits, v(2^CosAddrBits) = 0)
//                        cosk  = v - ((d * t + 2^(CosFracBits-1)) >> CosFracBits)
//   ROM 12, direct (the patent's table, Format::patent()):
//                        addr  = round-half-up(zeta * 2^CosAddrBits), >= 2^CosAddrBits -> 0
//                        cosk  = min(round(cos^k(addr * h) * 2^CosDataBits), 2^CosDataBits - 1)
//   multiplier 13        I     = (C * cosk + 2^(CosDataBits-1)) >> CosDataBits   (same format as C)
//   decoder 10           bank  from n (bank_max_n table); n = 0 or n > 1000 -> every pixel 0
//   blend (Format::blend, off by default; docs/display_exact.md): a second multiplier 11 and ROM 12
//                        read for the next bank, blended by a weight from ROM 9 before multiplier 13
#pragma once

#include "coefficients.hpp"
#include "scanline_setup.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <string>
#include <vector>

namespace specular::device {

// The default build: interpolated ROM 12 of 8 banks x 256 entries x 31 bits (63,488 bits), minimax
// coefficients, decoder table derived from the bank set (derive_bank_max_n). Format::patent()
// is the patent's own configuration: direct 4096-entry table, banks {1, 2, 4, 16}, decoder
// 1 | 2 | 3..6 | 7..1000 (with maclaurin coefficients a = sqrt(n/k) in ROM 9).
struct Format {
  int c_bits = 16, c_frac = 15;            // reg 1 and the output: unsigned, 0 <= C < 2
  int angle_bits = 32, angle_frac = 28;    // reg 2 (dpsi) and reg 3 (psi0): signed radians
  int acc_bits = 44;                       // reg 8: angle_bits + 12, cannot overflow over 2048 adds
  // reg 4: 10 bits, the width of kMaxN (the patent's range of n, coefficients.hpp)
  int n_bits = std::bit_width(static_cast<unsigned>(kMaxN));
  // counter 5: 11 bits, the width of kMaxLen (scanline_setup.hpp: l in 0..kMaxLen)
  int len_bits = std::bit_width(static_cast<unsigned>(kMaxLen));
  int coef_bits = 21, coef_frac = 18;      // ROM 9 words: a(n) * 2/pi
  int psi_mul_frac = 20;                   // fraction bits of |psi| kept at multiplier 11
  bool cos_interp = true;                  // ROM 12 interpolated (false: direct table)
  int cos_addr_bits = 8;                   // ROM 12 entries per bank: 2^cos_addr_bits
  int cos_data_bits = 18;                  // fraction bits of cos^k (ROM 12 value / direct word)
  int cos_delta_bits = 12;                 // interpolated: width of the step d to the next entry
  int cos_frac_bits = 12;                  // interpolated: bits of zeta that weight the step
  std::vector<int> banks{1, 2, 3, 4, 6, 8, 12, 16};            // k of each ROM 12 bank
  std::vector<int> bank_max_n{1, 2, 3, 4, 6, 9, 13, kMaxN};    // decoder 10: bank j serves
                                                               // bank_max_n[j-1] < n <= bank_max_n[j]
                                                               // (decoder_bank, coefficients.hpp)
  // Display-exact options (docs/display_exact.md); their defaults leave every build above as it was.
  // ROM 12 bank j holds cos^k over a x in [0, pi/2 * 2^-bank_shift[j]) (its own domain: a bank of
  // large k lives in the first hundredths of a radian); ROM 9 then holds a(n) * 2^shift * 2/pi, so
  // the datapath is the same. Empty: every shift 0.
  std::vector<int> bank_shift{};
  // Two banks per n (decoder 10's bank j and the next, j + 1, or j again for the last bank):
  //   cosb = c1 + ((c2 - c1) * w + 2^(weight_bits-1)) >> weight_bits   (arithmetic shift: floor)
  // with c1 = cos^k1(a1 |psi|), c2 = cos^k2(a2 |psi|) each read as above (a second multiplier 11 and
  // a second ROM 12 read; a read past its domain is 0), w = round(t 2^weight_bits) the weight of
  // bank j + 1 from a third ROM 9 field; multiplier 13 takes cosb. In blend mode bank_max_n may
  // have one entry fewer than banks: the last bank then serves only as a second bank.
  bool blend = false;
  int weight_bits = 12;

  // The patent's configuration (bit-exact build option, see the header comment).
  static Format patent();

  static constexpr int max_n() { return kMaxN; }
  // Counter 5's largest l: the line has at most max_len() + 1 pixels.
  int max_len() const { return (1 << len_bits) - 1; }
  int coef_rom_depth() const { return 1 << n_bits; }
  int cos_rom_depth() const { return static_cast<int>(banks.size()) << cos_addr_bits; }
  // Bits of one ROM 12 word: {v, d} interpolated, the saturating value direct.
  int cos_word_bits() const { return cos_interp ? cos_data_bits + 1 + cos_delta_bits : cos_data_bits; }
  int shift_of(int bank) const { return bank_shift.empty() ? 0 : bank_shift[static_cast<size_t>(bank)]; }
  // Bits of one ROM 9 word: a1 alone, or {a1, a2, w} in blend mode.
  int coef_word_bits() const { return blend ? 2 * coef_bits + weight_bits : coef_bits; }
  // ceil(pi/2 * 2^angle_frac): |psi| codes at or above it are at or past pi/2.
  int64_t half_pi_code() const;
  bool operator==(const Format&) const = default;
};
// kMaxLen is a full counter: the default len_bits hold exactly 0..kMaxLen.
static_assert(std::has_single_bit(static_cast<unsigned>(kMaxLen) + 1U), "kMaxLen must be 2^len_bits - 1");

// Register contents as the device holds them (raw two's complement / unsigned codes).
struct Registers {
  uint32_t c = 0;      // reg 1
  int64_t dpsi = 0;    // reg 2 (sign-extended value)
  int64_t psi0 = 0;    // reg 3 (sign-extended value)
  uint32_t n = 0;      // reg 4
  uint32_t len = 0;    // counter 5: the line has len + 1 pixels
};

// ---- Host-side quantizers (the only place doubles meet the device formats) ----
// Round to nearest (ties away from zero). `saturated`, when given, is set to true if the
// value was clamped (C: negative or >= 2 - 2^-c_frac, angle: outside the signed range)
// or was NaN (mapped to 0), and to false otherwise.
uint32_t quantize_c(double c, const Format& f, bool* saturated = nullptr);
int64_t quantize_angle(double rad, const Format& f, bool* saturated = nullptr);
// The rounding rule under both: x * 2^frac to the nearest code (ties away from zero), clamped
// to [lo, hi], NaN to 0; the geometry span's vector components use it too (geo_span.hpp).
int64_t quantize_fixed(double x, int frac, int64_t lo, int64_t hi, bool* saturated = nullptr);
// Register 4's code for n (nearest integer, clamped to n_bits; not finite: 0) and counter 5's
// for l (clamped to 0..max_len()).
uint32_t quantize_n(double n, const Format& f);
uint32_t quantize_len(int l, const Format& f);
// Exact conversions back (every code is exactly representable in a double).
double c_value(uint32_t code, const Format& f);
double angle_value(int64_t code, const Format& f);
// The coefficient a(n) (radians per radian) that ROM 9 word `code` = a * 2/pi * 2^coef_frac
// stands for.
double coef_value(uint32_t code, const Format& f);

// The host's register writes for one scanline (docs/scanline_setup.md -> docs/interfaces.md): C, psi0 and dpsi
// quantized as above; n to the nearest integer code (0 and > 1000 stay invalid, so the
// device outputs 0, as the setup's C = 0 does); l clamped to the counter. Every path that
// loads the device (regression, scenes, report) goes through here.
struct RegisterLoad {
  Registers reg;
  bool c_saturated = false;      // C outside [0, 2): clamped
  bool angle_saturated = false;  // psi0 or dpsi outside the signed range: clamped
};
RegisterLoad load_registers(const ScanlineSetup& s, double n, int l, const Format& f);

// Everything multiplier 11 .. multiplier 13 compute for one pixel, for debugging and
// for the quantization analysis. Fields after the one that zeroed the pixel keep 0.
struct PixelTrace {
  int64_t psi = 0;          // reg 8: psi0 + i*dpsi, acc_bits two's complement, angle_frac bits
  uint64_t abs_psi = 0;     // one's complement magnitude (psi >= 0 ? psi : ~psi)
  bool far = false;         // |psi| >= pi/2: pixel 0 without using the multiplier
  uint64_t abs_psi_t = 0;   // |psi| truncated to 1 integer + psi_mul_frac fraction bits
  int bank = -1;            // decoder 10; -1: n = 0 or n > max_n (pixel 0)
  uint32_t coef = 0;        // ROM 9 word at address n
  uint64_t zeta = 0;        // coef * |psi|_t, coef_frac + psi_mul_frac fraction bits, quarter turns
  uint64_t addr = 0;        // ROM 12 address (direct: rounded, before the overflow test)
  uint32_t frac = 0;        // interpolated: the step weight t
  bool overflow = false;    // a|psi| >= pi/2: pixel 0
  uint32_t word = 0;        // ROM 12 word
  uint32_t cosk = 0;        // cos^k, cos_data_bits fraction bits (interpolated or direct)
  uint32_t intensity = 0;   // multiplier 13 output
  // Blend mode only (Format::blend): the second read, the weight and the blended value.
  int bank2 = -1;           // decoder 10's second bank
  uint32_t coef2 = 0;       // ROM 9's a2 field
  uint64_t zeta2 = 0, addr2 = 0;
  uint32_t frac2 = 0;
  bool overflow2 = false;   // a2 |psi| past bank2's domain: c2 = 0
  uint32_t word2 = 0, cosk2 = 0;
  uint32_t weight = 0;      // ROM 9's w field
  uint32_t blended = 0;     // cosb, the input of multiplier 13
};

// ROM 9's two further fields in blend mode, each coef_rom_depth() words: a2 (coef_bits) and the
// weight w (weight_bits).
struct BlendRoms {
  std::vector<uint32_t> coef2, weight;
};

// Stream view (rtl/core/specular_stream.sv): a span is one line's registers plus an opaque tag;
// the core returns every pixel of every span in order, each with its span's tag and a
// last flag on pixel l. The values are those of line() for the same registers.
struct Span {
  Registers reg;
  uint32_t tag = 0;
};
struct StreamPixel {
  uint32_t intensity = 0;
  bool last = false;
  uint32_t tag = 0;
  bool operator==(const StreamPixel&) const = default;
};

// The RGB core (specular_stream's Channels = 3, docs/interfaces.md): one C per channel, channel 0
// first (the low bits of span_c_i and px_intensity_o).
using RgbC = std::array<uint32_t, 3>;

// The datapath of the header comment, integer arithmetic only.
class DeviceModel {
 public:
  // coef_rom: coef_rom_depth() words of coef_bits; cos_rom: cos_rom_depth() words of
  // cos_data_bits. Throws std::invalid_argument on a size, width or format mismatch.
  DeviceModel(Format f, std::vector<uint32_t> coef_rom, std::vector<uint32_t> cos_rom);
  // Blend mode (f.blend must be true; the constructor above refuses it).
  DeviceModel(Format f, std::vector<uint32_t> coef_rom, std::vector<uint32_t> cos_rom, BlendRoms blend);

  const Format& format() const { return f_; }
  // ROM 9 (a, or a1 in blend mode) and, in blend mode, its fields a2 and w.
  const std::vector<uint32_t>& coef_rom() const { return coef_rom_; }
  const BlendRoms& blend_roms() const { return blend_; }
  // Decoder 10: bank index for n, -1 when n = 0 or n > max_n.
  int bank_of(uint32_t n) const;
  // Blend mode: the second bank of first bank j (j + 1, the last bank for the last).
  int second_bank(int j) const { return std::min(j + 1, static_cast<int>(f_.banks.size()) - 1); }
  uint32_t pixel(const Registers& r, int i) const { return trace(r, i).intensity; }
  // The RGB core's pixel i: the one cos^k (or blended value) of trace(r, i) through multiplier 13
  // once per channel, C = c[ch] (each cut to c_bits); r.c is not used. Channel ch equals
  // pixel() with r.c = c[ch].
  RgbC rgb_pixel(const Registers& r, const RgbC& c, int i) const;
  PixelTrace trace(const Registers& r, int i) const;
  // The l + 1 = len + 1 intensities of one line in pixel order.
  std::vector<uint32_t> line(const Registers& r) const;
  // The pixels of one span (l + 1 of them), appended to `out`, and of a span sequence.
  void stream_span(const Span& s, std::vector<StreamPixel>& out) const;
  std::vector<StreamPixel> stream(const std::vector<Span>& spans) const;

  // Registers as the device latches them: each field cut to its register width
  // (unsigned fields masked, angles sign-extended from angle_bits).
  Registers latch(const Registers& r) const;

 private:
  // One read of ROM 12 (multiplier 11, the address, the interpolation); cosk 0 past the domain.
  struct Read {
    uint64_t zeta = 0, addr = 0;
    uint32_t frac = 0, word = 0, cosk = 0;
    bool overflow = false;
  };
  Read read_cos(int bank, uint32_t coef, uint64_t abs_psi_t) const;
  // Multiplier 13: c * cosk rounded half up back to the format of C.
  uint32_t mul13(uint32_t c, uint32_t cosk) const;
  void check() const;
  Format f_;
  std::vector<uint32_t> coef_rom_, cos_rom_;
  BlendRoms blend_;
};

}  // namespace specular::device
