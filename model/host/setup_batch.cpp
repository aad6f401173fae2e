// SPDX-License-Identifier: Apache-2.0
// Batched scanline setup (model/host/setup_batch.hpp): the SoA containers, the scalar
// reference loop, the block driver and the run-time dispatch between the two compiled
// kernels (setup_batch_kernel.inl).
#include "setup_batch.hpp"

#include "setup_batch_detail.hpp"

#include "metrics.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <utility>

#define SETUP_KERNEL_NS baseline_kernels
#include "setup_batch_kernel.inl"
#undef SETUP_KERNEL_NS

namespace specular::host {

void SpanBatch::clear() {
  for (auto* v : {&n1x, &n1y, &n1z, &n2x, &n2y, &n2z, &h1x, &h1y, &h1z, &hex, &hey, &hez, &n, &scale}) v->clear();
  l.clear();
}

void SpanBatch::reserve(size_t count) {
  for (auto* v : {&n1x, &n1y, &n1z, &n2x, &n2y, &n2z, &h1x, &h1y, &h1z, &hex, &hey, &hez, &n, &scale})
    v->reserve(count);
  l.reserve(count);
}

void SpanBatch::push_back(const ScanlineInput& in) {
  n1x.push_back(in.n1.x), n1y.push_back(in.n1.y), n1z.push_back(in.n1.z);
  n2x.push_back(in.n2.x), n2y.push_back(in.n2.y), n2z.push_back(in.n2.z);
  h1x.push_back(in.h1.x), h1y.push_back(in.h1.y), h1z.push_back(in.h1.z);
  hex.push_back(in.he.x), hey.push_back(in.he.y), hez.push_back(in.he.z);
  n.push_back(in.n);
  scale.push_back(in.is * in.ks * in.norm);
  l.push_back(in.l);
}

ScanlineInput SpanBatch::input(size_t i) const {
  ScanlineInput s;
  s.n1 = {n1x[i], n1y[i], n1z[i]};
  s.n2 = {n2x[i], n2y[i], n2z[i]};
  s.h1 = {h1x[i], h1y[i], h1z[i]};
  s.he = {hex[i], hey[i], hez[i]};
  s.is = scale[i];
  s.n = n[i];
  s.l = l[i];
  return s;
}

void RegisterBatch::resize(size_t count) {
  c.resize(count), psi0.resize(count), dpsi.resize(count), n.resize(count), len.resize(count);
  status.resize(count), flags.resize(count);
}

namespace {

void check_sizes(const SpanBatch& in) {
  const size_t n = in.size();
  for (const auto* v : {&in.n1x, &in.n1y, &in.n1z, &in.n2x, &in.n2y, &in.n2z, &in.h1x, &in.h1y, &in.h1z, &in.hex,
                        &in.hey, &in.hez, &in.n, &in.scale})
    if (v->size() != n) throw std::invalid_argument("setup_batch: the SpanBatch arrays differ in length");
}

void scalar_one(const SpanBatch& in, size_t i, const device::Format& f, RegisterBatch& out) {
  const ScanlineInput s = in.input(i);
  const ScanlineSetup st = scanline_setup(s);
  const device::RegisterLoad ld = device::load_registers(st, s.n, s.l, f);
  out.c[i] = ld.reg.c, out.psi0[i] = ld.reg.psi0, out.dpsi[i] = ld.reg.dpsi;
  out.n[i] = ld.reg.n, out.len[i] = ld.reg.len;
  out.status[i] = static_cast<uint8_t>(st.status);
  out.flags[i] = (ld.c_saturated ? kCSaturated : 0) | (ld.angle_saturated ? kAngleSaturated : 0);
}

}  // namespace

device::Registers span_registers(const ScanlineInput& in, const device::Format& f, bool* c_saturated) {
  const device::RegisterLoad load = device::load_registers(scanline_setup(in), in.n, in.l, f);
  if (c_saturated) *c_saturated = load.c_saturated;
  return load.reg;
}

void setup_scalar(const SpanBatch& in, const device::Format& f, RegisterBatch& out) {
  check_sizes(in);
  out.resize(in.size());
  for (size_t i = 0; i < in.size(); ++i) scalar_one(in, i, f, out);
}

namespace detail {

size_t setup_batch_baseline(const SpanBatch& in, const device::Format& f, RegisterBatch& out) {
  return run_blocks(in, f, out, baseline_kernels::setup_block, baseline_kernels::flat_block,
                    baseline_kernels::setup_block_regs, baseline_kernels::flat_block_regs);
}

}  // namespace detail

void setup_batch(const SpanBatch& in, const device::Format& f, RegisterBatch& out, SimdPath path) {
  check_sizes(in);
  out.resize(in.size());
  if (in.size() == 0) return;
  size_t specials = 0;
  if (path == SimdPath::automatic && cpu_has_avx512())
    specials = detail::setup_batch_avx512(in, f, out);
  else if (resolve(path) == SimdPath::avx2)
    specials = detail::setup_batch_avx2(in, f, out);
  else
    specials = detail::setup_batch_baseline(in, f, out);
  // Spans the kernel left to the scalar setup (docs/scanline_setup.md#batched-setup).
  for (size_t i = 0; specials > 0 && i < in.size(); ++i)
    if (out.status[i] == detail::kSpecialStatus) scalar_one(in, i, f, out), --specials;
}

namespace {

glm::dvec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  for (;;) {
    const glm::dvec3 v{g(rng), g(rng), g(rng)};
    const double l = glm::length(v);
    if (l > 1e-3) return v / l;
  }
}

// v turned by `angle` towards a random direction orthogonal to it.
glm::dvec3 tilt(const glm::dvec3& v, double angle, std::mt19937_64& rng) {
  glm::dvec3 w = random_unit(rng);
  w = glm::normalize(w - glm::dot(w, v) * v);
  return std::cos(angle) * v + std::sin(angle) * w;
}

ScanlineInput random_span(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, u01(rng)); };
  static const std::vector<int> kBoundaries = patent_bank_edges();
  ScanlineInput in;
  in.n1 = random_unit(rng);
  in.n2 = u01(rng) < 0.1 ? in.n1 : tilt(in.n1, log_uniform(1e-9, 2.0), rng);
  in.n = u01(rng) < 0.05 ? kBoundaries[rng() % kBoundaries.size()]
                         : std::min(std::floor(1.0 + kMaxN * u01(rng)), static_cast<double>(kMaxN));
  in.h1 = u01(rng) < 0.8 ? tilt(in.n1, log_uniform(1e-6, 3.0 / std::sqrt(in.n)), rng) : random_unit(rng);
  in.he = u01(rng) < 0.5 ? in.h1 : tilt(in.h1, log_uniform(1e-9, 1.0), rng);
  const double r = u01(rng);
  in.l = static_cast<int>(rng() % (r < 0.6 ? 16 : r < 0.9 ? 256 : kMaxLen + 1));
  in.is = u01(rng) < 0.02 ? 2.5 : u01(rng) * 1.2;
  return in;
}

}  // namespace

std::vector<ScanlineInput> random_spans(size_t count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<ScanlineInput> v;
  v.reserve(count);
  for (size_t i = 0; i < count; ++i) v.push_back(random_span(rng));
  return v;
}

std::vector<ScanlineInput> random_spans_of_length(size_t count, uint64_t seed, int len) {
  std::vector<ScanlineInput> v = random_spans(count, seed);
  for (auto& s : v) s.l = len;
  return v;
}

namespace {

// Pixel indices [lo, hi] (clipped to 0..len) where |psi0 + i dpsi| <= cut; lo > hi when none.
std::pair<int, int> lobe_range(double psi0, double dpsi, int len, double cut) {
  if (dpsi == 0.0) return std::abs(psi0) <= cut ? std::pair{0, len} : std::pair{1, 0};
  double a = (-cut - psi0) / dpsi, b = (cut - psi0) / dpsi;
  if (a > b) std::swap(a, b);
  const double lo = std::max(0.0, std::floor(a) - 1.0), hi = std::min(static_cast<double>(len), std::ceil(b) + 1.0);
  return lo > hi ? std::pair{1, 0} : std::pair{static_cast<int>(lo), static_cast<int>(hi)};
}

constexpr int kShortSpan = 15;  // compare_pixels evaluates every pixel of spans up to this l

struct Decoded {
  double c, psi0, dpsi, n;
  int len;
  // |psi| beyond which C cos^n(psi) < 1 LSB (every pixel when C < 1 LSB: -1).
  double cut(double lsb) const {
    if (n <= 0.0 || c < lsb) return -1.0;
    return std::acos(std::pow(lsb / c, 1.0 / n));
  }
  double pixel(int i) const {
    const double psi = psi0 + i * dpsi;
    if (n <= 0.0 || !(std::abs(psi) < std::numbers::pi / 2)) return 0.0;
    // n is a register code (an integer <= max_n): cos^n by squaring, relative error below
    // 2 log2(n) + 1 ulp (1e-14 here), far under the 1e-4 compared; std::pow costs more.
    double r = 1.0, b = std::cos(psi);
    for (unsigned k = static_cast<unsigned>(n); k; k >>= 1, b *= b)
      if (k & 1U) r *= b;
    return c * r;
  }
};

Decoded decode(const device::Registers& r, const device::Format& f) {
  const bool valid_n = r.n >= 1 && static_cast<int>(r.n) <= f.max_n();
  return {device::c_value(r.c, f), device::angle_value(r.psi0, f), device::angle_value(r.dpsi, f),
          valid_n ? static_cast<double>(r.n) : 0.0, static_cast<int>(r.len)};
}

}  // namespace

PixelAgreement compare_pixels(const device::Registers& r, const device::Registers& ref, const device::Format& f,
                              double rel_tol) {
  PixelAgreement out;
  const double lsb = std::ldexp(1.0, -f.c_frac);
  const Decoded a = decode(r, f), b = decode(ref, f);
  const int len = static_cast<int>(std::max(r.len, ref.len));
  // Short spans: every pixel (cheaper than finding the lobe, and the same verdict: a pixel
  // outside both lobes differs by less than 1 LSB).
  int lo = 0, hi = len;
  if (len > kShortSpan) {
    const auto ra = lobe_range(a.psi0, a.dpsi, len, a.cut(lsb));
    const auto rb = lobe_range(b.psi0, b.dpsi, len, b.cut(lsb));
    lo = std::min(ra.first, rb.first), hi = std::max(ra.second, rb.second);
    if (ra.first > ra.second) lo = rb.first, hi = rb.second;
    if (rb.first > rb.second) lo = ra.first, hi = ra.second;
  }
  const double xe = b.n > 0.0 ? epicenter_end(b.n) : 0.0;
  for (int i = lo; i <= hi; ++i) {
    const double pa = i <= a.len ? a.pixel(i) : 0.0, pb = i <= b.len ? b.pixel(i) : 0.0;
    const double d = std::abs(pa - pb);
    const bool epi = b.n > 0.0 && std::abs(b.psi0 + i * b.dpsi) <= xe;
    const double allowance = rel_tol * (epi ? pb : b.c) + lsb;
    if (d / allowance > out.worst) out.worst = d / allowance, out.worst_pixel = i;
    out.max_abs_lsb = std::max(out.max_abs_lsb, d / lsb);
    if (epi && pb >= 0x1p-10) out.max_rel_epicenter = std::max(out.max_rel_epicenter, d / pb);
  }
  return out;
}

}  // namespace specular::host
