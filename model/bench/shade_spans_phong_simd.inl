// SPDX-License-Identifier: Apache-2.0
// Stage 3 of the Phong cross-span shader on intrinsic vectors (model/bench/shade_spans.hpp),
// written once for the AVX2 and the AVX-512 variant: each of shade_spans_avx2.cpp and
// shade_spans_avx512.cpp includes it after shade_spans_kernel.inl, inside its own
// SHADE_KERNEL_NS, with an `Ops` struct of its instruction set:
//   V, kWidth                    the vector type and its floats
//   set1, zero, load             broadcast, 0, unaligned load
//   add, sub, mul, div, fmadd    lane-wise arithmetic (fmadd(a, b, c) = a b + c)
//   max                          lane-wise maximum
//   rsqrt_estimate               the hardware estimate of 1 / sqrt(x)
//   pow                          SLEEF's powf of the instruction set (1.0 ulp)
//   keep_positive(c, v)          v where c > 0 (ordered: false for NaN), else 0
//   store(out, v, left)          the first `left` lanes (all when left >= kWidth)

namespace specular::host::SHADE_KERNEL_NS {

template <class Ops>
struct PhongSimd {
  using V = typename Ops::V;

  // 1 / sqrt(x): the hardware estimate and one Newton step (a few ulp).
  static V rsqrt_nr(V x) {
    const V r = Ops::rsqrt_estimate(x);
    const V xrr = Ops::mul(Ops::mul(x, r), r);
    return Ops::mul(Ops::mul(Ops::set1(0.5f), r), Ops::sub(Ops::set1(3.0f), xrr));
  }

  // C c^n where c = dot / sqrt(q) > 0, else 0 (N = 0 or H = 0 give NaN: 0).
  static void out(V dot, V q, V n, V C, float* o, int left) {
    const V zero = Ops::zero();
    const V c = Ops::mul(dot, rsqrt_nr(q));
    Ops::store(o, Ops::keep_positive(c, Ops::mul(C, Ops::pow(Ops::max(c, zero), n))), left);
  }

  static void constant(const PhongBuffers& B, int count, float* o) {
    for (int i = 0; i < count; i += Ops::kWidth)
      out(Ops::load(&B.d[i]), Ops::load(&B.q[i]), Ops::load(&B.n[i]), Ops::load(&B.c[i]), o + i, count - i);
  }

  template <bool Point, bool Persp>
  static void pp(const PhongBuffers& B, int count, const PhongGroup& g, float* o) {
    const V one = Ops::set1(1.0f);
    const V gx = Ops::set1(g.light[0]), gy = Ops::set1(g.light[1]), gz = Ops::set1(g.light[2]);
    const V ex = Ops::set1(g.viewer[0]), ey = Ops::set1(g.viewer[1]), ez = Ops::set1(g.viewer[2]);
    for (int i = 0; i < count; i += Ops::kWidth) {
      const V r = Ops::div(one, Ops::load(&B.den[i]));
      const V px = Ops::mul(Ops::load(&B.px[i]), r);
      const V py = Ops::mul(Ops::load(&B.py[i]), r);
      const V pz = Ops::mul(Ops::load(&B.pz[i]), r);
      V lx = gx, ly = gy, lz = gz;
      if constexpr (Point) {
        lx = Ops::sub(gx, px), ly = Ops::sub(gy, py), lz = Ops::sub(gz, pz);
        const V s = rsqrt_nr(Ops::fmadd(lx, lx, Ops::fmadd(ly, ly, Ops::mul(lz, lz))));
        lx = Ops::mul(lx, s), ly = Ops::mul(ly, s), lz = Ops::mul(lz, s);
      }
      V vx = ex, vy = ey, vz = ez;
      if constexpr (Persp) {
        vx = Ops::sub(ex, px), vy = Ops::sub(ey, py), vz = Ops::sub(ez, pz);
        const V s = rsqrt_nr(Ops::fmadd(vx, vx, Ops::fmadd(vy, vy, Ops::mul(vz, vz))));
        vx = Ops::mul(vx, s), vy = Ops::mul(vy, s), vz = Ops::mul(vz, s);
      }
      const V hx = Ops::add(lx, vx), hy = Ops::add(ly, vy), hz = Ops::add(lz, vz);
      const V nx = Ops::load(&B.nx[i]), ny = Ops::load(&B.ny[i]), nz = Ops::load(&B.nz[i]);
      const V dot = Ops::fmadd(nx, hx, Ops::fmadd(ny, hy, Ops::mul(nz, hz)));
      const V nn = Ops::fmadd(nx, nx, Ops::fmadd(ny, ny, Ops::mul(nz, nz)));
      const V hh = Ops::fmadd(hx, hx, Ops::fmadd(hy, hy, Ops::mul(hz, hz)));
      out(dot, Ops::mul(nn, hh), Ops::load(&B.n[i]), Ops::load(&B.c[i]), o + i, count - i);
    }
  }
};

}  // namespace specular::host::SHADE_KERNEL_NS
