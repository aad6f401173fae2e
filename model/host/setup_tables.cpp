// SPDX-License-Identifier: Apache-2.0
// The setup's tables and shared primitives (setup_tables.hpp).
#include "setup_tables.hpp"

#include <bit>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace specular::host::fixed {

namespace {

constexpr int64_t one(int frac) { return int64_t{1} << frac; }

int64_t round_ld(long double v) { return static_cast<int64_t>(std::llround(v)); }

// The exact product of two codes; the table arithmetic stays below 2^96 in magnitude.
i128 prod(i128 a, i128 b) {
  const i128 p = a * b;
  if (p >= (i128{1} << 96) || p <= -(i128{1} << 96)) throw std::logic_error("setup_tables: a product beyond 96 bits");
  return p;
}

}  // namespace

// ---- Tables ----

const std::vector<int64_t>& atan_table() {
  static const std::vector<int64_t> t = [] {
    std::vector<int64_t> v;
    for (int i = 0; i < kAtanIters; ++i) v.push_back(round_ld(std::ldexp(std::atan(std::ldexp(1.0L, -i)), kAtanFrac)));
    return v;
  }();
  return t;
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

int64_t atan_pi() { return round_ld(std::ldexp(std::numbers::pi_v<long double>, kAtanFrac)); }

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

int64_t log2_unit(int64_t a) {
  if (a <= 0) throw std::logic_error("log2_unit: non-positive argument");
  const int p = std::bit_width(static_cast<uint64_t>(a)) - 1;
  const int64_t mant = p <= kLogUnitFrac ? a << (kLogUnitFrac - p) : a >> (p - kLogUnitFrac);  // [2^44, 2^45)
  const auto idx = static_cast<size_t>((mant >> (kLogUnitFrac - kLogAddrBits)) & ((1 << kLogAddrBits) - 1));
  const i128 eps = prod(mant, log_recip_table()[idx]) - (i128{1} << (kLogUnitFrac + kLogRecipFrac));
  const i128 e = rshift_round(eps, kLogUnitFrac + kLogRecipFrac - kLogFrac);  // Q30, |e| < 2^-10
  const PolyConsts& c = poly_consts();
  i128 t = c.l3;
  t = c.l2 + rshift_round(prod(e, t), kLogFrac);
  t = c.l1 + rshift_round(prod(e, t), kLogFrac);
  const i128 poly = rshift_round(prod(e, t), kLogFrac);
  return static_cast<int64_t>((p - kLogUnitFrac) * one(kLogFrac) + log_value_table()[idx] + poly);
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

// ---- Checks and decode ----

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

}  // namespace specular::host::fixed
