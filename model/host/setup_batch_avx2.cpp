// SPDX-License-Identifier: Apache-2.0
// AVX2 + FMA variant of the batched setup kernel (model/host/setup_batch.hpp). This file is
// compiled with -mavx2 -mfma (model/CMakeLists.txt) and only called after cpu_has_avx2().
#include "setup_batch_detail.hpp"

#define SETUP_KERNEL_NS avx2_kernels
#include "setup_batch_kernel.inl"
#undef SETUP_KERNEL_NS

namespace specular::host::detail {

size_t setup_batch_avx2(const SpanBatch& in, const device::Format& f, RegisterBatch& out) {
  return run_blocks(in, f, out, avx2_kernels::setup_block, avx2_kernels::flat_block,
                    avx2_kernels::setup_block_regs, avx2_kernels::flat_block_regs);
}

}  // namespace specular::host::detail
