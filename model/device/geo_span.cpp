// SPDX-License-Identifier: Apache-2.0
// The geometry span interface, docs/interfaces.md#geometry-span-interface.
#include "geo_span.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace specular::device {

GeoVec quantize_vec(const glm::dvec3& v, const GeoFormat& g, bool* saturated) {
  bool any = false;
  GeoVec out{};
  for (int i = 0; i < 3; ++i) {
    bool sat = false;
    out[static_cast<size_t>(i)] = static_cast<int32_t>(quantize_fixed(v[i], g.vec_frac, g.vec_min(), g.vec_max(), &sat));
    any = any || sat;
  }
  if (saturated) *saturated = any;
  return out;
}

glm::dvec3 vec_value(const GeoVec& v, const GeoFormat& g) {
  return {std::ldexp(static_cast<double>(v[0]), -g.vec_frac), std::ldexp(static_cast<double>(v[1]), -g.vec_frac),
          std::ldexp(static_cast<double>(v[2]), -g.vec_frac)};
}

GeoSpan quantize_geo(const ScanlineInput& in, const GeoFormat& g, const Format& f, uint32_t tag) {
  GeoSpan s;
  s.n1 = quantize_vec(in.n1, g);
  s.n2 = quantize_vec(in.n2, g);
  s.h1 = quantize_vec(in.h1, g);
  s.he = quantize_vec(in.he, g);
  s.n = quantize_n(in.n, f);
  s.len = quantize_len(in.l, f);
  s.scale = quantize_c(in.is * in.ks * in.norm, f);
  s.tag = g.tag_bits >= 32 ? tag : (tag & ((1U << g.tag_bits) - 1U));
  return s;
}

ScanlineInput geo_input(const GeoSpan& s, const GeoFormat& g, const Format& f) {
  ScanlineInput in;
  in.n1 = vec_value(s.n1, g);
  in.n2 = vec_value(s.n2, g);
  in.h1 = vec_value(s.h1, g);
  in.he = vec_value(s.he, g);
  in.is = c_value(s.scale, f);
  in.ks = 1.0;
  in.norm = 1.0;
  in.n = static_cast<double>(s.n);
  in.l = static_cast<int>(s.len);
  return in;
}

uint64_t pack_vec(const GeoVec& v, const GeoFormat& g) {
  if (g.packed_bits() > 64) throw std::invalid_argument("pack_vec: 3 * vec_bits must be at most 64");
  const uint64_t mask = (uint64_t{1} << g.vec_bits) - 1;
  uint64_t out = 0;
  for (int i = 2; i >= 0; --i) out = (out << g.vec_bits) | (static_cast<uint64_t>(v[static_cast<size_t>(i)]) & mask);
  return out;
}

GeoVec unpack_vec(uint64_t bits, const GeoFormat& g) {
  if (g.packed_bits() > 64) throw std::invalid_argument("unpack_vec: 3 * vec_bits must be at most 64");
  const uint64_t mask = (uint64_t{1} << g.vec_bits) - 1;
  GeoVec out{};
  for (int i = 0; i < 3; ++i) {
    uint64_t u = (bits >> (i * g.vec_bits)) & mask;
    if ((u >> (g.vec_bits - 1)) & 1U) u |= ~mask;
    out[static_cast<size_t>(i)] = static_cast<int32_t>(static_cast<int64_t>(u));
  }
  return out;
}

}  // namespace specular::device
