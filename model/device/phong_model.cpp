// SPDX-License-Identifier: Apache-2.0
// Golden model of phong_stream (model/device/phong_model.hpp, docs/phong_hw.md).
#include "phong_model.hpp"

#include <bit>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace specular::device {

namespace {

__extension__ typedef __int128 i128;
__extension__ typedef unsigned __int128 u128;

// x * 2^s, floor when s < 0 (arithmetic shift).
i128 shift(i128 x, int s) { return s >= 0 ? x << s : x >> (-s); }

int bit_width_u(u128 x) {
  int b = 0;
  while (x) {
    ++b;
    x >>= 1;
  }
  return b;
}

void check(bool ok, const char* field, int value, const std::string& range) {
  if (!ok) {
    std::ostringstream m;
    m << "PhongFormat: " << field << " = " << value << " outside " << range;
    throw std::invalid_argument(m.str());
  }
}

int64_t sign_extend(uint64_t v, int bits) {
  const uint64_t mask = (uint64_t{1} << bits) - 1;
  v &= mask;
  if ((v >> (bits - 1)) & 1U) v |= ~mask;
  return static_cast<int64_t>(v);
}

}  // namespace

int PhongFormat::w_bits() const {
  return std::bit_width(static_cast<unsigned>(cos_frac + 1)) + log_bits;
}

void PhongFormat::validate() const {
  check(vec_bits >= 4 && vec_bits <= 21, "vec_bits", vec_bits, "4..21");
  check(vec_frac >= 0 && vec_frac < vec_bits, "vec_frac", vec_frac, "0..vec_bits-1");
  check(n_bits == 10, "n_bits", n_bits, "10 (n in 1..1000)");
  check(len_bits >= 1 && len_bits <= 11, "len_bits", len_bits, "1..11");
  check(tag_bits >= 1 && tag_bits <= 32, "tag_bits", tag_bits, "1..32");
  check(c_bits >= 2 && c_bits <= 16 && c_frac < c_bits, "c_bits", c_bits, "2..16 with c_frac < c_bits");
  check(op_bits >= 8 && op_bits <= acc_bits() && op_bits <= 30, "op_bits", op_bits, "8..min(30, vec_bits + len_bits)");
  check(norm_bits >= 8 && norm_bits <= 30, "norm_bits", norm_bits, "8..30");
  check(rsqrt_addr_bits >= 2 && rsqrt_addr_bits <= norm_bits && rsqrt_addr_bits <= 14, "rsqrt_addr_bits",
        rsqrt_addr_bits, "2..min(14, norm_bits)");
  check(newton >= 0 && newton <= 2, "newton", newton, "0..2");
  check(cos_frac >= 8 && cos_frac <= 30, "cos_frac", cos_frac, "8..30");
  check(log_addr_bits >= 1 && log_addr_bits <= 14, "log_addr_bits", log_addr_bits, "1..14");
  check(log_frac_bits >= 1 && log_addr_bits + log_frac_bits <= cos_frac, "log_frac_bits", log_frac_bits,
        "1..cos_frac - log_addr_bits");
  check(log_bits >= log_addr_bits + 2 && log_bits <= 32, "log_bits", log_bits, "log_addr_bits+2..32");
  check(exp_addr_bits >= 1 && exp_addr_bits <= 14, "exp_addr_bits", exp_addr_bits, "1..14");
  check(exp_frac_bits >= 1 && exp_addr_bits + exp_frac_bits <= log_bits, "exp_frac_bits", exp_frac_bits,
        "1..log_bits - exp_addr_bits");
  check(exp_bits >= exp_addr_bits + 2 && exp_bits <= 30, "exp_bits", exp_bits, "exp_addr_bits+2..30");
}

PhongFormat PhongFormat::preset(int n_max) {
  // docs/phong_hw.md#configuration-search: build/bin/phong_search --n-max N.
  PhongFormat f;
  switch (n_max) {
    case 1000:
      return f;
    case 128:
      // The search's result had rsqrt_addr_bits = 9, which misses the budget by 0.1 % of it
      // on the sweep of seed 5 (1.001e-3 at n = 128); one more address bit holds on the
      // sweeps of seeds 2, 3, 5, 6, 11 and 12 (docs/phong_hw.md#configuration-search).
      f.op_bits = 20;
      f.norm_bits = 20;
      f.rsqrt_addr_bits = 10, f.newton = 1;
      f.cos_frac = 19;
      f.log_addr_bits = 7, f.log_frac_bits = 11, f.log_bits = 19;
      f.exp_addr_bits = 4, f.exp_frac_bits = 8, f.exp_bits = 16;
      return f;
    case 64:
      f.op_bits = 20;
      f.norm_bits = 19;
      f.rsqrt_addr_bits = 9, f.newton = 1;
      f.cos_frac = 19;
      f.log_addr_bits = 6, f.log_frac_bits = 11, f.log_bits = 18;
      f.exp_addr_bits = 4, f.exp_frac_bits = 8, f.exp_bits = 16;
      return f;
    default:
      throw std::invalid_argument("PhongFormat::preset: n_max = " + std::to_string(n_max) + " is not 64, 128 or 1000");
  }
}

std::string PhongFormat::describe() const {
  std::ostringstream m;
  m << (const_h ? "constH " : "") << "op" << op_bits << " norm" << norm_bits << " rsqrt" << rsqrt_addr_bits << "x"
    << newton << "nr cos" << cos_frac << " log" << log_addr_bits << "/" << log_frac_bits << "/" << log_bits << " exp"
    << exp_addr_bits << "/" << exp_frac_bits << "/" << exp_bits;
  return m.str();
}

GeoFormat geo_format(const PhongFormat& f) {
  GeoFormat g;
  g.vec_bits = f.vec_bits;
  g.vec_frac = f.vec_frac;
  g.tag_bits = f.tag_bits;
  return g;
}

Format c_format(const PhongFormat& f) {
  Format c;
  c.c_bits = f.c_bits;
  c.c_frac = f.c_frac;
  c.n_bits = f.n_bits;
  c.len_bits = f.len_bits;
  return c;
}

std::vector<uint64_t> phong_rsqrt_rom(const PhongFormat& f) {
  f.validate();
  std::vector<uint64_t> rom(static_cast<size_t>(f.rsqrt_depth()));
  const double step = std::ldexp(1.0, 2 - f.rsqrt_addr_bits);  // segment width on [1, 4)
  for (size_t j = 0; j < rom.size(); ++j) {
    const double mid = 1.0 + (static_cast<double>(j) + 0.5) * step;
    rom[j] = static_cast<uint64_t>(std::llround(std::ldexp(1.0 / std::sqrt(mid), f.norm_bits)));
  }
  return rom;
}

std::vector<uint64_t> phong_log_rom(const PhongFormat& f) {
  f.validate();
  const int depth = f.log_depth();
  auto v = [&](int j) {
    return static_cast<uint64_t>(std::llround(std::ldexp(std::log2(1.0 + std::ldexp(j, -f.log_addr_bits)), f.log_bits)));
  };
  std::vector<uint64_t> rom(static_cast<size_t>(depth));
  const int db = f.log_delta_bits();
  for (int j = 0; j < depth; ++j) {
    const uint64_t vj = v(j), dv = v(j + 1) - vj;
    if (vj >= (uint64_t{1} << f.log_bits) || dv >= (uint64_t{1} << db))
      throw std::logic_error("phong_log_rom: a word does not fit its field");
    rom[static_cast<size_t>(j)] = (vj << db) | dv;
  }
  return rom;
}

std::vector<uint64_t> phong_exp_rom(const PhongFormat& f) {
  f.validate();
  const int depth = f.exp_depth();
  auto u = [&](int j) {
    return static_cast<uint64_t>(std::llround(std::ldexp(std::exp2(-std::ldexp(j, -f.exp_addr_bits)), f.exp_bits)));
  };
  std::vector<uint64_t> rom(static_cast<size_t>(depth));
  const int db = f.exp_delta_bits();
  for (int j = 0; j < depth; ++j) {
    const uint64_t uj = u(j), du = uj - u(j + 1);
    if (uj > (uint64_t{1} << f.exp_bits) || du >= (uint64_t{1} << db))
      throw std::logic_error("phong_exp_rom: a word does not fit its field");
    rom[static_cast<size_t>(j)] = (uj << db) | du;
  }
  return rom;
}

PhongModel::PhongModel(PhongFormat f) : f_(f) {
  f_.validate();
  rsqrt_ = phong_rsqrt_rom(f_);
  log_ = phong_log_rom(f_);
  exp_ = phong_exp_rom(f_);
}

GeoSpan PhongModel::latch(const GeoSpan& s) const {
  GeoSpan r = s;
  for (int c = 0; c < 3; ++c) {
    r.n1[c] = static_cast<int32_t>(sign_extend(static_cast<uint64_t>(s.n1[c]), f_.vec_bits));
    r.n2[c] = static_cast<int32_t>(sign_extend(static_cast<uint64_t>(s.n2[c]), f_.vec_bits));
    r.h1[c] = static_cast<int32_t>(sign_extend(static_cast<uint64_t>(s.h1[c]), f_.vec_bits));
    r.he[c] = static_cast<int32_t>(sign_extend(static_cast<uint64_t>(s.he[c]), f_.vec_bits));
  }
  r.n = s.n & ((1U << f_.n_bits) - 1U);
  r.len = s.len & ((1U << f_.len_bits) - 1U);
  r.scale = s.scale & ((1U << f_.c_bits) - 1U);
  r.tag = f_.tag_bits >= 32 ? s.tag : (s.tag & ((1U << f_.tag_bits) - 1U));
  return r;
}

PhongTrace PhongModel::trace(const GeoSpan& in, int i) const {
  const PhongFormat& f = f_;
  const GeoSpan s = latch(in);
  if (i < 0 || static_cast<uint32_t>(i) > s.len) throw std::out_of_range("PhongModel: pixel index outside 0..l");
  PhongTrace t;
  // Per span: L = l << k in [2^(len_bits-1), 2^len_bits), steps << k.
  const int lw = std::bit_width(s.len);
  const int k = s.len == 0 ? 0 : f.len_bits - lw;
  const int64_t big_l = s.len == 0 ? (int64_t{1} << (f.len_bits - 1)) : (static_cast<int64_t>(s.len) << k);
  const int drop = f.acc_bits() - f.op_bits;
  for (int c = 0; c < 3; ++c) {
    const int64_t an = big_l * s.n1[c] + (s.len == 0 ? 0 : static_cast<int64_t>(i) * ((int64_t{s.n2[c]} - s.n1[c]) << k));
    int64_t bn;
    if (f.const_h)
      bn = int64_t{s.h1[c]} << (f.len_bits - 1);
    else
      bn = big_l * s.h1[c] + (s.len == 0 ? 0 : static_cast<int64_t>(i) * ((int64_t{s.he[c]} - s.h1[c]) << k));
    t.a[c] = an >> drop;
    t.b[c] = bn >> drop;
  }
  i128 d = 0, na = 0, nb = 0;
  for (int c = 0; c < 3; ++c) {
    d += i128{t.a[c]} * t.b[c];
    na += i128{t.a[c]} * t.a[c];
    nb += i128{t.b[c]} * t.b[c];
  }
  t.d = static_cast<int64_t>(d);
  t.na = static_cast<uint64_t>(na);
  t.nb = static_cast<uint64_t>(nb);
  const bool n_ok = s.n >= 1 && s.n <= static_cast<uint32_t>(kMaxN);
  auto zero = [](const GeoVec& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; };
  const bool zero_end = zero(s.n1) || zero(s.n2) || zero(s.h1) || (!f.const_h && zero(s.he));
  if (!n_ok || zero_end || d <= 0) return t;

  // Normalization: the mantissas of na and nb, their product, 1/sqrt by ROM and Newton.
  const int m_frac = f.norm_bits - 2;
  t.ea = (bit_width_u(static_cast<u128>(na)) - 1) & ~1;
  t.eb = (bit_width_u(static_cast<u128>(nb)) - 1) & ~1;
  t.ma = static_cast<uint64_t>(shift(na, m_frac - t.ea));
  t.mb = static_cast<uint64_t>(shift(nb, m_frac - t.eb));
  const u128 m = u128{t.ma} * t.mb;
  t.em = m >= (u128{4} << (2 * m_frac)) ? 1 : 0;
  t.mm = static_cast<uint64_t>(m >> (m_frac + 2 * t.em));
  const uint64_t idx = (t.mm >> (f.norm_bits - f.rsqrt_addr_bits)) - (uint64_t{1} << (f.rsqrt_addr_bits - 2));
  t.y0 = rsqrt_.at(idx);
  uint64_t y = t.y0;
  for (int it = 0; it < f.newton; ++it) {
    const u128 sq = (u128{y} * y) >> f.norm_bits;
    const u128 u = (u128{t.mm} * sq) >> m_frac;
    const u128 three = u128{3} << f.norm_bits;
    if (u >= three) throw std::logic_error("PhongModel: Newton step out of range");
    y = static_cast<uint64_t>((u128{y} * (three - u)) >> (f.norm_bits + 1));
  }
  t.y = y;
  const int big_k = t.ea / 2 + t.eb / 2 + t.em;
  t.dn = static_cast<uint64_t>(shift(d, f.cos_frac - big_k));
  const uint64_t one = uint64_t{1} << f.cos_frac;
  t.c = static_cast<uint64_t>(std::min<u128>((u128{t.dn} * y) >> f.norm_bits, one));
  if (t.c == 0) return t;

  // -log2 c from the interpolated log2 ROM.
  if (t.c == one) {
    t.w = 0;
  } else {
    const int p = std::bit_width(t.c) - 1;
    t.e = f.cos_frac - p;
    const uint64_t frac = (t.c << t.e) - one;
    const uint64_t j = frac >> (f.cos_frac - f.log_addr_bits);
    const uint64_t tw = (frac >> (f.cos_frac - f.log_addr_bits - f.log_frac_bits)) & ((uint64_t{1} << f.log_frac_bits) - 1);
    const uint64_t word = log_[j];
    const int db = f.log_delta_bits();
    const uint64_t v = word >> db, dv = word & ((uint64_t{1} << db) - 1);
    const uint64_t lg = v + ((dv * tw + (uint64_t{1} << (f.log_frac_bits - 1))) >> f.log_frac_bits);
    t.w = (static_cast<uint64_t>(t.e) << f.log_bits) - lg;
  }
  // z = n w, 2^-z from the interpolated exp2 ROM.
  t.z = static_cast<uint64_t>(s.n) * t.w;
  const uint64_t zi = t.z >> f.log_bits;
  if (zi > static_cast<uint64_t>(f.exp_bits)) return t;
  const uint64_t zf = t.z & ((uint64_t{1} << f.log_bits) - 1);
  const uint64_t j = zf >> (f.log_bits - f.exp_addr_bits);
  const uint64_t tw = (zf >> (f.log_bits - f.exp_addr_bits - f.exp_frac_bits)) & ((uint64_t{1} << f.exp_frac_bits) - 1);
  const uint64_t word = exp_[j];
  const int db = f.exp_delta_bits();
  const uint64_t u = word >> db, du = word & ((uint64_t{1} << db) - 1);
  t.p = (u - ((du * tw + (uint64_t{1} << (f.exp_frac_bits - 1))) >> f.exp_frac_bits)) >> zi;
  t.intensity = static_cast<uint32_t>((uint64_t{s.scale} * t.p + (uint64_t{1} << (f.exp_bits - 1))) >> f.exp_bits);
  return t;
}

void PhongModel::stream_span(const GeoSpan& in, std::vector<StreamPixel>& out) const {
  const GeoSpan s = latch(in);
  for (uint32_t i = 0; i <= s.len; ++i) out.push_back({pixel(s, static_cast<int>(i)), i == s.len, s.tag});
}

std::vector<StreamPixel> PhongModel::stream(const std::vector<GeoSpan>& spans) const {
  std::vector<StreamPixel> out;
  for (const GeoSpan& s : spans) stream_span(s, out);
  return out;
}

}  // namespace specular::device
