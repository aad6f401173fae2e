// SPDX-License-Identifier: Apache-2.0
// Batched scanline setup: many spans at once, straight to the device's register codes.
//
// The scalar double `scanline_setup` (model/setup/scanline_setup.hpp) is the reference
// and the documentation of the mathematics (docs/scanline_setup.md). This is the same
// computation reorganized for throughput: structure-of-arrays in, register codes out, no
// per-span allocation or branch, vectorized over spans (AVX-512 or AVX2 when the CPU has it,
// portable code otherwise; single precision after the geometry for spans of l <= 255;
// docs/scanline_setup.md#batched-setup says how and how accurate).
//
// Contract: for every span, the status equals scanline_setup's, and the pixels
// C cos^n(psi_i) computed from these registers agree with those from
// load_registers(scanline_setup(span)) within 0.01 % relative in the epicenter plus 1 LSB
// of C (tests/model/test_setup_batch.cpp).
#pragma once

#include "device_model.hpp"
#include "scanline_setup.hpp"
#include "span_shade.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace specular::host {

// Input spans, one entry per span in each array (all arrays the same length).
// scale = Is * ks * s(n); vectors need not be unit (they are normalized, as scanline_setup
// does); n in [1, 1000], l in 0..2047, otherwise the span is invalid_input.
struct SpanBatch {
  std::vector<double> n1x, n1y, n1z, n2x, n2y, n2z;
  std::vector<double> h1x, h1y, h1z, hex, hey, hez;
  std::vector<double> n, scale;
  std::vector<int32_t> l;

  size_t size() const { return l.size(); }
  void clear();
  void reserve(size_t count);
  // Appends one span (scale = in.is * in.ks * in.norm).
  void push_back(const ScanlineInput& in);
  // The span as the scalar setup takes it (is = scale, ks = norm = 1).
  ScanlineInput input(size_t i) const;
};

// Per-span flags beside the status.
enum RegisterFlag : uint8_t {
  kCSaturated = 1,      // C outside [0, 2): clamped into reg 1
  kAngleSaturated = 2,  // psi0 or dpsi outside the signed register range: clamped
};

// Output registers, structure of arrays, one entry per input span.
struct RegisterBatch {
  std::vector<uint32_t> c;      // reg 1 code
  std::vector<int64_t> psi0;    // reg 3 code (signed)
  std::vector<int64_t> dpsi;    // reg 2 code (signed)
  std::vector<uint32_t> n;      // reg 4 code
  std::vector<uint32_t> len;    // counter 5
  std::vector<uint8_t> status;  // SetupStatus as an integer
  std::vector<uint8_t> flags;   // RegisterFlag bits

  size_t size() const { return c.size(); }
  void resize(size_t count);
  device::Registers registers(size_t i) const { return {c[i], dpsi[i], psi0[i], n[i], len[i]}; }
  SetupStatus setup_status(size_t i) const { return static_cast<SetupStatus>(status[i]); }
};

// One span's registers by the scalar setup, load_registers(scanline_setup(in), in.n, in.l, f):
// the reference every other path is checked against. `c_saturated` (optional) reports a C
// that did not fit register 1.
device::Registers span_registers(const ScanlineInput& in, const device::Format& f, bool* c_saturated = nullptr);

// The reference: scanline_setup + load_registers per span (scalar double).
void setup_scalar(const SpanBatch& in, const device::Format& f, RegisterBatch& out);

// The batched setup. `out` is resized to in.size(). Throws std::invalid_argument when the
// input arrays differ in length.
void setup_batch(const SpanBatch& in, const device::Format& f, RegisterBatch& out,
                 SimdPath path = SimdPath::automatic);

// A flat span: N1 = N2 and H1 = He exactly (every one-pixel span of a rasterizer, whose two
// ends are the same pixel, and flat shading under a light and a viewer at infinity). The
// batched setup takes blocks of mostly flat spans by a kernel of their own
// (docs/scanline_setup.md#batched-setup), so a producer that hands them over together
// (host::order_for_shading) gets them set up at that kernel's cost.
inline bool is_flat(const ScanlineInput& in) { return in.n1 == in.n2 && in.h1 == in.he; }

// Synthetic spans for tests and benchmarks, shaped like those of meshes and of long spans
// across a highlight: N2 a small to large turn of N1 (10 % equal), H1 near N1 (80 %: inside
// or near the lobe) or anywhere, He = H1 (light and viewer at infinity, 50 %) or a turn of
// it, n over 1..1000 (5 % on 1, 2, 3, 6, 7, 1000), l: 60 % 0..15, 30 % 0..255, 10 % 0..2047,
// Is up to 1.2 (2 % at 2.5: C saturates). Deterministic for a seed.
std::vector<ScanlineInput> random_spans(size_t count, uint64_t seed);
// The same with every l = `len` (synthetic spans of one length: benchmarks).
std::vector<ScanlineInput> random_spans_of_length(size_t count, uint64_t seed, int len);

// How closely two register sets for the same span agree in the pixels they stand for,
// P_i = C cos^n(psi_i) (0 where |psi_i| >= pi/2), decoded from the codes in double.
// `ref` is the reference (the scalar setup's registers); the test of the batch is
//   |P_i - Pref_i| <= rel_tol * Pref_i + 1 LSB   where |psi_i(ref)| <= x_e(n) (the epicenter),
//   |P_i - Pref_i| <= rel_tol * C_ref + 1 LSB    elsewhere,
// with 1 LSB = 2^-c_frac. On spans longer than 15 pixels, pixels where both values are below
// 1 LSB pass without being evaluated (the difference is below 1 LSB), which keeps long spans
// cheap; shorter spans have every pixel evaluated.
struct PixelAgreement {
  double worst = 0.0;              // max |P - Pref| / allowance over the pixels: <= 1 passes
  double max_rel_epicenter = 0.0;  // max |P - Pref| / Pref over epicenter pixels with Pref >= 2^-10
  double max_abs_lsb = 0.0;        // max |P - Pref| in LSB of C
  int worst_pixel = -1;            // where `worst` is reached
  bool ok() const { return worst <= 1.0; }
};
PixelAgreement compare_pixels(const device::Registers& r, const device::Registers& ref, const device::Format& f,
                              double rel_tol = 1e-4);

}  // namespace specular::host
