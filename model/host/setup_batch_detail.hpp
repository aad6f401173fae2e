// SPDX-License-Identifier: Apache-2.0
// Internals shared by the two compiled variants of the batched setup (setup_batch.cpp, the
// x86-64 baseline, and setup_batch_avx2.cpp): the block driver that feeds the kernel of
// setup_batch_kernel.inl and turns its double codes into register codes.
#pragma once

#include "setup_batch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace specular::host::detail {

// The register formats the kernel rounds to, as doubles (from device::Format).
struct KernelFormat {
  double c_scale, c_top;                   // 2^c_frac, 2^c_bits - 1
  double angle_scale, angle_lo, angle_hi;  // 2^angle_frac, signed range of angle_bits
  double max_len;                          // counter maximum
  // The single-precision path of short spans (docs/scanline_setup.md#single-precision-short-spans)
  // serves this format: every angle code of |angle| <= 4 rad fits the register and an int32,
  // and C codes up to 2^21 are exact in float.
  bool single;
};

// Spans of l <= kSingleMaxLen go through the single-precision kernel; the bound follows from
// the float error of gamma and lambda (docs/scanline_setup.md#single-precision-short-spans).
inline constexpr int kSingleMaxLen = 255;

// Internal linkage: each variant's translation unit gets its own copy, compiled with its own
// ISA flags (a shared inline copy could be the AVX2 one).
namespace {

KernelFormat kernel_format(const device::Format& f) {
  return {std::ldexp(1.0, f.c_frac),
          std::ldexp(1.0, f.c_bits) - 1.0,
          std::ldexp(1.0, f.angle_frac),
          -std::ldexp(1.0, f.angle_bits - 1),
          std::ldexp(1.0, f.angle_bits - 1) - 1.0,
          static_cast<double>(std::min(f.max_len(), kMaxLen)),
          f.angle_bits <= 32 && 4.0 * std::ldexp(1.0, f.angle_frac) < std::ldexp(1.0, f.angle_bits - 1) - 1.0 &&
              f.c_bits <= 21};
}

}  // namespace

// Output of the block kernel: the register codes as (integral) doubles, flags, and `special`
// (1: the caller runs the scalar setup for this span). Doubles, because a loop that mixes
// them with narrower integer stores does not vectorize; the driver converts afterwards.
struct BlockOut {
  double* c;
  double* psi0;
  double* dpsi;
  double* n;
  double* flags;    // RegisterFlag bits as a double
  double* special;  // 1: not done by the kernel
};

// The register arrays of a block, for kernels that write them directly.
struct RegOut {
  uint32_t* c;
  int64_t* psi0;
  int64_t* dpsi;
  uint32_t* n;
  uint32_t* len;
  uint8_t* status;
  uint8_t* flags;
};

// Status the block driver writes for spans the kernel leaves to the scalar setup.
inline constexpr uint8_t kSpecialStatus = 0xff;

inline constexpr int kBlock = 256;

namespace {

// Writes `count` block results to the register batch: entry j goes to span base + idx[j], or
// to base + j when idx is null (then the loops vectorize). Returns how many are special.
inline int store_block(const SpanBatch& in, RegisterBatch& out, size_t base, const int* idx, int count,
                       const BlockOut& o, bool narrow) {
  int specials = 0;
  if (!idx) {
    uint32_t* __restrict oc = &out.c[base];
    int64_t* __restrict op = &out.psi0[base];
    int64_t* __restrict od = &out.dpsi[base];
    uint32_t* __restrict on = &out.n[base];
    uint32_t* __restrict ol = &out.len[base];
    uint8_t* __restrict os = &out.status[base];
    uint8_t* __restrict of = &out.flags[base];
    const int32_t* __restrict il = &in.l[base];
    // The output arrays are distinct vectors (GCC ignores __restrict on locals).
    if (narrow) {
#pragma GCC ivdep
      for (int i = 0; i < count; ++i) {
        op[i] = static_cast<int32_t>(o.psi0[i]);
        od[i] = static_cast<int32_t>(o.dpsi[i]);
      }
    } else {
#pragma GCC ivdep
      for (int i = 0; i < count; ++i) {
        op[i] = static_cast<int64_t>(o.psi0[i]);
        od[i] = static_cast<int64_t>(o.dpsi[i]);
      }
    }
#pragma GCC ivdep
    for (int i = 0; i < count; ++i) {
      oc[i] = static_cast<uint32_t>(static_cast<int32_t>(o.c[i]));
      on[i] = static_cast<uint32_t>(static_cast<int32_t>(o.n[i]));
      ol[i] = static_cast<uint32_t>(il[i]);
      of[i] = static_cast<uint8_t>(static_cast<int32_t>(o.flags[i]));
      os[i] = o.special[i] != 0.0 ? kSpecialStatus : static_cast<uint8_t>(SetupStatus::ok);
    }
    for (int i = 0; i < count; ++i) specials += o.special[i] != 0.0 ? 1 : 0;
    return specials;
  }
  for (int j = 0; j < count; ++j) {
    const size_t i = base + static_cast<size_t>(idx[j]);
    out.psi0[i] = static_cast<int64_t>(o.psi0[j]);
    out.dpsi[i] = static_cast<int64_t>(o.dpsi[j]);
    out.c[i] = static_cast<uint32_t>(static_cast<int32_t>(o.c[j]));
    out.n[i] = static_cast<uint32_t>(static_cast<int32_t>(o.n[j]));
    out.len[i] = static_cast<uint32_t>(in.l[i]);
    out.flags[i] = static_cast<uint8_t>(static_cast<int32_t>(o.flags[j]));
    out.status[i] = o.special[j] != 0.0 ? kSpecialStatus : static_cast<uint8_t>(SetupStatus::ok);
    specials += o.special[j] != 0.0 ? 1 : 0;
  }
  return specials;
}

// Runs the kernels over the batch in blocks of kBlock spans (block-local arrays stay in L1).
// In a block where at least kFlatNum / kFlatDen of the spans are flat (is_flat, setup_batch.hpp)
// `flat` takes every span and `kernel` the others, gathered; otherwise `kernel` takes the
// whole block in place. Returns how many spans were left to the scalar setup
// (status kSpecialStatus).
template <class Kernel, class Flat, class KernelRegs, class FlatRegs>
size_t run_blocks(const SpanBatch& in, const device::Format& f, RegisterBatch& out, Kernel kernel, Flat flat,
                  KernelRegs kernel_regs, FlatRegs flat_regs) {
  // Measured on the repository scenes: the gathering costs more than the flat kernel saves
  // unless most of the block is flat (dense_mesh: 96 % of its spans; bunny 55 %, spheres 36 %).
  constexpr int kFlatNum = 3, kFlatDen = 4;
  const KernelFormat kf = kernel_format(f);
  alignas(64) double c[kBlock], psi0[kBlock], dpsi[kBlock], n[kBlock], flags[kBlock], special[kBlock];
  const BlockOut o{c, psi0, dpsi, n, flags, special};
  // Gathered inputs of a split block.
  alignas(64) double g[14][kBlock];
  alignas(64) int32_t gl[kBlock];
  alignas(64) int64_t is_flat[kBlock];  // as wide as the doubles compared: one vector mask
  alignas(64) int idx_other[kBlock];
  const bool narrow = f.angle_bits <= 32;  // codes fit int32: a vector conversion
  size_t specials = 0;
  for (size_t b = 0; b < in.size(); b += kBlock) {
    const int count = static_cast<int>(std::min<size_t>(kBlock, in.size() - b));
    const double *n1x = &in.n1x[b], *n1y = &in.n1y[b], *n1z = &in.n1z[b], *n2x = &in.n2x[b], *n2y = &in.n2y[b],
                 *n2z = &in.n2z[b], *h1x = &in.h1x[b], *h1y = &in.h1y[b], *h1z = &in.h1z[b], *hex = &in.hex[b],
                 *hey = &in.hey[b], *hez = &in.hez[b], *nexp = &in.n[b], *scale = &in.scale[b];
    const int32_t* len = &in.l[b];
    int64_t flats = 0;
#pragma GCC ivdep
    for (int i = 0; i < count; ++i) {
      int64_t t = n1x[i] == n2x[i] ? 1 : 0;
      t = n1y[i] == n2y[i] ? t : 0;
      t = n1z[i] == n2z[i] ? t : 0;
      t = h1x[i] == hex[i] ? t : 0;
      t = h1y[i] == hey[i] ? t : 0;
      t = h1z[i] == hez[i] ? t : 0;
      is_flat[i] = t;
      flats += t;
    }
    const bool direct = narrow && kf.single;  // the kernels write the register arrays themselves
    const RegOut r{&out.c[b], &out.psi0[b], &out.dpsi[b], &out.n[b], &out.len[b], &out.status[b], &out.flags[b]};
    if (flats * kFlatDen < count * kFlatNum) {
      if (direct) {
        kernel_regs(n1x, n1y, n1z, n2x, n2y, n2z, h1x, h1y, h1z, hex, hey, hez, nexp, scale, len, count, kf, r);
        int block_specials = 0;
        for (int i = 0; i < count; ++i) block_specials += r.status[i] == kSpecialStatus ? 1 : 0;
        specials += static_cast<size_t>(block_specials);
      } else {
        kernel(n1x, n1y, n1z, n2x, n2y, n2z, h1x, h1y, h1z, hex, hey, hez, nexp, scale, len, count, kf, o);
        specials += static_cast<size_t>(store_block(in, out, b, nullptr, count, o, narrow));
      }
      continue;
    }
    // Mostly flat: the flat kernel takes the whole block in place (for the other spans it
    // computes values that are overwritten below), then the other spans are gathered for the
    // general kernel and their results scattered over those.
    if (direct) {
      flat_regs(n1x, n1y, n1z, h1x, h1y, h1z, nexp, scale, len, count, kf, r);
    } else {
      flat(n1x, n1y, n1z, h1x, h1y, h1z, nexp, scale, len, count, kf, o);
      store_block(in, out, b, nullptr, count, o, narrow);
    }
    int ng = 0;  // branch-free list of the other spans
    for (int i = 0; i < count; ++i) {
      idx_other[ng] = i;
      ng += 1 - static_cast<int>(is_flat[i]);
    }
    if (ng > 0) {
      for (int j = 0; j < ng; ++j) {
        const int i = idx_other[j];
        g[0][j] = n1x[i], g[1][j] = n1y[i], g[2][j] = n1z[i], g[3][j] = n2x[i], g[4][j] = n2y[i], g[5][j] = n2z[i];
        g[6][j] = h1x[i], g[7][j] = h1y[i], g[8][j] = h1z[i], g[9][j] = hex[i], g[10][j] = hey[i], g[11][j] = hez[i];
        g[12][j] = nexp[i], g[13][j] = scale[i], gl[j] = len[i];
      }
      kernel(g[0], g[1], g[2], g[3], g[4], g[5], g[6], g[7], g[8], g[9], g[10], g[11], g[12], g[13], gl, ng, kf, o);
      store_block(in, out, b, idx_other, ng, o, narrow);
    }
    const uint8_t* st = &out.status[b];
    int block_specials = 0;
    for (int i = 0; i < count; ++i) block_specials += st[i] == kSpecialStatus ? 1 : 0;
    specials += static_cast<size_t>(block_specials);
  }
  return specials;
}

}  // namespace

// Each returns the number of spans left to the scalar setup.
size_t setup_batch_baseline(const SpanBatch& in, const device::Format& f, RegisterBatch& out);
size_t setup_batch_avx2(const SpanBatch& in, const device::Format& f, RegisterBatch& out);
size_t setup_batch_avx512(const SpanBatch& in, const device::Format& f, RegisterBatch& out);

}  // namespace specular::host::detail
