// SPDX-License-Identifier: Apache-2.0
// Scanline setup, docs/scanline_setup.md. How every hard case is resolved (tests/model/test_scanline.cpp
// has one named test per case):
//
//  * NaN / infinite components, zero-length N1 or N2, n outside [1, 1000], l outside
//    0..kMaxLen, Is/ks/s(n) negative or not finite: status invalid_input, everything 0.
//  * Non-unit vectors: normalized first (note says so); status stays ok.
//  * Zero-length H1 or He (the host's H = (L+V)/|L+V| with L = -V): undefined_halfway, C = 0.
//  * N1 = N2: the rotation is the identity, H2 = He; nothing special.
//  * N1 = -N2: opposite_normals, half turn about the tangential part of He (see header).
//    The limit N2 -> -N1 depends on the direction of approach, so no rule can be continuous
//    there; away from exact opposition the rotation is computed stably (below).
//  * gamma = 0 (H2 = H1): u is undefined, we set N1.u = 0, so lambda = 0 (or pi) and dpsi = 0.
//    The only threshold is the rounding-noise floor of the chord |H2 - H1| (16 ulp, gamma ~
//    3.6e-15): below it the chord's direction is noise, so gamma is set to 0. Above it u is
//    computed from H2 - H1 without cancellation and re-orthogonalized against H1; whatever
//    lambda results, A cos(lambda) = N1.H1 and dpsi ~ gamma, so every pixel is continuous
//    across the floor (the change is O(1e-15)).
//  * gamma = pi (H2 = -H1): opposite_halfway, great circle through N1.
//  * cos t1 <= 0, psi beyond +-pi/2: no special case; lambda is in (-pi, pi] and the pixel
//    clamp (|psi| >= pi/2 gives 0) handles it. A = 0 gives C = 0.
//  * l = 0: one pixel, dpsi = 0. l = kMaxLen: ordinary.
//  * psi crossing 0 inside the span: ordinary; cos is even.
#include "scanline_setup.hpp"

#include "coefficients.hpp"

#include <glm/geometric.hpp>

#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace specular {

namespace {
using glm::dvec3;

void add_note(std::string& note, const char* what) {
  if (!note.empty()) note += "; ";
  note += what;
}

bool finite3(const dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Some unit vector orthogonal to unit v (deterministic: crossed with the least-aligned axis).
dvec3 any_perpendicular(const dvec3& v) {
  const dvec3 ax = std::abs(v.x) <= std::abs(v.y) && std::abs(v.x) <= std::abs(v.z) ? dvec3(1, 0, 0)
                   : std::abs(v.y) <= std::abs(v.z)                                  ? dvec3(0, 1, 0)
                                                                                     : dvec3(0, 0, 1);
  return glm::normalize(glm::cross(v, ax));
}

struct Normalized {
  dvec3 n1, n2, h1, he;
  bool zero_h = false;
  bool rescaled = false;
};

// Returns false on invalid input (message in *why).
bool normalize_input(const ScanlineInput& in, Normalized& out, std::string* why) {
  auto bad = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  static const std::string n_range = "n must be in [1, " + std::to_string(kMaxN) + "]";
  static const std::string l_range = "l must be in 0.." + std::to_string(kMaxLen) + " (" +
                                     std::to_string(std::bit_width(static_cast<unsigned>(kMaxLen))) + "-bit counter)";
  if (!std::isfinite(in.n) || in.n < 1.0 || in.n > kMaxN) return bad(n_range.c_str());
  if (in.l < 0 || in.l > kMaxLen) return bad(l_range.c_str());
  if (!std::isfinite(in.is) || in.is < 0.0) return bad("Is must be finite and >= 0");
  if (!std::isfinite(in.ks) || in.ks < 0.0) return bad("ks must be finite and >= 0");
  if (!std::isfinite(in.norm) || in.norm < 0.0) return bad("s(n) must be finite and >= 0");
  if (!finite3(in.n1) || !finite3(in.n2) || !finite3(in.h1) || !finite3(in.he))
    return bad("vector with a NaN or infinite component");
  const double ln1 = glm::length(in.n1), ln2 = glm::length(in.n2);
  if (!(ln1 > 0.0) || !(ln2 > 0.0) || !std::isfinite(ln1) || !std::isfinite(ln2))
    return bad("zero-length (or overflowing) normal");
  const double lh1 = glm::length(in.h1), lhe = glm::length(in.he);
  if (!std::isfinite(lh1) || !std::isfinite(lhe)) return bad("overflowing halfway vector");
  out.n1 = in.n1 / ln1;
  out.n2 = in.n2 / ln2;
  out.zero_h = !(lh1 > 0.0) || !(lhe > 0.0);
  if (!out.zero_h) {
    out.h1 = in.h1 / lh1;
    out.he = in.he / lhe;
  }
  auto off = [](double len) { return std::abs(len - 1.0) > 1e-12; };
  out.rescaled = off(ln1) || off(ln2) || (!out.zero_h && (off(lh1) || off(lhe)));
  return true;
}
}  // namespace

std::string to_string(SetupStatus s) {
  switch (s) {
    case SetupStatus::ok: return "ok";
    case SetupStatus::invalid_input: return "invalid_input";
    case SetupStatus::undefined_halfway: return "undefined_halfway";
    case SetupStatus::opposite_normals: return "opposite_normals";
    case SetupStatus::opposite_halfway: return "opposite_halfway";
  }
  return "?";
}

namespace {
bool decide(SetupRule::Force f, bool by_metric) {
  return f == SetupRule::Force::by_metric ? by_metric : f == SetupRule::Force::yes;
}
}  // namespace

ScanlineSetup scanline_setup(const ScanlineInput& in, const SetupRule& rule) {
  ScanlineSetup s;
  Normalized v;
  std::string why;
  if (!normalize_input(in, v, &why)) {
    s.status = SetupStatus::invalid_input;
    s.note = "invalid input: " + why + "; C = 0, every pixel 0";
    return s;
  }
  if (v.rescaled) s.note = "non-unit input vectors were normalized";
  if (v.zero_h) {
    s.status = SetupStatus::undefined_halfway;
    s.note = "zero-length halfway vector (L = -V): no specular term, C = 0";
    return s;
  }

  // 1. H2 = rotation of He taking N2 to N1 (Rodrigues). With sum = N1 + N2,
  //    1 + c = |sum|^2 / 2 and v = N1 x N2 = N1 x sum keep full relative precision even
  //    when N2 is nearly -N1 (the printed forms cancel).
  const dvec3 sum = v.n1 + v.n2;
  const double opc = 0.5 * glm::dot(sum, sum);
  dvec3 h2;
  s.q = 2.0 * opc;
  if (decide(rule.opposite_normals, rule.hardware ? s.q < rule.q_min : opc <= 1e-30)) {
    s.status = SetupStatus::opposite_normals;
    add_note(s.note, "N1 = -N2: half turn about the tangential part of He");
    dvec3 w = v.he - glm::dot(v.he, v.n1) * v.n1;
    const double lw = glm::length(w);
    w = lw > 1e-12 ? w / lw : any_perpendicular(v.n1);
    h2 = 2.0 * glm::dot(w, v.he) * w - v.he;
  } else {
    const dvec3 rv = glm::cross(v.n1, sum);
    h2 = v.he - glm::cross(rv, v.he) + glm::cross(rv, glm::cross(rv, v.he)) / opc;
    h2 = glm::normalize(h2);  // a rotation keeps length; this only removes rounding
  }

  // 2. gamma from the chord lengths (accurate at 0 and pi, unlike acos or the dot product).
  const dvec3 d = h2 - v.h1, hs = h2 + v.h1;
  const double ld = glm::length(d), lhs = glm::length(hs);
  s.gamma = 2.0 * std::atan2(ld, lhs);
  const double cos_t1 = glm::dot(v.n1, v.h1);

  // 3. u: unit vector in the plane of H1, H2, orthogonal to H1, towards H2.
  //    d + (|d|^2 / 2) H1 is exactly H2 - (H1.H2) H1, computed without cancellation.
  //    A chord of a few ulp is rounding noise of step 1 (rotation, normalization): its
  //    direction means nothing, and taking u from it gave A > 1 (C saturated) for N1 = N2,
  //    H1 = He. Below kChordNoise gamma is 0; pixel values change by O(kChordNoise) there.
  constexpr double kChordNoise = 16.0 * std::numeric_limits<double>::epsilon();
  s.sin_gamma = 0.5 * ld * lhs;  // 2 sin(gamma/2) cos(gamma/2)
  s.x_positive = ld < lhs;
  const bool flat = rule.hardware ? s.x_positive && s.sin_gamma < rule.flat_sin : ld <= kChordNoise;
  const bool opposite = rule.hardware ? !s.x_positive && s.sin_gamma < rule.opposite_sin : lhs <= 1e-12;
  double nu = 0.0;
  if (decide(rule.flat, flat)) {
    s.flat = true;
    s.gamma = 0.0;
    nu = 0.0;  // gamma = 0: u undefined and irrelevant (dpsi = 0, A cos(lambda) = cos t1)
  } else if (decide(rule.opposite_halfway, opposite)) {
    s.status = SetupStatus::opposite_halfway;
    if (rule.hardware) s.gamma = std::numbers::pi;  // the stated rule: the half turn exactly
    add_note(s.note, "H2 = -H1: slerp along the great circle through N1");
    dvec3 u = v.n1 - cos_t1 * v.h1;
    const double lu = glm::length(u);
    u = lu > 1e-12 ? u / lu : any_perpendicular(v.h1);
    nu = glm::dot(v.n1, u);
  } else {
    // Re-orthogonalize against H1: |H2| = 1 only to rounding, so d carries a radial part.
    const dvec3 w = d + (0.5 * ld * ld) * v.h1;
    const dvec3 u = glm::normalize(w - glm::dot(w, v.h1) * v.h1);
    nu = glm::dot(v.n1, u);
  }
  s.A = std::hypot(cos_t1, nu);
  s.lambda = std::atan2(nu, cos_t1);

  // 4. Device inputs. (Erratum: the patent loads reg 3 with -sqrt(n/k) lambda, but
  //    multiplier 11 scales the accumulator, so reg 3 holds the unscaled -lambda.)
  s.C = in.is * in.ks * in.norm * std::pow(s.A, in.n);
  s.psi0 = -s.lambda + 0.0;  // + 0.0: never print -0
  s.dpsi = in.l > 0 ? s.gamma / in.l : 0.0;
  return s;
}

double pixel_blinn(const ScanlineSetup& s, double n, int i) {
  const double psi = pixel_psi(s, i);
  if (!(std::abs(psi) < 1.57079632679489661923)) return 0.0;
  return s.C * std::pow(std::cos(psi), n);
}

double phong_truth(const ScanlineInput& in, int i) {
  if (i < 0 || i > std::max(in.l, 0)) throw std::out_of_range("phong_truth: pixel index outside 0..l");
  Normalized v;
  if (!normalize_input(in, v, nullptr) || v.zero_h) return 0.0;
  const double t = in.l > 0 ? static_cast<double>(i) / in.l : 0.0;
  const dvec3 nn = (1.0 - t) * v.n1 + t * v.n2;
  const dvec3 hh = (1.0 - t) * v.h1 + t * v.he;
  const double ln = glm::length(nn), lh = glm::length(hh);
  if (!(ln > 1e-300) || !(lh > 1e-300)) return 0.0;
  const double c = glm::dot(nn, hh) / (ln * lh);
  return c > 0.0 ? in.is * in.ks * in.norm * std::pow(c, in.n) : 0.0;
}

}  // namespace specular
