// SPDX-License-Identifier: Apache-2.0
//
// specular_axil (rtl/axi/specular_axil.sv; register map and rules in docs/interfaces.md) over
// the AXI4-Lite driver and pixel sink of axil_driver.hpp, which check the slave's protocol
// in every cycle:
//   - every register's reset value and access type (RO, RW, W1C, WO), SLVERR on unmapped
//     addresses and on writes to read-only registers, WSTRB byte lanes;
//   - a shadow register file under random AW/W orders, gaps and B/R backpressure;
//   - one outstanding write and one outstanding read (ready low until the response);
//   - the error bits, their write-1-to-clear and irq_o;
//   - hundreds of spans pushed through the bus, every pixel bit-exact against the golden
//     model (specular::device::DeviceModel), with tlast and tuser = tag, and the counters;
//   - the latency from PUSH to pixel 0 against BUILD_CORE;
//   - asynchronous reset.
// Two models: Vaxil (the defaults: AddrWidth 8, FifoDepth 4, TagBits 16) and Vaxil_small
// (AddrWidth 12, FifoDepth 5, TagBits 7: a FIFO depth that is not a power of two, a tag
// narrower than its register, addresses above the map).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"  // anonymous structs in Verilator's public-parameter headers
#include "Vaxil.h"
#include "Vaxil_small.h"
#include "Vaxil_small_specular_axil.h"
#include "Vaxil_specular_axil.h"
#include "Vpipeline_axi_default_specular_pipeline.h"
#pragma GCC diagnostic pop

#include "axil_driver.hpp"
#include "device_model.hpp"
#include "rom_image.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <map>
#include <random>
#include <string>
#include <vector>

using namespace specular::rtl_test;
namespace dev = specular::device;

namespace {

// The default configuration's stream latency (sim/specular_pipeline.sv from rtl/prim/specular_pkg.sv).
constexpr uint32_t kStreamLatency = Vpipeline_axi_default_specular_pipeline::StreamLatency;

// Byte offsets (docs/interfaces.md).
enum : uint32_t {
  kId = 0x00,
  kVersion = 0x04,
  kIrqEn = 0x08,
  kErr = 0x0c,
  kStatus = 0x10,
  kSpans = 0x14,
  kPixels = 0x18,
  kSpanC = 0x20,
  kSpanPsi0 = 0x24,
  kSpanDpsi = 0x28,
  kSpanN = 0x2c,
  kSpanLen = 0x30,
  kSpanTag = 0x34,
  kPush = 0x38,
  kBuildCore = 0x40,
  kBuildRom = 0x44,
  kBuildRomBits = 0x48,
  kBuildFmt = 0x4c,
  kBankMaxN = 0x80,
};
constexpr uint32_t kErrBadN = 1, kErrFull = 2;
constexpr uint32_t kStatusFull = 1u << 8, kStatusBusy = 1u << 9, kStatusIrq = 1u << 10;

enum class Access { ro, rw, w1c, wo, none };

struct RegSpec {
  Access access = Access::none;
  uint32_t reset = 0;  // reset value (RO: the constant)
  uint32_t mask = 0;   // RW: the writable bits
};

uint32_t ones(int bits) { return bits >= 32 ? 0xffffffffu : (1u << bits) - 1; }

// The map, written from docs/interfaces.md and device::Format (independent of the RTL's
// own constants), for a model with the default core parameters.
template <class R>
std::map<uint32_t, RegSpec> expected_map() {
  const dev::Format f;
  const int tag_bits = static_cast<int>(R::TagBits);
  const int fifo = static_cast<int>(R::FifoDepth);
  const uint32_t word_bits = static_cast<uint32_t>(f.cos_interp ? f.cos_data_bits + 1 + f.cos_delta_bits : f.cos_data_bits);
  const uint32_t banks = static_cast<uint32_t>(f.banks.size());
  std::map<uint32_t, RegSpec> m;
  m[kId] = {Access::ro, 0x53504543u, 0};  // "SPEC"
  m[kVersion] = {Access::ro, 0x00010000u, 0};
  m[kIrqEn] = {Access::rw, 0, 0x3};
  m[kErr] = {Access::w1c, 0, 0};
  m[kStatus] = {Access::ro, 0, 0};
  m[kSpans] = {Access::ro, 0, 0};
  m[kPixels] = {Access::ro, 0, 0};
  m[kSpanC] = {Access::rw, 0, ones(f.c_bits)};
  m[kSpanPsi0] = {Access::rw, 0, ones(f.angle_bits)};
  m[kSpanDpsi] = {Access::rw, 0, ones(f.angle_bits)};
  m[kSpanN] = {Access::rw, 0, ones(f.n_bits)};
  m[kSpanLen] = {Access::rw, 0, ones(f.len_bits)};
  m[kSpanTag] = {Access::rw, 0, ones(tag_bits)};
  m[kPush] = {Access::wo, 0, 0};
  // The stream's latency (docs/pipeline.md#stage-counts; both benches have the default widths).
  m[kBuildCore] = {Access::ro, kStreamLatency | static_cast<uint32_t>(fifo) << 8 | static_cast<uint32_t>(tag_bits) << 16 |
                                   (f.cos_interp ? 1u << 24 : 0u), 0};
  m[kBuildRom] = {Access::ro, banks | static_cast<uint32_t>(f.cos_addr_bits) << 8 | word_bits << 16, 0};
  m[kBuildRomBits] = {Access::ro, banks * (1u << f.cos_addr_bits) * word_bits, 0};
  m[kBuildFmt] = {Access::ro, static_cast<uint32_t>(f.c_bits) | static_cast<uint32_t>(f.angle_bits) << 8 |
                                  static_cast<uint32_t>(f.n_bits) << 16 | static_cast<uint32_t>(f.len_bits) << 24, 0};
  for (uint32_t j = 0; j < 16; ++j)
    m[kBankMaxN + 4 * j] = {Access::ro, j < banks ? static_cast<uint32_t>(f.bank_max_n[j]) : 0u, 0};
  return m;
}

// One model with its driver and pixel sink; the hooks drive tready and sample pixels.
template <class V>
struct Bench {
  V dut;
  AxilDriver<V> bus;
  PixelSink<V> sink;
  explicit Bench(uint32_t seed) : bus(dut, seed), sink(dut, seed ^ 0x5a5a5a5au) {
    bus.before_eval = [this] { sink.drive(); };
    bus.after_eval = [this] { sink.sample(bus.cycle()); };
    // Settle with rst_ni high so that the reset is a falling edge (sim/stream_harness.hpp).
    dut.rst_ni = 1;
    dut.clk_i = 0;
    dut.m_axis_px_tready = 0;
    dut.eval();
    reset();
  }
  void reset() {
    bus.reset();
    sink.clear();
  }
  void no_protocol_errors() {
    for (const auto& e : bus.errors()) FAIL_CHECK("AXI4-Lite: " << e);
    for (const auto& e : sink.errors) FAIL_CHECK("AXI4-Stream: " << e);
  }
};

uint32_t rd(auto& bus, uint32_t addr) {
  const ReadResult r = bus.read(addr);
  INFO("read 0x" << std::hex << addr);
  CHECK(r.resp == kOkay);
  return r.data;
}

void wr(auto& bus, uint32_t addr, uint32_t data, uint8_t strb = 0xf) {
  INFO("write 0x" << std::hex << addr << " = 0x" << data);
  CHECK(bus.write(addr, data, strb) == kOkay);
}

struct BusSpan {
  uint32_t c = 0, psi0 = 0, dpsi = 0, n = 0, len = 0, tag = 0;
};

template <class B>
void push(B& b, const BusSpan& s) {
  wr(b.bus, kSpanC, s.c);
  wr(b.bus, kSpanPsi0, s.psi0);
  wr(b.bus, kSpanDpsi, s.dpsi);
  wr(b.bus, kSpanN, s.n);
  wr(b.bus, kSpanLen, s.len);
  wr(b.bus, kSpanTag, s.tag);
  wr(b.bus, kPush, 1);
}

dev::Span to_model(const BusSpan& s, int tag_bits) {
  dev::Span m;
  m.reg.c = s.c;
  m.reg.psi0 = static_cast<int32_t>(s.psi0);
  m.reg.dpsi = static_cast<int32_t>(s.dpsi);
  m.reg.n = s.n;
  m.reg.len = s.len;
  m.tag = s.tag & ones(tag_bits);
  return m;
}

const dev::DeviceModel& golden() {
  static const dev::DeviceModel m =
      specular::load_device_model(dev::Format{}, specular::kCoefMinimaxHex, specular::kCosHex);
  return m;
}

// Runs idle cycles until PIXELS reads `want` (or a limit), then checks that the core is idle.
template <class B>
void drain(B& b, uint32_t want) {
  for (int i = 0; i < 20000 && rd(b.bus, kPixels) != want; ++i) b.bus.idle_cycles(8);
  CHECK(rd(b.bus, kPixels) == want);
  const uint32_t st = rd(b.bus, kStatus);
  CHECK((st & 0xff) == 0);
  CHECK((st & kStatusBusy) == 0);
}

template <class B>
void check_pixels(const B& b, const std::vector<dev::StreamPixel>& want) {
  REQUIRE(b.sink.got.size() == want.size());
  int bad = 0;
  for (size_t i = 0; i < want.size(); ++i) {
    const auto& g = b.sink.got[i];
    if (g.data != want[i].intensity || g.last != want[i].last || g.user != want[i].tag) {
      if (++bad <= 5)
        FAIL_CHECK("pixel " << i << ": got (" << g.data << ", last " << g.last << ", tag " << g.user << "), want ("
                            << want[i].intensity << ", last " << want[i].last << ", tag " << want[i].tag << ")");
    }
  }
  CHECK(bad == 0);
}

// Register-map sweep shared by both models: reads every word of the window, writes
// all-ones and zero to every register but PUSH, checks the responses and the read-back.
template <class V, class R>
void sweep_map(Bench<V>& b) {
  auto map = expected_map<R>();
  const uint32_t top = 1u << static_cast<int>(R::AddrWidth);
  std::vector<uint32_t> addrs;
  for (uint32_t a = 0; a < 0x100; a += 4) addrs.push_back(a);
  for (uint32_t a = 0x100; a < top; a += 0x104) addrs.push_back(a);  // beyond the map (AddrWidth > 8)
  for (uint32_t a : addrs) {
    const auto it = map.find(a);
    const RegSpec spec = it == map.end() ? RegSpec{} : it->second;
    INFO("address 0x" << std::hex << a);
    const ReadResult r0 = b.bus.read(a);
    if (spec.access == Access::none) {
      CHECK(r0.resp == kSlverr);
      CHECK(r0.data == 0);
      CHECK(b.bus.write(a, 0xffffffffu) == kSlverr);
      continue;
    }
    CHECK(r0.resp == kOkay);
    CHECK(r0.data == spec.reset);
    // Address bits [1:0] are ignored.
    CHECK(b.bus.read(a | 3).data == spec.reset);
    if (spec.access == Access::wo) continue;  // PUSH: its own test
    const uint8_t resp = b.bus.write(a, 0xffffffffu);
    const uint32_t after = b.bus.read(a).data;
    switch (spec.access) {
      case Access::ro:
        CHECK(resp == kSlverr);
        CHECK(after == spec.reset);
        break;
      case Access::rw:
        CHECK(resp == kOkay);
        CHECK(after == spec.mask);
        CHECK(b.bus.write(a, 0) == kOkay);
        CHECK(b.bus.read(a).data == 0);
        break;
      case Access::w1c:
        CHECK(resp == kOkay);
        CHECK(after == 0);  // nothing set, ones clear nothing
        break;
      default:
        break;
    }
  }
}

}  // namespace

TEST_CASE("specular_axil parameters: the core's defaults, AddrWidth 8, FifoDepth 4", "[rtl][axil]") {
  using R = Vaxil_specular_axil;
  const dev::Format f;
  CHECK(static_cast<int>(R::CBits) == f.c_bits);
  CHECK(static_cast<int>(R::AngleBits) == f.angle_bits);
  CHECK(static_cast<int>(R::NBits) == f.n_bits);
  CHECK(static_cast<int>(R::LenBits) == f.len_bits);
  CHECK(static_cast<int>(R::CosAddrBits) == f.cos_addr_bits);
  CHECK(static_cast<int>(R::NumBanks) == static_cast<int>(f.banks.size()));
  CHECK(static_cast<int>(R::TagBits) == 16);
  CHECK(static_cast<int>(R::AddrWidth) == 8);
  CHECK(static_cast<int>(R::FifoDepth) == 4);
  CHECK(static_cast<int>(Vaxil_small_specular_axil::AddrWidth) == 12);
  CHECK(static_cast<int>(Vaxil_small_specular_axil::FifoDepth) == 5);
  CHECK(static_cast<int>(Vaxil_small_specular_axil::TagBits) == 7);
}

TEST_CASE("specular_axil register map: reset values, access types, SLVERR", "[rtl][axil]") {
  const auto order = GENERATE(WriteOrder::together, WriteOrder::aw_first, WriteOrder::w_first);
  SECTION("default model") {
    Bench<Vaxil> b(11);
    b.bus.timing = {order, 2, 0.5, 0.5};
    sweep_map<Vaxil, Vaxil_specular_axil>(b);
    b.no_protocol_errors();
  }
  SECTION("AddrWidth 12, FifoDepth 5, TagBits 7") {
    Bench<Vaxil_small> b(12);
    b.bus.timing = {order, 2, 0.5, 0.5};
    sweep_map<Vaxil_small, Vaxil_small_specular_axil>(b);
    b.no_protocol_errors();
  }
}

TEST_CASE("specular_axil WSTRB: byte lanes of RW, W1C and PUSH", "[rtl][axil]") {
  Bench<Vaxil> b(21);
  b.bus.timing = {WriteOrder::random, 1, 0.6, 0.6};
  wr(b.bus, kSpanPsi0, 0x11223344u);
  wr(b.bus, kSpanPsi0, 0xaabbccddu, 0x5);  // lanes 0 and 2
  CHECK(rd(b.bus, kSpanPsi0) == 0x11bb33ddu);
  wr(b.bus, kSpanPsi0, 0xffffffffu, 0x8);
  CHECK(rd(b.bus, kSpanPsi0) == 0xffbb33ddu);
  wr(b.bus, kSpanPsi0, 0, 0x0);  // no lane: OKAY, nothing changes
  CHECK(rd(b.bus, kSpanPsi0) == 0xffbb33ddu);
  wr(b.bus, kSpanC, 0xffffffffu, 0x4);  // lane 2 is above C's 16 bits
  CHECK(rd(b.bus, kSpanC) == 0);
  wr(b.bus, kSpanC, 0x1234, 0x2);
  CHECK(rd(b.bus, kSpanC) == 0x1200);
  // PUSH without a lane pushes nothing; ERR clears only in strobed lanes.
  wr(b.bus, kSpanN, 0);
  wr(b.bus, kPush, 1, 0x0);
  CHECK(rd(b.bus, kSpans) == 0);
  CHECK((rd(b.bus, kStatus) & 0xff) == 0);
  wr(b.bus, kPush, 0, 0x8);  // any lane pushes, whatever the data
  CHECK(rd(b.bus, kSpans) == 1);
  CHECK(rd(b.bus, kErr) == kErrBadN);
  wr(b.bus, kErr, 0xffffffffu, 0xe);  // the error bits are in lane 0
  CHECK(rd(b.bus, kErr) == kErrBadN);
  wr(b.bus, kErr, 0xffffffffu, 0x1);
  CHECK(rd(b.bus, kErr) == 0);
  b.bus.idle_cycles(40);
  b.no_protocol_errors();
}

TEST_CASE("specular_axil random AW/W orders and B/R backpressure against a shadow map", "[rtl][axil]") {
  const auto order = GENERATE(WriteOrder::together, WriteOrder::aw_first, WriteOrder::w_first, WriteOrder::random);
  const double bready = GENERATE(1.0, 0.25);
  Bench<Vaxil> b(100 + static_cast<uint32_t>(order) * 7 + (bready < 1 ? 1 : 0));
  b.bus.timing = {order, 3, bready, bready < 1 ? 0.3 : 1.0};
  auto map = expected_map<Vaxil_specular_axil>();
  std::map<uint32_t, uint32_t> shadow;
  for (const auto& [a, s] : map) shadow[a] = s.reset;
  std::mt19937 rng(7 + static_cast<uint32_t>(order));
  int writes = 0, reads = 0, errors = 0;
  for (int op = 0; op < 1500; ++op) {
    const uint32_t a = 4 * (rng() % 64);
    const auto it = map.find(a);
    const Access acc = it == map.end() ? Access::none : it->second.access;
    INFO("op " << op << ", address 0x" << std::hex << a);
    if (rng() % 2 && acc != Access::wo) {
      const uint32_t data = static_cast<uint32_t>(rng());
      const uint8_t strb = static_cast<uint8_t>(rng() % 16);
      const uint8_t resp = b.bus.write(a, data, strb);
      ++writes;
      if (acc == Access::rw) {
        CHECK(resp == kOkay);
        uint32_t v = shadow[a];
        for (int l = 0; l < 4; ++l)
          if (strb >> l & 1) v = (v & ~(0xffu << 8 * l)) | (data & 0xffu << 8 * l);
        shadow[a] = v & map[a].mask;
      } else if (acc == Access::w1c) {
        CHECK(resp == kOkay);
      } else {
        CHECK(resp == kSlverr);
        ++errors;
      }
    } else {
      const ReadResult r = b.bus.read(a);
      ++reads;
      if (acc == Access::none) {
        CHECK(r.resp == kSlverr);
        CHECK(r.data == 0);
      } else {
        CHECK(r.resp == kOkay);
        CHECK(r.data == shadow[a]);
      }
    }
  }
  CHECK(writes > 500);
  CHECK(reads > 500);
  CHECK(errors > 100);
  CHECK(b.bus.writes() == writes);
  CHECK(b.bus.reads() == reads);
  b.no_protocol_errors();
}

TEST_CASE("specular_axil: one outstanding write and one outstanding read", "[rtl][axil]") {
  Bench<Vaxil> b(31);
  auto& d = b.dut;
  auto idle = [&] {
    d.s_axil_awvalid = d.s_axil_wvalid = d.s_axil_arvalid = 0;
  };
  // AW alone: accepted, then awready stays low and no B comes until W.
  idle();
  d.s_axil_bready = 1;
  d.s_axil_rready = 1;
  d.s_axil_awvalid = 1;
  d.s_axil_awaddr = kSpanC;
  d.eval();
  CHECK(d.s_axil_awready == 1);
  b.bus.raw_cycle();
  idle();
  for (int i = 0; i < 5; ++i) {
    d.eval();
    CHECK(d.s_axil_awready == 0);
    CHECK(d.s_axil_wready == 1);
    CHECK(d.s_axil_bvalid == 0);
    b.bus.raw_cycle();
  }
  // W: the write happens, B follows; with bready low B holds and no channel is ready.
  d.s_axil_bready = 0;
  d.s_axil_wvalid = 1;
  d.s_axil_wdata = 0x4321;
  d.s_axil_wstrb = 0xf;
  b.bus.raw_cycle();
  idle();
  int wait = 0;
  for (d.eval(); !d.s_axil_bvalid && wait < 5; d.eval(), ++wait) b.bus.raw_cycle();
  REQUIRE(d.s_axil_bvalid == 1);
  CHECK(d.s_axil_bresp == kOkay);
  // Two reads while the B waits: AR in cycles 0 and 2, R held in 1 and 3 and taken there.
  for (int i = 0; i < 5; ++i) {
    d.eval();
    CHECK(d.s_axil_bvalid == 1);
    CHECK(d.s_axil_awready == 0);
    CHECK(d.s_axil_wready == 0);
    // A read is independent of the pending B.
    CHECK(d.s_axil_arready == (i == 0 ? 1 : (i % 2 == 0)));
    if (i == 0) {
      d.s_axil_arvalid = 1;
      d.s_axil_araddr = kSpanC;
      d.s_axil_rready = 0;
    } else {
      d.s_axil_arvalid = 0;
      d.s_axil_rready = i % 2;  // R taken in cycles 1 and 3
      if (i % 2) {
        CHECK(d.s_axil_rvalid == 1);
        CHECK(d.s_axil_rdata == 0x4321);
      }
      if (i == 2) {  // a second read while none is pending
        d.s_axil_arvalid = 1;
      }
    }
    b.bus.raw_cycle();
  }
  idle();
  d.s_axil_rready = 1;
  d.s_axil_bready = 1;
  b.bus.raw_cycle();
  d.eval();
  CHECK(d.s_axil_bvalid == 0);
  CHECK(d.s_axil_awready == 1);
  CHECK(d.s_axil_wready == 1);
  b.bus.idle_cycles(3);
  CHECK(rd(b.bus, kSpanC) == 0x4321);
  b.no_protocol_errors();
}

TEST_CASE("specular_axil error bits, write-1-to-clear and irq_o", "[rtl][axil]") {
  Bench<Vaxil> b(41);
  b.bus.timing = {WriteOrder::random, 1, 0.7, 0.7};
  b.sink.ready = 1.0;
  auto irq_after = [&] {
    b.bus.idle_cycles(1);  // irq_o is a register: set at the edge of the write
    return static_cast<int>(b.dut.irq_o);
  };
  SECTION("BAD_N: n = 0 or above the last bank's maximum, the span still runs") {
    const uint32_t n = GENERATE(0u, 1001u, 1023u);
    push(b, BusSpan{0x4000, 0, 0, n, 2, 0x55});
    CHECK(rd(b.bus, kErr) == kErrBadN);
    CHECK(irq_after() == 0);  // not enabled
    CHECK((rd(b.bus, kStatus) & kStatusIrq) == 0);
    wr(b.bus, kIrqEn, kErrBadN);
    CHECK(irq_after() == 1);
    CHECK((rd(b.bus, kStatus) & kStatusIrq) != 0);
    wr(b.bus, kErr, kErrFull);  // the other bit: no effect
    CHECK(rd(b.bus, kErr) == kErrBadN);
    CHECK(irq_after() == 1);
    wr(b.bus, kErr, kErrBadN);
    CHECK(rd(b.bus, kErr) == 0);
    CHECK(irq_after() == 0);
    drain(b, 3);
    REQUIRE(b.sink.got.size() == 3);
    for (const auto& p : b.sink.got) CHECK(p.data == 0);
    CHECK(b.sink.got[2].last);
    CHECK(b.sink.got[0].user == 0x55);
    CHECK(rd(b.bus, kSpans) == 1);
  }
  SECTION("n = 1 and n = 1000 are valid") {
    const uint32_t n = GENERATE(1u, 1000u);
    push(b, BusSpan{0x4000, 0, 0, n, 0, 1});
    CHECK(rd(b.bus, kErr) == 0);
    drain(b, 1);
  }
  SECTION("PUSH_FULL: the FIFO fills while the pixel side stalls; the extra span is dropped") {
    b.sink.ready = 0.0;
    wr(b.bus, kIrqEn, kErrFull);
    std::vector<BusSpan> spans;
    // Span 0 enters the core and stalls it (2048 pixels); spans 1..4 fill the FIFO.
    for (uint32_t i = 0; i < 5; ++i) {
      spans.push_back(BusSpan{0x7000 - 0x100 * i, static_cast<uint32_t>(-(1 << 27)), 1 << 16, 20 + i, 2047, 0x100 + i});
      push(b, spans.back());
    }
    uint32_t st = rd(b.bus, kStatus);
    CHECK((st & 0xff) == 4);
    CHECK((st & kStatusFull) != 0);
    CHECK((st & kStatusBusy) != 0);
    CHECK(rd(b.bus, kErr) == 0);
    CHECK(irq_after() == 0);
    push(b, BusSpan{0x1111, 0, 0, 5, 3, 0x999});  // dropped
    CHECK(rd(b.bus, kErr) == kErrFull);
    CHECK(irq_after() == 1);
    CHECK(rd(b.bus, kSpans) == 5);
    CHECK((rd(b.bus, kStatus) & 0xff) == 4);
    // Drain: every pixel of the five spans, none of the dropped one.
    b.sink.ready = 0.8;
    drain(b, 5 * 2048);
    std::vector<dev::Span> ms;
    for (const auto& s : spans) ms.push_back(to_model(s, 16));
    check_pixels(b, golden().stream(ms));
    CHECK(irq_after() == 1);  // sticky
    wr(b.bus, kErr, kErrFull | kErrBadN);
    CHECK(irq_after() == 0);
  }
  b.no_protocol_errors();
}

TEST_CASE("specular_axil: PUSH to pixel 0 is BUILD_CORE's latency", "[rtl][axil]") {
  Bench<Vaxil> b(51);
  const uint32_t latency = rd(b.bus, kBuildCore) & 0xff;
  CHECK(latency == kStreamLatency);
  // PUSH takes effect at the edge that ends the write; B is valid in the next cycle, at
  // whose end the span enters the FIFO; the core accepts it in the cycle after that, and
  // pixel 0 follows Latency cycles later (docs/interfaces.md).
  push(b, BusSpan{0x4000, 0, 0, 10, 5, 3});
  const long b_cycle = b.bus.last_bvalid_cycle();
  b.bus.idle_cycles(40);
  CHECK(b.sink.first_valid_cycle - b_cycle == 1 + static_cast<long>(latency));
  CHECK(b.sink.got.size() == 6);
  b.no_protocol_errors();
}

template <class V, class R>
void random_spans_through_the_bus(uint32_t seed, int count) {
  Bench<V> b(seed);
  b.bus.timing = {WriteOrder::random, 2, 0.5, 0.5};
  b.sink.ready = 0.7;
  const int tag_bits = static_cast<int>(R::TagBits);
  const uint32_t fifo = static_cast<uint32_t>(R::FifoDepth);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<uint32_t> c_any(0, 0xffff), n_any(0, 1023), len_any(0, 40);
  std::uniform_int_distribution<int32_t> psi_any(-(3 << 28), 3 << 28), dpsi_any(-(1 << 24), 1 << 24);
  std::vector<dev::Span> ms;
  bool any_bad_n = false;
  uint32_t pixels = 0;
  int full_waits = 0;
  for (int i = 0; i < count; ++i) {
    BusSpan s{c_any(rng), static_cast<uint32_t>(psi_any(rng)), static_cast<uint32_t>(dpsi_any(rng)),
              i % 8 == 0 ? n_any(rng) : 1 + n_any(rng) % 40, len_any(rng), static_cast<uint32_t>(rng())};
    any_bad_n |= s.n == 0 || s.n > 1000;
    // Wait for room (STATUS level), as a driver would.
    while ((rd(b.bus, kStatus) & 0xff) >= fifo) {
      ++full_waits;
      b.bus.idle_cycles(4);
    }
    push(b, s);
    ms.push_back(to_model(s, tag_bits));
    pixels += s.len + 1;
  }
  drain(b, pixels);
  check_pixels(b, golden().stream(ms));
  CHECK(rd(b.bus, kSpans) == static_cast<uint32_t>(count));
  CHECK(rd(b.bus, kErr) == (any_bad_n ? kErrBadN : 0u));
  UNSCOPED_INFO(count << " spans, " << pixels << " pixels, " << b.bus.writes() << " writes, " << b.bus.reads()
                      << " reads, " << full_waits << " waits for FIFO room, " << b.bus.cycle() << " cycles");
  b.no_protocol_errors();
}

TEST_CASE("specular_axil: 400 random spans through the bus, bit-exact against the golden model", "[rtl][axil]") {
  random_spans_through_the_bus<Vaxil, Vaxil_specular_axil>(2026, 400);
}

TEST_CASE("specular_axil FifoDepth 5, TagBits 7: 150 random spans, bit-exact", "[rtl][axil]") {
  random_spans_through_the_bus<Vaxil_small, Vaxil_small_specular_axil>(77, 150);
}

TEST_CASE("specular_axil asynchronous reset clears registers, FIFO and the core", "[rtl][axil]") {
  Bench<Vaxil> b(61);
  b.sink.ready = 0.0;
  wr(b.bus, kIrqEn, 3);
  for (int i = 0; i < 3; ++i) push(b, BusSpan{0x4000, 0, 0, 0, 100, 9});  // BAD_N, fills the core
  CHECK(rd(b.bus, kErr) == kErrBadN);
  b.bus.idle_cycles(30);
  CHECK(b.dut.m_axis_px_tvalid == 1);
  CHECK(b.dut.irq_o == 1);
  b.reset();
  b.dut.eval();
  CHECK(b.dut.m_axis_px_tvalid == 0);
  CHECK(b.dut.irq_o == 0);
  b.sink.ready = 1.0;
  b.bus.idle_cycles(50);
  CHECK(b.sink.got.empty());
  const auto map = expected_map<Vaxil_specular_axil>();
  for (const auto& [a, s] : map) {
    INFO("address 0x" << std::hex << a);
    CHECK(rd(b.bus, a) == s.reset);
  }
  b.no_protocol_errors();
}
