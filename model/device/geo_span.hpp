// SPDX-License-Identifier: Apache-2.0
// The geometry span interface (docs/interfaces.md#geometry-span-interface): what a
// rasterizer hands a complete shading system in hardware, one span per transfer.
// specular_system (the hardware setup and the device) and phong_stream (per-pixel
// Blinn-Phong) both take it, so both are driven by the same spans and compared on them.
//
// Vectors are three signed fixed-point components of vec_bits with vec_frac fraction
// bits, packed {z, y, x} with x in the low bits. They need not be unit length: a
// rasterizer's interpolated normals are shorter, and each core normalizes. The reference
// of every core is computed in double from the exact values these codes stand for
// (geo_input), so quantizing the geometry is not counted as error.
#pragma once

#include "device_model.hpp"
#include "scanline_setup.hpp"

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>

namespace specular::device {

struct GeoFormat {
  int vec_bits = 18;  // VecBits: each signed component
  int vec_frac = 16;  // VecFrac: fraction bits, so a component is in [-2, 2)
  int tag_bits = 16;  // TagBits

  int64_t vec_min() const { return -(int64_t{1} << (vec_bits - 1)); }
  int64_t vec_max() const { return (int64_t{1} << (vec_bits - 1)) - 1; }
  // Bits of one packed vector port ({z, y, x}).
  int packed_bits() const { return 3 * vec_bits; }
};

using GeoVec = std::array<int32_t, 3>;  // {x, y, z} codes, sign-extended

struct GeoSpan {
  GeoVec n1{}, n2{}, h1{}, he{};  // normals and halfway vectors at the first and last pixel
  uint32_t n = 1;                 // geo_n_i: exponent code (0 or > 1000: every pixel 0)
  uint32_t len = 0;               // geo_len_i: l, the span has l + 1 pixels
  uint32_t scale = 0;             // geo_scale_i: Is * ks * s(n), the format of C
  uint32_t tag = 0;               // geo_tag_i
  bool operator==(const GeoSpan&) const = default;
};

// Round each component to the nearest code (ties away from zero), clamped to the signed
// range; `saturated` (optional) is set when a component was clamped or NaN (mapped to 0).
GeoVec quantize_vec(const glm::dvec3& v, const GeoFormat& g, bool* saturated = nullptr);
// The exact value a vector code stands for.
glm::dvec3 vec_value(const GeoVec& v, const GeoFormat& g);

// A span of the scalar setup's input quantized to the interface: vectors by quantize_vec,
// scale = Is * ks * s(n) by quantize_c, n rounded, l clamped to the counter.
GeoSpan quantize_geo(const ScanlineInput& in, const GeoFormat& g, const Format& f, uint32_t tag = 0);

// The reference input of a geometry span: the exact values of its codes (scale as is with
// ks = norm = 1). The hardware setup is checked against scanline_setup(geo_input(s)), the
// per-pixel Phong core against phong_truth(geo_input(s), i).
ScanlineInput geo_input(const GeoSpan& s, const GeoFormat& g, const Format& f);

// Packed port values: {z, y, x}, each component vec_bits wide, two's complement; and back.
// packed_bits() <= 64 is required (the default 54); throws std::invalid_argument otherwise.
uint64_t pack_vec(const GeoVec& v, const GeoFormat& g);
GeoVec unpack_vec(uint64_t bits, const GeoFormat& g);

}  // namespace specular::device
