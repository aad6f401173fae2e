// SPDX-License-Identifier: Apache-2.0
// Bit-accurate golden model of phong_stream, the per-pixel Blinn-Phong competitor core on the
// geometry span interface (docs/interfaces.md#geometry-span-interface, docs/phong_hw.md).
//
// One definition of every width and rounding rule of the core. Pixel i of a span is
//   I_i = scale * max(0, N_i . H_i / (|N_i| |H_i|))^n,
//   N_i = N1 + (N2 - N1) i / l,  H_i = H1 + (He - H1) i / l   (N1, H1 when l = 0),
// the reference phong_truth(geo_input(span), i) of model/setup/scanline_setup.hpp.
//
// Per span (no division: the cosine does not change when N_i or H_i is scaled, so the core
// interpolates l * 2^k * N_i, which is exact in integers):
//   k      = len_bits - bit_width(l) (l >= 1), so L = l << k is in [2^(len_bits-1), 2^len_bits);
//            l = 0: L = 2^(len_bits-1), steps 0
//   A_0    = L * N1,  step EA = (N2 - N1) << k        (per component; the multiplier is
//   B_0    = L * H1,  step EB = (He - H1) << k         len_bits x vec_bits, per span)
//            constant H (const_h): B = H1 << (len_bits - 1) for every pixel, He unused
// Per pixel (acc_bits = vec_bits + len_bits; A_i = A_0 + i EA exactly, an accumulator that
// cannot overflow: A_i = 2^k ((l - i) N1 + i N2) is a convex combination of L N1 and L N2):
//   a, b   = A_i >> (acc_bits - op_bits), B_i >> (same)      signed op_bits (floor)
//   d      = a . b,  na = a . a,  nb = b . b                   exact (three op_bits^2 products each)
//   d <= 0 -> pixel 0 (N.H <= 0, or N_i or H_i is the zero vector); a zero N1, N2, H1 or He
//   (He: unless const_h) zeroes every pixel of the span (a per-span flag)
//   ea, eb = the even numbers with na / 2^ea, nb / 2^eb in [1, 4)
//   ma, mb = floor(na * 2^(norm_bits-2-ea)), same for nb    norm_bits unsigned, norm_bits-2 fraction bits
//   m      = ma * mb; em = 1 if m >= 4 (value) else 0
//   mm     = m >> (norm_bits - 2 + 2 em)                     norm_bits, [1, 4), norm_bits-2 fraction bits
//   y0     = rsqrt ROM[(mm >> (norm_bits - rsqrt_addr_bits)) - 2^(rsqrt_addr_bits-2)]
//            word j = round(2^norm_bits / sqrt(x_j)), x_j the middle of segment j of [1, 4)
//            (3 * 2^(rsqrt_addr_bits-2) words of norm_bits, norm_bits fraction bits)
//   Newton, `newton` times (each step truncates):
//            t = y*y >> norm_bits;  u = mm*t >> (norm_bits-2);  y = y*((3 << norm_bits) - u) >> (norm_bits+1)
//   K      = ea/2 + eb/2 + em;  dn = floor(d * 2^(cos_frac - K))          (d / sqrt(na nb) = dn y / 2^...)
//   c      = min((dn * y) >> norm_bits, 2^cos_frac)          cos_frac fraction bits, (0, 1]; 0 -> pixel 0
//   log2:  c = 2^-e * mant, mant in [1, 2) (cos_frac fraction bits; c = 1: w = 0)
//          j = the log_addr_bits fraction bits of mant below the point, t = the next log_frac_bits
//          word j = {v, dv}: v = round(log2(1 + j 2^-log_addr_bits) * 2^log_bits), dv = v(j+1) - v(j)
//          (v(2^log_addr_bits) = 2^log_bits; dv has log_delta_bits())
//          w = (e << log_bits) - (v + ((dv * t + 2^(log_frac_bits-1)) >> log_frac_bits))   = -log2 c
//   z      = n * w                                           log_bits fraction bits
//   exp2:  zi = z >> log_bits, zf = the rest; zi > exp_bits -> pixel 0
//          j = the top exp_addr_bits bits of zf, t = the next exp_frac_bits
//          word j = {u, du}: u = round(2^(-j 2^-exp_addr_bits) * 2^exp_bits) (exp_bits + 1 bits),
//          du = u(j) - u(j+1) (u(2^exp_addr_bits) = 2^(exp_bits-1); du has exp_delta_bits())
//          p = (u - ((du * t + 2^(exp_frac_bits-1)) >> exp_frac_bits)) >> zi     = 2^-z, exp_bits fraction bits
//   out    = (scale * p + 2^(exp_bits-1)) >> exp_bits        the format of C (c_bits, c_frac)
//   n = 0 or n > 1000: every pixel 0.
//
// The cancellation-free form (form = PhongForm::cross, docs/phong_hw.md#the-cancellation-free-form):
// the same a, b, d, na, nb, ea, eb, em, mm and the same z = n w and exp2 stage; w = -log2 c
// comes from sin^2 = |a x b|^2 / (|a|^2 |b|^2) near the peak and from cos^2 = d^2 / (|a|^2 |b|^2)
// elsewhere, with no square root and no subtraction of nearly equal numbers:
//   a, b   as above but from the span's own range and rounded: hn = vec_bits - 1 - the widest
//          |component| of N1 and N2 (bits), hb the same of H1 and He (H1 alone when const_h);
//          a = (A_i + 2^(drop-hn-1)) >> (drop - hn), drop = acc_bits - op_bits; b likewise with hb
//   u      = a x b                                        exact (six op_bits^2 products)
//   K      as above: na nb = (mm / 2^(norm_bits-2)) 4^K
//   r      = 1/mm from the interpolated reciprocal ROM     rcp_bits fraction bits, (1/4, 1]
//            word j = {v, dv}: v = round(2^rcp_bits / x_j), x_j = 1 + j 2^-(rcp_addr_bits-2) on [1, 4),
//            dv = v(j) - v(j+1); t = the rcp_frac_bits bits of mm below the address;
//            r = v - ((dv * t + 2^(rcp_frac_bits-1)) >> rcp_frac_bits)
//   q      = u_bits - 2; u'_c = u_c >> (K - q), d' = d >> (K - q)   (floor; |u'|, |d'| < 2^(q+1))
//   su     = |u'|^2, sd = d'^2                            exact; su <= sd (s <= 1/2): the sine branch
//   sine:  s = min((su * r) >> (2q + rcp_bits - s_frac), 2^(s_frac-1))   sin^2, s_frac fraction bits
//          word j of the g ROM = {v, dv}: v = round(g(x_j) 2^g_bits), g(x) = -log2(1 - x) / (2x)
//          (g(0) = 1 / (2 ln 2)), x_j = j 2^-(g_addr_bits+1) on [0, 1/2), dv = v(j+1) - v(j);
//          j, t = the g_addr_bits and g_frac_bits bits of s below its 2^-1 bit;
//          gv = v + ((dv * t + 2^(g_frac_bits-1)) >> g_frac_bits);
//          w  = (s * gv) >> (s_frac + g_bits - log_bits)                 = -log2(1 - s) / 2
//   cosine: ed = bit_width(d) - 1; dm = d >> (ed - dm_frac) (floor; [1, 2), dm_frac fraction bits)
//          P = dm^2 * r (2 dm_frac + rcp_bits fraction bits, [1/4, 4)); ep = floor(log2 P) in -2..1;
//          mant = P / 2^ep in [1, 2), its top cos_frac fraction bits -> the log2 ROM as above
//          (j, t, v, dv, lg = log2 mant with log_bits fraction bits);
//          w = max(0, ((2 (K - ed) - ep) << log_bits) - lg) >> 1        = -log2(cos^2) / 2
//   the rsqrt ROM, newton and norm-to-cos steps are not used.
#pragma once

#include "device_model.hpp"
#include "geo_span.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace specular::device {

// The default is the narrowest configuration found for n in 1..1000 at the device's budget
// (docs/phong_hw.md#configuration-search); the named presets are the others found there.
// How the cosine reaches the power (the header comment): the textbook normalized dot product, or
// the cancellation-free sine / cosine squares.
enum class PhongForm { dot, cross };

struct PhongFormat {
  PhongForm form = PhongForm::dot;
  int vec_bits = 18, vec_frac = 16;  // the geometry span interface (GeoFormat)
  int n_bits = 10, len_bits = 11;    // geo_n_i, geo_len_i
  int c_bits = 16, c_frac = 15;      // geo_scale_i and px_intensity_o: the format of C
  int tag_bits = 16;                 // geo_tag_i, px_tag_o
  bool const_h = false;              // constant H: He is not read, H is not interpolated
  int op_bits = 20;                  // interpolated vector components at the dot products (signed)
  int norm_bits = 24;                // mantissas of |a|^2, |b|^2, their product and 1/sqrt
  int rsqrt_addr_bits = 6;           // rsqrt ROM: 3 * 2^(rsqrt_addr_bits-2) words
  int newton = 2;                    // Newton-Raphson steps after the rsqrt ROM (0..2)
  int cos_frac = 23;                 // fraction bits of the normalized cosine c
  int log_addr_bits = 9;             // log2 ROM: 2^log_addr_bits words {v, dv}
  int log_frac_bits = 13;            // bits of mant that weight the step
  int log_bits = 21;                 // fraction bits of -log2 c and of z = n * w
  int exp_addr_bits = 5;             // exp2 ROM: 2^exp_addr_bits words {u, du}
  int exp_frac_bits = 7;             // bits of zf that weight the step
  int exp_bits = 16;                 // fraction bits of p = 2^-z
  // The cross form only (PhongForm::cross; cos_frac is then the mantissa bits read by the log2 ROM).
  int u_bits = 18;                   // signed width of the scaled cross product u' and of d'
  int rcp_addr_bits = 6;             // reciprocal ROM: 3 * 2^(rcp_addr_bits-2) words {v, dv}
  int rcp_frac_bits = 8;             // bits of mm that weight the step
  int rcp_bits = 17;                 // fraction bits of r = 1/mm
  int s_frac = 22;                   // fraction bits of s = sin^2
  int g_addr_bits = 5;               // g ROM: 2^g_addr_bits words {v, dv} over s in [0, 1/2)
  int g_frac_bits = 8;               // bits of s that weight the step
  int g_bits = 17;                   // fraction bits of g(s)
  int dm_frac = 14;                  // fraction bits of the mantissa of d (cosine branch)

  // The narrowest configuration found for n in 1..n_max, n_max = 64, 128 or 1000 (the
  // default-constructed format is preset(1000)); throws std::invalid_argument otherwise.
  static PhongFormat preset(int n_max);
  // The cross form's configuration for n in 1..1000 at the device's budget: operands of one
  // 18 x 18 DSP tile (docs/phong_hw.md#the-cancellation-free-form).
  static PhongFormat cross();
  // The narrowest configuration of a form for n in 1..1000 at budget "b1", "b2", "b3" or "b4"
  // (docs/metrics.md#budgets; phong_search --form F --budget B, docs/phong_hw.md#budgets):
  // b1 is preset(1000) or cross(); throws std::invalid_argument otherwise.
  static PhongFormat at_budget(PhongForm form, const std::string& budget);

  int acc_bits() const { return vec_bits + len_bits; }
  int max_len() const { return (1 << len_bits) - 1; }
  int rsqrt_depth() const { return 3 << (rsqrt_addr_bits - 2); }
  int log_depth() const { return 1 << log_addr_bits; }
  int exp_depth() const { return 1 << exp_addr_bits; }
  int log_delta_bits() const { return log_bits - log_addr_bits + 1; }
  int exp_delta_bits() const { return exp_bits - exp_addr_bits; }
  int log_word_bits() const { return log_bits + log_delta_bits(); }
  int exp_word_bits() const { return exp_bits + 1 + exp_delta_bits(); }
  int rcp_depth() const { return 3 << (rcp_addr_bits - 2); }
  int g_depth() const { return 1 << g_addr_bits; }
  int rcp_delta_bits() const { return rcp_bits - rcp_addr_bits + 3; }  // the first step, rounded, can reach 2^(rcp_bits-rcp_addr_bits+2)
  int g_delta_bits() const { return g_bits - g_addr_bits; }
  // Bits of the largest w = -log2 c (c >= 2^-cos_frac): cos_frac + 1 integer values.
  int w_bits() const;
  // Throws std::invalid_argument naming the field and its allowed range.
  void validate() const;
  std::string describe() const;
  bool operator==(const PhongFormat&) const = default;
};

// A named configuration of phong_stream: the presets, their constant-H variants and the
// configurations per budget, by the names of roms/phong/phong_configs.cmake (phong_romgen
// writes it from this list; phong_search --measure reads it). budget: the one it is built for.
struct PhongConfig {
  std::string name;
  PhongFormat f;
  std::string budget;
};
const std::vector<PhongConfig>& phong_configs();

// The geometry interface's format that a PhongFormat reads.
GeoFormat geo_format(const PhongFormat& f);
// The device Format fields the reference conversions use (c_bits, c_frac, n_bits, len_bits).
Format c_format(const PhongFormat& f);

// ROM images (one word per entry, the layouts of the header comment; log and exp words
// packed {v, dv} and {u, du} with the step in the low bits).
std::vector<uint64_t> phong_rsqrt_rom(const PhongFormat& f);
std::vector<uint64_t> phong_log_rom(const PhongFormat& f);
std::vector<uint64_t> phong_exp_rom(const PhongFormat& f);
// The cross form's ROMs ({v, dv} words, the step in the low bits).
std::vector<uint64_t> phong_rcp_rom(const PhongFormat& f);
std::vector<uint64_t> phong_g_rom(const PhongFormat& f);

// Every intermediate of one pixel (fields after the one that zeroed the pixel keep 0).
struct PhongTrace {
  int64_t a[3]{}, b[3]{};  // operands
  int64_t d = 0;
  uint64_t na = 0, nb = 0;
  int ea = 0, eb = 0, em = 0;
  uint64_t ma = 0, mb = 0, mm = 0;
  uint64_t y0 = 0, y = 0;
  uint64_t dn = 0, c = 0;
  int e = 0;
  uint64_t w = 0, z = 0;
  uint64_t p = 0;
  uint32_t intensity = 0;
  // The cross form.
  int64_t u[3]{};
  uint64_t r = 0, su = 0, sd = 0, s = 0, gv = 0;
  bool sine = false;
};

class PhongModel {
 public:
  explicit PhongModel(PhongFormat f);
  const PhongFormat& format() const { return f_; }
  PhongTrace trace(const GeoSpan& s, int i) const;
  uint32_t pixel(const GeoSpan& s, int i) const { return trace(s, i).intensity; }
  // The pixels of one span (l + 1 of them, tag and last as specular_stream's pixel side).
  void stream_span(const GeoSpan& s, std::vector<StreamPixel>& out) const;
  std::vector<StreamPixel> stream(const std::vector<GeoSpan>& spans) const;
  // The span as the core latches it: every field cut to its port width.
  GeoSpan latch(const GeoSpan& s) const;

 private:
  PhongFormat f_;
  std::vector<uint64_t> rsqrt_, log_, exp_, rcp_, g_;
};

}  // namespace specular::device
