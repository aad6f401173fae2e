// Scanline setup by spherical (angular) interpolation, SPEC section 4.
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

// How the setup resolved the input; every hard case of SPEC section 4 maps to one.
enum class SetupStatus {
  ok,
  invalid_input,   // NaN / infinite / zero-length vector, n out of range, l < 0: C = 0, all pixels 0
  // other statuses are defined in scanline_setup.cpp's documentation and here
};

struct ScanlineSetup {
  double A = 0.0;       // amplitude of N1 . H(t)
  double lambda = 0.0;  // phase: A cos(lambda) = N1.H1, A sin(lambda) = N1.u
  double gamma = 0.0;   // angle between H1 and H2 (atan2 form), [0, pi]
  double C = 0.0;       // Is * ks * s(n) * A^n
  double psi0 = 0.0;    // -lambda
  double dpsi = 0.0;    // gamma / l, 0 when l = 0
  SetupStatus status = SetupStatus::ok;
  std::string note;     // human-readable explanation when status != ok
};

ScanlineSetup scanline_setup(const ScanlineInput& in);

// psi of pixel i (0..l).
inline double pixel_psi(const ScanlineSetup& s, int i) { return s.psi0 + i * s.dpsi; }

}  // namespace specular
