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
};

// Internal linkage: each variant's translation unit gets its own copy, compiled with its own
// ISA flags (a shared inline copy could be the AVX2 one).
namespace {

KernelFormat kernel_format(const device::Format& f) {
  return {std::ldexp(1.0, f.c_frac),
          std::ldexp(1.0, f.c_bits) - 1.0,
          std::ldexp(1.0, f.angle_frac),
          -std::ldexp(1.0, f.angle_bits - 1),
          std::ldexp(1.0, f.angle_bits - 1) - 1.0,
          static_cast<double>(std::min((1 << f.len_bits) - 1, kMaxLen))};
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

// Status the block driver writes for spans the kernel leaves to the scalar setup.
inline constexpr uint8_t kSpecialStatus = 0xff;

inline constexpr int kBlock = 256;

namespace {

// Runs `kernel` over the batch in blocks of kBlock spans (block-local arrays stay in L1).
// Returns how many spans it left to the scalar setup (status kSpecialStatus).
template <class Kernel>
size_t run_blocks(const SpanBatch& in, const device::Format& f, RegisterBatch& out, Kernel kernel) {
  const KernelFormat kf = kernel_format(f);
  alignas(64) double c[kBlock], psi0[kBlock], dpsi[kBlock], n[kBlock], flags[kBlock], special[kBlock];
  const BlockOut o{c, psi0, dpsi, n, flags, special};
  const bool narrow = f.angle_bits <= 32;  // codes fit int32: a vector conversion
  size_t specials = 0;
  for (size_t b = 0; b < in.size(); b += kBlock) {
    const int count = static_cast<int>(std::min<size_t>(kBlock, in.size() - b));
    kernel(&in.n1x[b], &in.n1y[b], &in.n1z[b], &in.n2x[b], &in.n2y[b], &in.n2z[b], &in.h1x[b], &in.h1y[b],
           &in.h1z[b], &in.hex[b], &in.hey[b], &in.hez[b], &in.n[b], &in.scale[b], &in.l[b], count, kf, o);
    uint32_t* __restrict oc = &out.c[b];
    int64_t* __restrict op = &out.psi0[b];
    int64_t* __restrict od = &out.dpsi[b];
    uint32_t* __restrict on = &out.n[b];
    uint32_t* __restrict ol = &out.len[b];
    uint8_t* __restrict os = &out.status[b];
    uint8_t* __restrict of = &out.flags[b];
    const int32_t* __restrict il = &in.l[b];
    // The output arrays are distinct vectors (GCC ignores __restrict on locals).
    if (narrow) {
#pragma GCC ivdep
      for (int i = 0; i < count; ++i) {
        op[i] = static_cast<int32_t>(psi0[i]);
        od[i] = static_cast<int32_t>(dpsi[i]);
      }
    } else {
#pragma GCC ivdep
      for (int i = 0; i < count; ++i) {
        op[i] = static_cast<int64_t>(psi0[i]);
        od[i] = static_cast<int64_t>(dpsi[i]);
      }
    }
#pragma GCC ivdep
    for (int i = 0; i < count; ++i) {
      oc[i] = static_cast<uint32_t>(static_cast<int32_t>(c[i]));
      on[i] = static_cast<uint32_t>(static_cast<int32_t>(n[i]));
      ol[i] = static_cast<uint32_t>(il[i]);
      of[i] = static_cast<uint8_t>(static_cast<int32_t>(flags[i]));
      os[i] = special[i] != 0.0 ? kSpecialStatus : static_cast<uint8_t>(SetupStatus::ok);
    }
    int block_specials = 0;
    for (int i = 0; i < count; ++i) block_specials += special[i] != 0.0 ? 1 : 0;
    specials += static_cast<size_t>(block_specials);
  }
  return specials;
}

}  // namespace

// Each returns the number of spans left to the scalar setup.
size_t setup_batch_baseline(const SpanBatch& in, const device::Format& f, RegisterBatch& out);
size_t setup_batch_avx2(const SpanBatch& in, const device::Format& f, RegisterBatch& out);
size_t setup_batch_avx512(const SpanBatch& in, const device::Format& f, RegisterBatch& out);
bool cpu_has_avx512();  // AVX-512 F, DQ and VL

}  // namespace specular::host::detail
