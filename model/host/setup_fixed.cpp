// SPDX-License-Identifier: Apache-2.0
// The fixed-point scanline setup, docs/setup_hw.md#the-datapath (the steps are listed in
// setup_fixed.hpp).
#include "setup_fixed.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

namespace specular::host::fixed {

namespace {



int bit_width128(i128 x) {
  const auto u = static_cast<u128>(x < 0 ? -x : x);
  const auto hi = static_cast<uint64_t>(u >> 64), lo = static_cast<uint64_t>(u);
  return hi != 0 ? 64 + std::bit_width(hi) : std::bit_width(lo);
}

i128 abs128(i128 x) { return x < 0 ? -x : x; }

// Block normalization of any number of components (docs/setup_hw.md#the-datapath).
int block_normalize_span(std::span<i128> v, int bits) {
  i128 mx = 0;
  for (i128 c : v) mx = std::max(mx, abs128(c));
  if (mx == 0) return 0;
  const int shift = bit_width128(mx) - bits;
  for (i128& c : v) c = rshift_round(c, shift);
  return shift;
}

std::array<i128, 3> wide(const Vec& v) { return {v[0], v[1], v[2]}; }
Vec narrow(const std::array<i128, 3>& v) {
  return {static_cast<int64_t>(v[0]), static_cast<int64_t>(v[1]), static_cast<int64_t>(v[2])};
}
i128 dot3(const Vec& a, const Vec& b) {
  return static_cast<i128>(a[0]) * b[0] + static_cast<i128>(a[1]) * b[1] + static_cast<i128>(a[2]) * b[2];
}
std::array<i128, 3> cross3(const Vec& a, const Vec& b) {
  return {static_cast<i128>(a[1]) * b[2] - static_cast<i128>(a[2]) * b[1],
          static_cast<i128>(a[2]) * b[0] - static_cast<i128>(a[0]) * b[2],
          static_cast<i128>(a[0]) * b[1] - static_cast<i128>(a[1]) * b[0]};
}

// C = scale 2^((n/2) log2 A^2) from trace.a2 (Q(2F)); 0 when A = 0.
void set_amplitude(const device::GeoSpan& g, const device::Format& f, const Widths& w, Result& r) {
  Trace& t = r.trace;
  if (t.a2 <= 0) return;
  // log2_unit reads its argument as Q44.
  t.log2_a2 = log2_unit(t.a2) - (2 * w.frac - kLogUnitFrac) * (int64_t{1} << kLogFrac);
  const auto e = static_cast<int64_t>(rshift_round(static_cast<i128>(g.n) * t.log2_a2, 1));  // (n/2) log2 A^2
  r.span.reg.c = scale_exp2(g.scale, e, (1u << f.c_bits) - 1, &r.c_saturated);
}

// The checks, the pass-through fields and the decode of both paths; true when the decode
// decided the span (its registers stay 0).
bool begin(const device::GeoSpan& g, const device::GeoFormat& gf, const device::Format& f, const Widths& w,
           const char* who, Result& r) {
  check_widths(w);
  check_geo_span(g, gf, f, who);
  r.span.tag = g.tag;
  r.span.reg.n = g.n;
  r.span.reg.len = g.len;
  const auto st = decode_codes(g);
  if (st) r.status = *st;
  return st.has_value();
}

Vec vec(const device::GeoVec& v) { return {v[0], v[1], v[2]}; }

}  // namespace

void check_widths(const Widths& w) {
  if (w.frac < 20 || w.frac > 30 || w.frac % 2 != 0)
    throw std::invalid_argument("setup_fixed: the unit width F must be even and in 20..30, got " + std::to_string(w.frac));
}

const std::vector<uint32_t>& seed_table() {
  // Word j - 128: round(2^18 / sqrt(j / 512)) = round(sqrt(2^45 / j)), j = 128..512.
  static_assert(kSeedAddrBits == 9 && kSeedFrac == 18, "the formula below is for 9 address bits and Q18 words");
  static const std::vector<uint32_t> t = [] {
    std::vector<uint32_t> v;
    for (uint64_t j = 128; j <= 512; ++j) {
      // round(sqrt(2^45 / j)) = floor(sqrt(2^47 / j) + 1) / 2, from an exact integer square root.
      const uint64_t x = (uint64_t{1} << 47) / j;
      auto r = static_cast<uint64_t>(std::sqrt(static_cast<long double>(x)));
      while (r * r > x) --r;
      while ((r + 1) * (r + 1) <= x) ++r;
      v.push_back(static_cast<uint32_t>((r + 1) >> 1));
    }
    return v;
  }();
  return t;
}

int64_t rsqrt(uint64_t m, const Widths& w) {
  const int b = w.rsqrt_in_bits(), rf = w.rsqrt_frac();
  if (m < (uint64_t{1} << (b - 2)) || m >= (uint64_t{1} << b)) throw std::logic_error("fixed::rsqrt: radicand not normalized");
  const uint64_t j = m >> (b - kSeedAddrBits);
  const auto t = static_cast<i128>((m >> (b - kSeedAddrBits - kSeedInterpBits)) & ((1u << kSeedInterpBits) - 1));
  const auto& y = seed_table();
  const i128 y0 = y[j - 128], y1 = y[j - 127];
  const i128 seed = y0 - rshift_round((y0 - y1) * t, kSeedInterpBits);  // Q18
  // One Newton-Raphson step r = s (3 - x s^2) / 2, x = m / 2^B.
  const i128 s2 = rshift_round(seed * seed, 2 * kSeedFrac - rf);      // s^2, Q(F+2)
  const i128 xs2 = rshift_round(static_cast<i128>(m) * s2, b);       // x s^2, Q(F+2)
  const i128 e = (i128{3} << rf) - xs2;                               // 3 - x s^2
  return static_cast<int64_t>(rshift_round(seed * e, kSeedFrac + 1)); // Q(F+2)
}

Vec normalize(const Vec& v, const Widths& w) {
  i128 sq = 0;
  for (int64_t c : v) sq += static_cast<i128>(c) * c;
  if (sq == 0) return {0, 0, 0};
  const int b = w.rsqrt_in_bits();
  // m = sq 4^k in [2^(B-2), 2^B); 1/sqrt(sq) = r 2^-(F+2) 2^-(B/2) 2^k.
  const int k = static_cast<int>(std::floor((b - bit_width128(sq)) / 2.0));
  const auto m = static_cast<uint64_t>(k >= 0 ? sq << (2 * k) : sq >> (-2 * k));
  const i128 r = rsqrt(m, w);
  const int s = w.rsqrt_frac() + b / 2 - k - w.frac;
  Vec u{};
  for (size_t i = 0; i < 3; ++i) u[i] = static_cast<int64_t>(rshift_round(static_cast<i128>(v[i]) * r, s));
  return u;
}

int block_normalize(std::array<i128, 3>& v, int bits) { return block_normalize_span(v, bits); }

int64_t atan_word(int i, int frac) {
  if (i < 0 || i >= kAtanIters || frac > kAtanFrac) throw std::logic_error("fixed::atan_word: outside the Q50 table");
  return static_cast<int64_t>(rshift_round(atan_table()[static_cast<size_t>(i)], kAtanFrac - frac));
}

int64_t pi_word(int frac) { return static_cast<int64_t>(rshift_round(atan_pi(), kAtanFrac - frac)); }

int64_t cordic_angle(int64_t x, int64_t y, int frac, int iters, int bits) {
  const int64_t lim = int64_t{1} << (bits - 1);
  auto fits = [lim](int64_t v) { return v >= -lim && v < lim; };
  int64_t z = 0;
  if (x < 0) {  // a half turn into the right half plane
    z = y >= 0 ? pi_word(frac) : -pi_word(frac);
    x = -x, y = -y;
  }
  for (int i = 0; i < iters; ++i) {
    const int64_t dx = y >> i, dy = x >> i, a = atan_word(i, frac);
    if (y >= 0) {
      x += dx, y -= dy, z += a;
    } else {
      x -= dx, y += dy, z -= a;
    }
    if (!fits(x) || !fits(y) || !fits(z)) throw std::logic_error("fixed::cordic_angle: a register beyond its width");
  }
  return z;
}

bool takes_flat_path(const device::GeoSpan& g) { return g.len == 0 || (g.n1 == g.n2 && g.h1 == g.he); }

Result setup_fixed_flat(const device::GeoSpan& g, const device::GeoFormat& gf, const device::Format& f, const Widths& w) {
  Result r;
  if (begin(g, gf, f, w, "setup_fixed_flat", r)) return r;
  Trace& t = r.trace;
  t.flat = true;
  t.n1 = normalize(vec(g.n1), w);
  t.h1 = normalize(vec(g.h1), w);
  t.cos_t1 = static_cast<int64_t>(rshift_round(dot3(t.n1, t.h1), w.frac));
  // cos t1 <= 0: pixel 0 is 0 whatever C; C = 0 says so without the angle pi.
  if (t.cos_t1 > 0) t.a2 = static_cast<int64_t>(static_cast<i128>(t.cos_t1) * t.cos_t1);
  set_amplitude(g, f, w, r);
  return r;
}

Result setup_fixed(const device::GeoSpan& g, const device::GeoFormat& gf, const device::Format& f, const Widths& w) {
  Result r;
  // 1. Decode.
  if (begin(g, gf, f, w, "setup_fixed", r)) return r;
  const int fr = w.frac, cf = w.cordic_frac(), bb = w.block_bits();
  Trace& t = r.trace;
  // 2. Unit N1, N2, H1.
  t.n1 = normalize(vec(g.n1), w);
  t.n2 = normalize(vec(g.n2), w);
  t.h1 = normalize(vec(g.h1), w);
  const Vec he = vec(g.he);

  // 3. G, a positive multiple of H2.
  const Vec m{t.n1[0] + t.n2[0], t.n1[1] + t.n2[1], t.n1[2] + t.n2[2]};
  const i128 q = dot3(m, m);
  t.q = static_cast<int64_t>(q);
  t.opposite_normals = q < (i128{1} << (2 * fr - kOppNormLog2));
  std::array<i128, 3> gp = wide(he);
  if (!t.opposite_normals) {
    const i128 hm = dot3(he, m);
    for (size_t i = 0; i < 3; ++i) gp[i] = q * he[i] - 2 * hm * m[i];
  }
  block_normalize(gp, bb);
  const Vec gpn = narrow(gp);
  const i128 s = rshift_round(dot3(gpn, t.n1), fr);  // G'.N1 at the scale of G'
  std::array<i128, 3> gv{};
  for (size_t i = 0; i < 3; ++i) gv[i] = gpn[i] - rshift_round(s * t.n1[i], fr - 1);
  block_normalize(gv, bb);
  t.g = narrow(gv);

  // 4. x, c, p, cos t1 and the decisions.
  std::array<i128, 4> xc{dot3(t.h1, t.g), 0, 0, 0};
  const auto c = cross3(t.h1, t.g);
  std::copy(c.begin(), c.end(), xc.begin() + 1);
  block_normalize_span(xc, bb);
  t.x = static_cast<int64_t>(xc[0]);
  t.c = {static_cast<int64_t>(xc[1]), static_cast<int64_t>(xc[2]), static_cast<int64_t>(xc[3])};
  const auto p = cross3(t.h1, t.n1);
  for (size_t i = 0; i < 3; ++i) t.p[i] = static_cast<int64_t>(rshift_round(p[i], fr));
  t.cos_t1 = static_cast<int64_t>(rshift_round(dot3(t.n1, t.h1), fr));
  const i128 cc = dot3(t.c, t.c), xx = static_cast<i128>(t.x) * t.x;
  t.flat = t.x > 0 && cc * ((i128{1} << kFlatLog2) - 1) < xx;
  t.opposite_halfway = t.x < 0 && cc * ((i128{1} << kOppHalfLog2) - 1) < xx;
  if (t.opposite_halfway) t.c = t.p;

  // 5. N1.u and |c|.
  if (!t.flat) {
    const Vec ch = normalize(t.c, w);
    t.nu = static_cast<int64_t>(rshift_round(dot3(ch, t.p), fr));
    t.c_len = static_cast<int64_t>(rshift_round(dot3(ch, t.c), fr));
  }

  // 6. The angles.
  const int up = cf - fr;
  if (t.opposite_halfway) {
    t.gamma = pi_word(cf);
  } else if (!t.flat) {
    t.gamma = std::clamp(cordic_angle(t.x * (int64_t{1} << up), t.c_len * (int64_t{1} << up), cf, w.cordic_iters(),
                                      w.cordic_bits()),
                         int64_t{0}, pi_word(cf));
  }
  t.lambda = cordic_angle(t.cos_t1 * (int64_t{1} << up), t.nu * (int64_t{1} << up), cf, w.cordic_iters(), w.cordic_bits());

  // 7. The registers.
  r.span.reg.psi0 = static_cast<int64_t>(rshift_round(-static_cast<i128>(t.lambda), cf - f.angle_frac));
  if (g.len != 0)
    r.span.reg.dpsi = static_cast<int64_t>(
        rshift_round(rshift_round(t.gamma, cf - kGammaFrac) * static_cast<i128>(recip_len_table()[g.len]),
                     kGammaFrac + kRecipLenFrac + recip_len_shift(g.len) - f.angle_frac));
  t.a2 = static_cast<int64_t>(static_cast<i128>(t.cos_t1) * t.cos_t1 + static_cast<i128>(t.nu) * t.nu);
  set_amplitude(g, f, w, r);
  if (t.opposite_halfway) r.status = SetupStatus::opposite_halfway;
  else if (t.opposite_normals) r.status = SetupStatus::opposite_normals;
  return r;
}

}  // namespace specular::host::fixed
