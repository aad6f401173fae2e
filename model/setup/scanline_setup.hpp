// SPDX-License-Identifier: Apache-2.0
// Scanline setup by spherical (angular) interpolation, docs/scanline_setup.md.
//
// The host turns the geometry of one scanline into the five device inputs
// (C, psi0, dpsi, n, l). Along the span the Blinn cosine is exactly
//   N1 . H(t) = A cos(t*gamma - lambda),   H(t) = slerp(H1, H2, t),
// so pixel i has psi_i = psi0 + i*dpsi and I_i = C cos^n(psi_i).
#pragma once

#include <glm/vec3.hpp>

#include <string>

namespace specular {

struct ScanlineInput {
  glm::dvec3 n1{0, 0, 1};  // unit normal at the first pixel
  glm::dvec3 n2{0, 0, 1};  // unit normal at the last pixel
  glm::dvec3 h1{0, 0, 1};  // unit halfway vector at the first pixel
  glm::dvec3 he{0, 0, 1};  // unit halfway vector at the last pixel (= h1 for light and viewer at infinity)
  double is = 1.0;         // light intensity Is
  double ks = 1.0;         // specular coefficient ks
  double norm = 1.0;       // normalization s(n); 1 when none
  double n = 1.0;          // specular exponent, [1, 1000]
  int l = 0;               // X_end - X_start; the span has l + 1 pixels
};

// How the setup resolved the input; every hard case of docs/scanline_setup.md maps to one.
enum class SetupStatus {
  ok,
  invalid_input,   // NaN / infinite / zero-length vector, n out of range, l < 0: C = 0, all pixels 0
  // other statuses are defined in scanline_setup.cpp's documentation and here
  undefined_halfway,  // H1 or He has zero length (L = -V, |L+V| = 0): C = 0, all pixels 0.
                      // Physically right: with L = -V, N.L = -N.V, so the light is behind the
                      // surface or the surface faces away; there is no specular term.
  opposite_normals,   // N1 = -N2 (1 + N1.N2 = 0): the rotation N2 -> N1 is not unique; we use the
                      // half turn about the tangential part of He (H2 = mirror of He through the
                      // tangent plane of N1). N1.H2 = N2.He still holds. The result is valid.
  opposite_halfway,   // H2 = -H1 (gamma = pi): the slerp path is not unique; we take the great
                      // circle through N1 (u = part of N1 orthogonal to H1). The result is valid.
};

inline constexpr int kMaxLen = 2047;  // counter 5 has 11 bits: l in 0..2047

struct ScanlineSetup {
  double A = 0.0;       // amplitude of N1 . H(t)
  double lambda = 0.0;  // phase: A cos(lambda) = N1.H1, A sin(lambda) = N1.u
  double gamma = 0.0;   // angle between H1 and H2 (atan2 form), [0, pi]
  double C = 0.0;       // Is * ks * s(n) * A^n
  double psi0 = 0.0;    // -lambda
  double dpsi = 0.0;    // gamma / l, 0 when l = 0
  SetupStatus status = SetupStatus::ok;
  std::string note;     // human-readable explanation when status != ok
  // The decision metrics (docs/setup_hw.md#the-contract): |N1 + N2|^2 of the unit normals,
  // sin gamma and the sign of H1.H2; and whether gamma was set to 0 (flat).
  double q = 0.0, sin_gamma = 0.0;
  bool x_positive = true, flat = false;
};

// The rule that decides the degenerate classes. The default is the scalar setup's own
// (double-precision noise floors); a hardware setup states thresholds at its own precision
// (docs/setup_hw.md#the-contract) and, inside a decision's guard band, forces the branch it
// took.
struct SetupRule {
  enum class Force { by_metric, yes, no };
  bool hardware = false;         // false: the double floors below; true: the thresholds on q and sin gamma
  double q_min = 0.0;            // hardware: opposite_normals when q < q_min
  double flat_sin = 0.0;         // hardware: flat when sin gamma < flat_sin and H1.H2 > 0
  double opposite_sin = 0.0;     // hardware: opposite_halfway when sin gamma < opposite_sin and H1.H2 < 0
  Force opposite_normals = Force::by_metric, flat = Force::by_metric, opposite_halfway = Force::by_metric;
};

ScanlineSetup scanline_setup(const ScanlineInput& in, const SetupRule& rule = {});

// psi of pixel i (0..l).
inline double pixel_psi(const ScanlineSetup& s, int i) { return s.psi0 + i * s.dpsi; }

// What the setup promises the device computes: C cos^n(psi_i), 0 where |psi_i| >= pi/2.
double pixel_blinn(const ScanlineSetup& s, double n, int i);

// Ground truth for the interpolation-model error: per-pixel Phong shading of the span with
// normalized-lerp normals and the true per-pixel H,
//   t = i / l (0 when l = 0), N = normalize(lerp(N1, N2, t)), H = normalize(lerp(H1, He, t)),
//   I = Is * ks * s(n) * max(0, N . H)^n.
// Inputs are normalized first, as in scanline_setup(). Returns 0 for invalid input, zero-length
// H1/He, or where a lerp passes through the zero vector (N1 = -N2 at t = 1/2).
// Throws std::out_of_range unless 0 <= i <= l.
double phong_truth(const ScanlineInput& in, int i);

std::string to_string(SetupStatus s);

}  // namespace specular
