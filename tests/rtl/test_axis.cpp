// SPDX-License-Identifier: Apache-2.0
//
// specular_axis (rtl/axi/specular_axis.sv): specular_stream with AXI4-Stream ports, packing
// and renaming only. The test runs a Vaxis and a Vstream (specular_stream alone) in lock
// step on the same random spans, gaps and pixel backpressure: in every cycle tready,
// tvalid, tdata, tlast and tuser must equal span_ready_o, px_valid_o, px_intensity_o,
// px_last_o and px_tag_o, whatever the pad bits of s_axis_span_tdata hold. The pixels are
// also checked bit-exactly against the golden model (DeviceModel::stream), with the AXI4-
// Stream master rules (pixel_sink in axil_driver.hpp). The descriptor layout is the table
// of docs/interfaces.md: {len, n, dpsi, psi0, c}, c in the least significant bits.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"  // anonymous structs in Verilator's public-parameter headers
#include "Vaxis.h"
#include "Vaxis_specular_axis.h"
#include "Vstream.h"
#include "Vstream_specular_stream.h"
#pragma GCC diagnostic pop

#include "axil_driver.hpp"
#include "device_model.hpp"
#include "rom_image.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <deque>
#include <random>
#include <vector>

using namespace specular::rtl_test;
namespace dev = specular::device;

namespace {

using RA = Vaxis_specular_axis;

// Packs a span into the words of s_axis_span_tdata (104 bits: 4 x 32), with `pad` in the
// bits above the descriptor. Bit offsets written out from docs/interfaces.md.
std::array<uint32_t, 4> pack(const dev::Span& s, uint32_t pad) {
  std::array<uint32_t, 4> w{};
  auto put = [&](int lsb, int bits, uint64_t v) {
    for (int b = 0; b < bits; ++b)
      if (v >> b & 1) w[static_cast<size_t>((lsb + b) / 32)] |= 1u << ((lsb + b) % 32);
  };
  put(0, 16, s.reg.c);
  put(16, 32, static_cast<uint32_t>(s.reg.psi0));
  put(48, 32, static_cast<uint32_t>(s.reg.dpsi));
  put(80, 10, s.reg.n);
  put(90, 11, s.reg.len);
  put(101, 3, pad);
  return w;
}

}  // namespace

TEST_CASE("specular_axis layout: TDATA widths and field offsets", "[rtl][axis]") {
  CHECK(static_cast<int>(RA::SpanDataBits) == 104);
  CHECK(static_cast<int>(RA::PxDataBits) == 16);
  CHECK(static_cast<int>(RA::OffC) == 0);
  CHECK(static_cast<int>(RA::OffPsi0) == 16);
  CHECK(static_cast<int>(RA::OffDpsi) == 48);
  CHECK(static_cast<int>(RA::OffN) == 80);
  CHECK(static_cast<int>(RA::OffLen) == 90);
  CHECK(static_cast<int>(RA::TagBits) == 16);
  CHECK(static_cast<int>(RA::CBits) == static_cast<int>(Vstream_specular_stream::CBits));
}

TEST_CASE("specular_axis equals specular_stream in lock step, bit-exact against the golden model", "[rtl][axis]") {
  const double ready_p = GENERATE(1.0, 0.6);
  const double offer_p = GENERATE(1.0, 0.5);
  const specular::BuildConfig& bc = specular::build_config("default");
  const auto model = specular::load_device_model(bc.f, bc.coef_hex(), bc.cos_hex());
  Vaxis ax;
  Vstream st;
  PixelSink<Vaxis> sink(ax, 5);
  sink.ready = ready_p;
  // Settle with rst_ni high, then reset both (sim/stream_harness.hpp).
  ax.rst_ni = st.rst_ni = 1;
  ax.clk_i = st.clk_i = 0;
  ax.s_axis_span_tvalid = st.span_valid_i = 0;
  ax.m_axis_px_tready = st.px_ready_i = 0;
  ax.eval();
  st.eval();
  reset(ax);
  reset(st);

  std::mt19937 rng(static_cast<uint32_t>(ready_p * 10 + offer_p * 100));
  std::uniform_int_distribution<uint32_t> c_any(0, 0xffff), n_any(0, 1023), len_any(0, 12);
  std::uniform_int_distribution<int32_t> psi_any(-(3 << 28), 3 << 28), dpsi_any(-(1 << 24), 1 << 24);
  std::uniform_real_distribution<double> u(0, 1);
  auto new_span = [&](int i) {
    dev::Span s;
    s.reg.c = c_any(rng);
    s.reg.psi0 = psi_any(rng);
    s.reg.dpsi = dpsi_any(rng);
    s.reg.n = i % 6 == 0 ? n_any(rng) : 1 + n_any(rng) % 40;
    s.reg.len = i % 5 == 0 ? 0 : len_any(rng);
    s.tag = static_cast<uint32_t>(rng() & 0xffff);
    return s;
  };

  const int kSpans = 300;
  std::vector<dev::Span> accepted;
  dev::Span cur = new_span(0);
  bool offering = false;
  int mismatches = 0;
  long cycle = 0, expected_pixels = 0;
  for (; cycle < 200000; ++cycle) {
    if (!offering && static_cast<int>(accepted.size()) < kSpans && u(rng) < offer_p) offering = true;
    const auto w = pack(cur, static_cast<uint32_t>(rng() & 7));  // fresh pad bits every cycle
    for (size_t i = 0; i < 4; ++i) ax.s_axis_span_tdata[i] = w[i];
    ax.s_axis_span_tuser = cur.tag;
    ax.s_axis_span_tvalid = offering;
    st.span_valid_i = offering;
    st.span_c_i = cur.reg.c;
    st.span_psi0_i = static_cast<uint32_t>(cur.reg.psi0);
    st.span_dpsi_i = static_cast<uint32_t>(cur.reg.dpsi);
    st.span_n_i = cur.reg.n;
    st.span_len_i = cur.reg.len;
    st.span_tag_i = cur.tag;
    sink.drive();
    st.px_ready_i = ax.m_axis_px_tready;
    ax.clk_i = st.clk_i = 0;
    ax.eval();
    st.eval();
    const bool same = ax.s_axis_span_tready == st.span_ready_o && ax.m_axis_px_tvalid == st.px_valid_o &&
                      ax.m_axis_px_tdata == st.px_intensity_o && ax.m_axis_px_tlast == st.px_last_o &&
                      ax.m_axis_px_tuser == st.px_tag_o;
    if (!same && ++mismatches <= 5) FAIL_CHECK("cycle " << cycle << ": specular_axis differs from specular_stream");
    sink.sample(cycle);
    const bool accept = offering && ax.s_axis_span_tready;
    tick(ax);
    tick(st);
    if (accept) {
      accepted.push_back(cur);
      expected_pixels += cur.reg.len + 1;
      cur = new_span(static_cast<int>(accepted.size()));
      offering = false;
    }
    if (static_cast<int>(accepted.size()) == kSpans && static_cast<long>(sink.got.size()) == expected_pixels) break;
  }
  CHECK(mismatches == 0);
  REQUIRE(static_cast<int>(accepted.size()) == kSpans);
  const auto want = model.stream(accepted);
  REQUIRE(sink.got.size() == want.size());
  int bad = 0;
  for (size_t i = 0; i < want.size(); ++i) {
    const auto& g = sink.got[i];
    if ((g.data != want[i].intensity || g.last != want[i].last || g.user != want[i].tag) && ++bad <= 5)
      FAIL_CHECK("pixel " << i << ": got " << g.data << "/" << g.last << "/" << g.user << ", want " << want[i].intensity
                          << "/" << want[i].last << "/" << want[i].tag);
  }
  CHECK(bad == 0);
  for (const auto& e : sink.errors) FAIL_CHECK("AXI4-Stream: " << e);
  UNSCOPED_INFO("ready " << ready_p << ", offer " << offer_p << ": " << want.size() << " pixels in " << cycle << " cycles");
}
