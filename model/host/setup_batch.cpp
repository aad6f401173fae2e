// Batched scanline setup (model/host/setup_batch.hpp). Interim version: the scalar loop.
#include "setup_batch.hpp"

#include <stdexcept>

namespace specular::host {

void SpanBatch::clear() {
  for (auto* v : {&n1x, &n1y, &n1z, &n2x, &n2y, &n2z, &h1x, &h1y, &h1z, &hex, &hey, &hez, &n, &scale}) v->clear();
  l.clear();
}

void SpanBatch::reserve(size_t count) {
  for (auto* v : {&n1x, &n1y, &n1z, &n2x, &n2y, &n2z, &h1x, &h1y, &h1z, &hex, &hey, &hez, &n, &scale})
    v->reserve(count);
  l.reserve(count);
}

void SpanBatch::push_back(const ScanlineInput& in) {
  n1x.push_back(in.n1.x), n1y.push_back(in.n1.y), n1z.push_back(in.n1.z);
  n2x.push_back(in.n2.x), n2y.push_back(in.n2.y), n2z.push_back(in.n2.z);
  h1x.push_back(in.h1.x), h1y.push_back(in.h1.y), h1z.push_back(in.h1.z);
  hex.push_back(in.he.x), hey.push_back(in.he.y), hez.push_back(in.he.z);
  n.push_back(in.n);
  scale.push_back(in.is * in.ks * in.norm);
  l.push_back(in.l);
}

ScanlineInput SpanBatch::input(size_t i) const {
  ScanlineInput s;
  s.n1 = {n1x[i], n1y[i], n1z[i]};
  s.n2 = {n2x[i], n2y[i], n2z[i]};
  s.h1 = {h1x[i], h1y[i], h1z[i]};
  s.he = {hex[i], hey[i], hez[i]};
  s.is = scale[i];
  s.n = n[i];
  s.l = l[i];
  return s;
}

void RegisterBatch::resize(size_t count) {
  c.resize(count), psi0.resize(count), dpsi.resize(count), n.resize(count), len.resize(count);
  status.resize(count), flags.resize(count);
}

void setup_scalar(const SpanBatch& in, const device::Format& f, RegisterBatch& out) {
  out.resize(in.size());
  for (size_t i = 0; i < in.size(); ++i) {
    const ScanlineInput s = in.input(i);
    const ScanlineSetup st = scanline_setup(s);
    const device::RegisterLoad ld = device::load_registers(st, s.n, s.l, f);
    out.c[i] = ld.reg.c, out.psi0[i] = ld.reg.psi0, out.dpsi[i] = ld.reg.dpsi;
    out.n[i] = ld.reg.n, out.len[i] = ld.reg.len;
    out.status[i] = static_cast<uint8_t>(st.status);
    out.flags[i] = (ld.c_saturated ? kCSaturated : 0) | (ld.angle_saturated ? kAngleSaturated : 0);
  }
}

void setup_batch(const SpanBatch& in, const device::Format& f, RegisterBatch& out, SimdPath) {
  setup_scalar(in, f, out);
}

}  // namespace specular::host
