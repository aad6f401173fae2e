// SPDX-License-Identifier: Apache-2.0
// The device-method span kernel, compiled twice: by span_shade.cpp for the x86-64 baseline
// and by span_shade_avx2.cpp with -mavx2 -mfma. Each includes this file inside its own
// namespace (SPAN_KERNEL_NS), so the two instantiations never merge at link time.
// Written as plain loops that GCC vectorizes (checked with -fopt-info-vec).
#include <algorithm>
#include <cmath>

namespace specular::SPAN_KERNEL_NS {

// b^K by a fixed square-and-multiply chain, unrolled at compile time.
template <int K>
inline float powk(float b) {
  if constexpr (K == 1) {
    return b;
  } else if constexpr (K % 2 == 0) {
    const float t = powk<K / 2>(b);
    return t * t;
  } else {
    return powk<K - 1>(b) * b;
  }
}

// cos u for |u| <= pi/2 by its Taylor series to u^12 (coefficients (-1)^j / (2j)!); the
// omitted tail is below u^14/14! = 6.4e-9 at pi/2.
inline float cos_poly(float u) {
  const float w = u * u;
  return 1.0f + w * (-1.0f / 2 + w * (1.0f / 24 + w * (-1.0f / 720 + w * (1.0f / 40320 +
                w * (-1.0f / 3628800 + w * (1.0f / 479001600))))));
}

template <int K>
void device_kernel(float u0, float du, float cut, int len, float C, float* __restrict out) {
  for (int i = 0; i <= len; ++i) {
    const float u = u0 + static_cast<float>(i) * du;
    const float c = cos_poly(u);
    const float v = C * powk<K>(c > 0.0f ? c : 0.0f);  // both arms computed: a select, no branch
    out[i] = std::abs(u) < cut ? v : 0.0f;
  }
}

// The bank set of DeviceSpanPlan; a k outside it is a programming error (nothing written).
inline void device_dispatch(int k, float u0, float du, float cut, int len, float C, float* out) {
  switch (k) {
#define SPAN_BANK(K) \
  case K: device_kernel<K>(u0, du, cut, len, C, out); break;
    SPAN_BANK(1) SPAN_BANK(2) SPAN_BANK(3) SPAN_BANK(4) SPAN_BANK(5) SPAN_BANK(6) SPAN_BANK(7)
    SPAN_BANK(8) SPAN_BANK(12) SPAN_BANK(16) SPAN_BANK(24) SPAN_BANK(32) SPAN_BANK(48) SPAN_BANK(64)
#undef SPAN_BANK
    default: break;
  }
}

}  // namespace specular::SPAN_KERNEL_NS
