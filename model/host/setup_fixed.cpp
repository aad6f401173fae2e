// SPDX-License-Identifier: Apache-2.0
// The fixed-point scanline setup, docs/setup_hw.md (the steps are listed in setup_fixed.hpp).
#include "setup_fixed.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace specular::host::fixed {

namespace {

constexpr int64_t one(int frac) { return int64_t{1} << frac; }

// Position of the highest set bit + 1 of a non-negative 128-bit value (0 for 0).
int bit_width128(i128 x) {
  const auto u = static_cast<u128>(x);
  const auto hi = static_cast<uint64_t>(u >> 64), lo = static_cast<uint64_t>(u);
  return hi != 0 ? 64 + std::bit_width(hi) : std::bit_width(lo);
}

// floor(sqrt(x)), exact.
uint64_t isqrt(uint64_t x) {
  uint64_t r = static_cast<uint64_t>(std::sqrt(static_cast<long double>(x)));
  while (r > 0 && static_cast<u128>(r) * r > x) --r;
  while (static_cast<u128>(r + 1) * (r + 1) <= x) ++r;
  return r;
}

int64_t round_ld(long double v) { return static_cast<int64_t>(std::llround(v)); }

// The exact product of two codes. Every product of the datapath is below 2^96 in magnitude
// (docs/setup_hw.md#datapath; log2, exp2, A and dpsi below 2^63: the RTL's 64-bit products).
i128 prod(i128 a, i128 b) {
  const i128 p = a * b;
  if (p >= (i128{1} << 96) || p <= -(i128{1} << 96)) throw std::logic_error("setup_fixed: a product beyond 96 bits");
  return p;
}

}  // namespace

// ---- Tables ----

const std::vector<uint32_t>& rsqrt_seed_table() {
  // Word a - 1024: round(2^16 / sqrt((a + 1/2) / 4096)) = round(sqrt(2^45 / (2a + 1))).
  static_assert(kRsqrtAddrBits == 12 && kRsqrtSeedFrac == 16, "the seed formula below is for 12 address bits, Q16");
  static const std::vector<uint32_t> t = [] {
    std::vector<uint32_t> v;
    for (uint64_t a = 1u << (kRsqrtAddrBits - 2); a < (1u << kRsqrtAddrBits); ++a)
      v.push_back(static_cast<uint32_t>((isqrt((uint64_t{1} << 47) / (2 * a + 1)) + 1) >> 1));
    return v;
  }();
  return t;
}

const std::vector<int64_t>& atan_table() {
  static const std::vector<int64_t> t = [] {
    std::vector<int64_t> v;
    for (int i = 0; i < kCordicIters; ++i) v.push_back(round_ld(std::ldexp(std::atan(std::ldexp(1.0L, -i)), kCordicFrac)));
    return v;
  }();
  return t;
}

int64_t cordic_inv_gain() {
  static const int64_t g = [] {
    long double k = 1.0L;
    for (int i = 0; i < kCordicIters; ++i) k *= std::sqrt(1.0L + std::ldexp(1.0L, -2 * i));
    return round_ld(std::ldexp(1.0L / k, kGainFrac));
  }();
  return g;
}

const std::vector<uint32_t>& log_recip_table() {
  // round(2^12 / (1 + (i + 1/2) / 1024)) = round(2^23 / (2049 + 2i)).
  static const std::vector<uint32_t> t = [] {
    std::vector<uint32_t> v;
    for (uint32_t i = 0; i < (1u << kLogAddrBits); ++i)
      v.push_back((((uint32_t{1} << (kLogRecipFrac + kLogAddrBits + 2)) / ((2u << kLogAddrBits) + 1 + 2 * i)) + 1) >> 1);
    return v;
  }();
  return t;
}

const std::vector<int64_t>& log_value_table() {
  static const std::vector<int64_t> t = [] {
    std::vector<int64_t> v;
    for (uint32_t r : log_recip_table())
      v.push_back(round_ld(std::ldexp(-std::log2(std::ldexp(static_cast<long double>(r), -kLogRecipFrac)), kLogFrac)));
    return v;
  }();
  return t;
}

const std::vector<int64_t>& exp2_table() {
  static const std::vector<int64_t> t = [] {
    std::vector<int64_t> v;
    for (int i = 0; i < (1 << kLogAddrBits); ++i)
      v.push_back(round_ld(std::ldexp(std::exp2(std::ldexp(static_cast<long double>(i), -kLogAddrBits)), kLogFrac)));
    return v;
  }();
  return t;
}

int recip_len_shift(uint32_t len) { return len == 0 ? 0 : std::bit_width(len) - 1; }

const std::vector<uint64_t>& recip_len_table() {
  // Word l: round(2^(31 + s) / l) in [2^30, 2^31], s = floor(log2 l): a mantissa of 1/l with
  // the same relative precision for every l.
  static const std::vector<uint64_t> t = [] {
    std::vector<uint64_t> v{0};
    for (uint64_t l = 1; l <= static_cast<uint64_t>(kMaxLen); ++l)
      v.push_back(((uint64_t{1} << (kRecipLenFrac + recip_len_shift(static_cast<uint32_t>(l)) + 1)) / l + 1) >> 1);
    return v;
  }();
  return t;
}

int64_t cordic_pi() { return round_ld(std::ldexp(std::numbers::pi_v<long double>, kCordicFrac)); }

const PolyConsts& poly_consts() {
  static const PolyConsts c = [] {
    const long double ln2 = std::numbers::ln2_v<long double>;
    auto q = [](long double v) { return round_ld(std::ldexp(v, kLogFrac)); };
    return PolyConsts{q(1.0L / ln2), q(-1.0L / (2.0L * ln2)), q(1.0L / (3.0L * ln2)),
                      q(ln2), q(ln2 * ln2 / 2.0L), q(ln2 * ln2 * ln2 / 6.0L)};
  }();
  return c;
}

// ---- Primitives ----

int64_t rsqrt_norm(uint64_t m) {
  const int shift = kRsqrtInBits - kRsqrtAddrBits;
  const uint64_t addr = m >> shift;
  const uint64_t base = uint64_t{1} << (kRsqrtAddrBits - 2);
  if (addr < base || addr >= (uint64_t{1} << kRsqrtAddrBits)) throw std::logic_error("rsqrt_norm: radicand not normalized");
  i128 r = static_cast<i128>(rsqrt_seed_table()[addr - base]) << (kRsqrtFrac - kRsqrtSeedFrac);
  for (int s = 0; s < kRsqrtSteps; ++s) {
    const i128 t = rshift_round(prod(r, r), kRsqrtFrac);                      // R^2
    const i128 p = rshift_round(prod(static_cast<i128>(m), t), kRsqrtInBits); // M R^2
    const i128 e = (i128{3} << kRsqrtFrac) - p;                               // 3 - M R^2
    r = rshift_round(prod(r, e), kRsqrtFrac + 1);                             // R (3 - M R^2) / 2
  }
  return static_cast<int64_t>(r);
}

Vec normalize(const Vec& v) {
  i128 sq = 0;
  for (int64_t c : v) sq += prod(c, c);
  if (sq == 0) return {0, 0, 0};
  // m = sq 4^k in [2^44, 2^46); 1/sqrt(sq) = 2^k r 2^-67, so u = v r 2^(k - 23) in Q44.
  const int k = static_cast<int>(std::floor((kRsqrtInBits - bit_width128(sq)) / 2.0));
  const auto m = static_cast<uint64_t>(k >= 0 ? sq << (2 * k) : sq >> (-2 * k));
  const i128 r = rsqrt_norm(m);
  const int s = kRsqrtInBits / 2 + kRsqrtFrac - kUnitFrac - k;  // 23 - k
  Vec u{};
  for (int i = 0; i < 3; ++i) u[static_cast<size_t>(i)] = static_cast<int64_t>(rshift_round(prod(v[static_cast<size_t>(i)], r), s));
  return u;
}

int64_t dot(const Vec& a, const Vec& b) {
  i128 s = 0;
  for (size_t i = 0; i < 3; ++i) s += prod(a[i], b[i]);
  return static_cast<int64_t>(rshift_round(s, kUnitFrac));
}

Vec reflect(const Vec& v, const Vec& u) {
  const i128 s = dot(v, u);
  Vec out{};
  for (size_t i = 0; i < 3; ++i) out[i] = v[i] - static_cast<int64_t>(rshift_round(prod(s, u[i]), kUnitFrac - 1));
  return out;
}

Polar cordic_vectoring(int64_t x, int64_t y) {
  int64_t z = 0;
  if (x < 0) {  // a half turn into the right half plane
    z = y >= 0 ? cordic_pi() : -cordic_pi();
    x = -x, y = -y;
  }
  const auto& at = atan_table();
  for (int i = 0; i < kCordicIters; ++i) {
    const int64_t dx = y >> i, dy = x >> i;
    if (y >= 0) {
      x += dx, y -= dy, z += at[static_cast<size_t>(i)];
    } else {
      x -= dx, y += dy, z -= at[static_cast<size_t>(i)];
    }
  }
  return {z, x};
}

int64_t log2_unit(int64_t a) {
  if (a <= 0) throw std::logic_error("log2_unit: non-positive argument");
  const int p = std::bit_width(static_cast<uint64_t>(a)) - 1;
  const int64_t mant = p <= kUnitFrac ? a << (kUnitFrac - p) : a >> (p - kUnitFrac);  // [2^44, 2^45)
  const auto idx = static_cast<size_t>((mant >> (kUnitFrac - kLogAddrBits)) & ((1 << kLogAddrBits) - 1));
  const i128 eps = prod(mant, log_recip_table()[idx]) - (i128{1} << (kUnitFrac + kLogRecipFrac));
  const i128 e = rshift_round(eps, kUnitFrac + kLogRecipFrac - kLogFrac);  // Q30, |e| < 2^-10
  const PolyConsts& c = poly_consts();
  i128 t = c.l3;
  t = c.l2 + rshift_round(prod(e, t), kLogFrac);
  t = c.l1 + rshift_round(prod(e, t), kLogFrac);
  const i128 poly = rshift_round(prod(e, t), kLogFrac);
  return static_cast<int64_t>((p - kUnitFrac) * one(kLogFrac) + log_value_table()[idx] + poly);
}

uint32_t scale_exp2(uint32_t code, int64_t e, uint32_t max_code, bool* saturated) {
  if (saturated) *saturated = false;
  if (code == 0) return 0;
  const int64_t ei = e >> kLogFrac;  // floor
  if (ei < -(kLogFrac + 1)) return 0;  // code 2^e < 2^16 2^-41: rounds to 0
  if (ei > 16) {                       // code 2^e >= 2^17 > every max_code of a 16-bit C
    if (saturated) *saturated = true;
    return max_code;
  }
  const int64_t f = e - ei * one(kLogFrac);  // [0, 2^30)
  const int lo_bits = kLogFrac - kLogAddrBits;
  const auto j = static_cast<size_t>(f >> lo_bits);
  const i128 fl = f & (one(lo_bits) - 1);  // Q30, < 2^-10
  const PolyConsts& c = poly_consts();
  i128 t = c.e3;
  t = c.e2 + rshift_round(prod(fl, t), kLogFrac);
  t = c.e1 + rshift_round(prod(fl, t), kLogFrac);
  const i128 p = one(kLogFrac) + rshift_round(prod(fl, t), kLogFrac);
  const i128 mant = rshift_round(prod(exp2_table()[j], p), kLogFrac);  // Q30 in [1, 2)
  const i128 v = rshift_round(prod(mant, code), kLogFrac - static_cast<int>(ei));
  if (v > max_code) {
    if (saturated) *saturated = true;
    return max_code;
  }
  return static_cast<uint32_t>(v);
}

// ---- The setup ----

void check_geo_span(const device::GeoSpan& g, const device::GeoFormat& gf, const device::Format& f, const char* who) {
  const std::string w = std::string(who) + ": ";
  auto require = [&w](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument(w + what);
  };
  const device::Format def;
  require(gf.vec_bits >= 2 && gf.vec_bits <= 24, "vec_bits must be in 2..24, got " + std::to_string(gf.vec_bits));
  require(f.c_bits == def.c_bits && f.angle_bits == def.angle_bits && f.angle_frac == def.angle_frac &&
              f.n_bits == def.n_bits && f.len_bits == def.len_bits,
          "the register formats must be device::Format{}'s (C 16 bits, angles 32/28, n 10, l 11)");
  require(g.n < (1u << f.n_bits), "n code " + std::to_string(g.n) + " outside 0.." + std::to_string((1u << f.n_bits) - 1));
  require(g.len <= static_cast<uint32_t>(f.max_len()), "len " + std::to_string(g.len) + " outside 0.." + std::to_string(f.max_len()));
  require(g.scale < (1u << f.c_bits), "scale code " + std::to_string(g.scale) + " outside 0.." + std::to_string((1u << f.c_bits) - 1));
  for (const auto* v : {&g.n1, &g.n2, &g.h1, &g.he})
    for (int32_t c : *v)
      require(c >= gf.vec_min() && c <= gf.vec_max(), "vector component " + std::to_string(c) + " outside " +
                                                          std::to_string(gf.vec_min()) + ".." + std::to_string(gf.vec_max()));
}

std::optional<SetupStatus> decode_codes(const device::GeoSpan& g) {
  auto zero = [](const device::GeoVec& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; };
  if (g.n == 0 || g.n > static_cast<uint32_t>(kMaxN) || zero(g.n1) || zero(g.n2)) return SetupStatus::invalid_input;
  if (zero(g.h1) || zero(g.he)) return SetupStatus::undefined_halfway;
  return std::nullopt;
}

Result setup_fixed(const device::GeoSpan& g, const device::GeoFormat& gf, const device::Format& f) {
  check_geo_span(g, gf, f, "setup_fixed");
  Result r;
  r.span.tag = g.tag;
  r.span.reg.n = g.n;
  r.span.reg.len = g.len;
  // 1. Decode.
  if (const auto st = decode_codes(g)) {
    r.status = *st;
    return r;
  }
  auto widen = [](const device::GeoVec& v) { return Vec{v[0], v[1], v[2]}; };
  const Vec c1 = widen(g.n1), c2 = widen(g.n2);
  const bool parallel = c1[1] * c2[2] - c1[2] * c2[1] == 0 && c1[2] * c2[0] - c1[0] * c2[2] == 0 &&
                        c1[0] * c2[1] - c1[1] * c2[0] == 0;
  Trace& t = r.trace;
  t.opposite_normals = parallel && c1[0] * c2[0] + c1[1] * c2[1] + c1[2] * c2[2] < 0;

  // 2. Unit vectors.
  t.unit = {normalize(c1), normalize(c2), normalize(widen(g.h1)), normalize(widen(g.he))};
  const Vec &n1 = t.unit[0], &n2 = t.unit[1], &h1 = t.unit[2], &he = t.unit[3];

  // 3. H2: the rotation taking N2 to N1 as two reflections.
  Vec y = he;
  if (!t.opposite_normals) y = reflect(he, normalize(Vec{n1[0] + n2[0], n1[1] + n2[1], n1[2] + n2[2]}));
  t.h2 = reflect(y, n1);

  // 4. Cosines, the flat and opposite-halfway tests, W.
  t.cos_t1 = dot(n1, h1);
  t.x = dot(h1, t.h2);
  bool flat = true, opp = true;
  for (size_t i = 0; i < 3; ++i) {
    flat = flat && std::abs(t.h2[i] - h1[i]) <= kChordFloor;
    opp = opp && std::abs(t.h2[i] + h1[i]) <= kChordFloor;
  }
  t.flat = flat;
  t.opposite_halfway = !flat && opp;
  Vec w{};
  for (size_t i = 0; i < 3; ++i)
    w[i] = t.opposite_halfway ? n1[i] - static_cast<int64_t>(rshift_round(prod(t.cos_t1, h1[i]), kUnitFrac))
                              : t.h2[i] - static_cast<int64_t>(rshift_round(prod(t.x, h1[i]), kUnitFrac));

  // 5. u = W / |W|.
  const Vec u = normalize(w);
  t.w_len = dot(u, w);
  t.nu = flat ? 0 : dot(n1, u);

  // 6. The angles and the amplitude.
  const int up = kCordicFrac - kUnitFrac;
  if (flat) {
    t.gamma = 0;
  } else if (t.opposite_halfway) {
    t.gamma = cordic_pi();
  } else {
    t.gamma = std::clamp(cordic_vectoring(t.x * one(up), t.w_len * one(up)).angle, int64_t{0}, cordic_pi());
  }
  const Polar p = cordic_vectoring(t.cos_t1 * one(up), t.nu * one(up));
  t.lambda = p.angle;
  // A = (A K) (1/K): A K rounded to Q30 first, the product (below 2^62) rounded to Q44.
  t.a = static_cast<int64_t>(rshift_round(prod(rshift_round(p.mag_k, kCordicFrac - kGainFrac), cordic_inv_gain()),
                                          2 * kGainFrac - kUnitFrac));

  // 7. The registers.
  r.span.reg.psi0 = static_cast<int64_t>(rshift_round(-static_cast<i128>(t.lambda), kCordicFrac - f.angle_frac));
  r.span.reg.dpsi = g.len == 0 ? 0
                               : static_cast<int64_t>(rshift_round(prod(rshift_round(t.gamma, kCordicFrac - kGammaFrac),
                                                                        static_cast<i128>(recip_len_table()[g.len])),
                                                                   kGammaFrac + kRecipLenFrac + recip_len_shift(g.len) - f.angle_frac));
  if (t.a > 0) {
    t.log2_a = log2_unit(t.a);
    r.span.reg.c = scale_exp2(g.scale, static_cast<int64_t>(g.n) * t.log2_a, (1u << f.c_bits) - 1, &r.c_saturated);
  }
  if (t.opposite_halfway) r.status = SetupStatus::opposite_halfway;
  else if (t.opposite_normals) r.status = SetupStatus::opposite_normals;
  return r;
}

}  // namespace specular::host::fixed
