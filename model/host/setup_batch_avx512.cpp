// SPDX-License-Identifier: Apache-2.0
// AVX-512 (F, DQ, VL) variant of the batched setup kernel (model/host/setup_batch.hpp). This file is
// compiled with -mavx512f -mavx512dq -mavx512vl -mprefer-vector-width=512 (model/CMakeLists.txt) and only called after cpu_has_avx512().
#include "setup_batch_detail.hpp"

#define SETUP_KERNEL_NS avx512_kernels
#include "setup_batch_kernel.inl"
#undef SETUP_KERNEL_NS

namespace specular::host::detail {

size_t setup_batch_avx512(const SpanBatch& in, const device::Format& f, RegisterBatch& out) {
  return run_blocks(in, f, out, avx512_kernels::setup_block, avx512_kernels::flat_block,
                    avx512_kernels::setup_block_regs, avx512_kernels::flat_block_regs);
}

}  // namespace specular::host::detail
