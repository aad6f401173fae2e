// SPDX-License-Identifier: Apache-2.0
//
// AXI4-Lite master and AXI4-Stream sink over a Verilator model, for the tests of
// rtl/axi/specular_axil.sv and rtl/axi/specular_axis.sv (register map: docs/interfaces.md).
//
// AxilDriver<V> drives the s_axil_* ports of V, one transaction at a time, with
//   - the order of AW and W per write: both in one cycle, AW first or W first, with random
//     gaps (AxilTiming), or a random choice per write;
//   - random backpressure on B and R (bready / rready low with a given probability);
//   - random values on AWADDR, WDATA, WSTRB, ARADDR while their valid is low, and random
//     AWPROT / ARPROT (the slave must ignore all of them).
// Every cycle it checks the slave's side of the protocol:
//   - bvalid, once high, stays high with bresp unchanged until bready (B held under
//     backpressure); rvalid likewise with rdata and rresp;
//   - a B only after both the AW and the W of a write have been accepted, one B per
//     write; an R only after an accepted AR, one R per read.
// Violations are collected in errors(). Cycle convention of rtl_harness.hpp: inputs,
// eval(), outputs, tick(). The hooks before_eval / after_eval run in every cycle (the
// pixel sink below uses them).
#pragma once

#include "rtl_harness.hpp"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace specular::rtl_test {

inline constexpr uint8_t kOkay = 0;
inline constexpr uint8_t kSlverr = 2;

enum class WriteOrder { together, aw_first, w_first, random };

struct AxilTiming {
  WriteOrder order = WriteOrder::together;
  int max_gap = 0;       // valid raised after 0..max_gap idle cycles; AW/W apart by as much
  double bready = 1.0;   // probability that bready is high in a cycle
  double rready = 1.0;   // probability that rready is high in a cycle
};

struct ReadResult {
  uint32_t data = 0;
  uint8_t resp = 0;
};

template <class V>
class AxilDriver {
 public:
  AxilDriver(V& dut, uint32_t seed) : dut_(dut), rng_(seed) { idle(); }

  AxilTiming timing;
  std::function<void()> before_eval;  // e.g. drive m_axis_px_tready
  std::function<void()> after_eval;   // e.g. sample a pixel transfer

  long cycle() const { return cycle_; }
  const std::vector<std::string>& errors() const { return errors_; }
  // Cycle in which the B of the last write was first valid.
  long last_bvalid_cycle() const { return last_bvalid_cycle_; }
  // Transactions completed (B and R transfers).
  long writes() const { return b_done_; }
  long reads() const { return r_done_; }

  // Asynchronous reset (rtl_harness.hpp): the slave forgets every transaction.
  void reset() {
    idle();
    rtl_test::reset(dut_);
    aw_acc_ = w_acc_ = b_done_ = ar_acc_ = r_done_ = 0;
    b_stall_ = r_stall_ = false;
  }

  void idle_cycles(int n) {
    for (int i = 0; i < n; ++i) {
      idle();
      dut_.s_axil_bready = coin(timing.bready);
      dut_.s_axil_rready = coin(timing.rready);
      step([] {});
    }
  }

  // One write; returns BRESP. Throws nothing: a timeout is recorded in errors().
  uint8_t write(uint32_t addr, uint32_t data, uint8_t strb = 0xf) {
    WriteOrder order = timing.order;
    if (order == WriteOrder::random) order = static_cast<WriteOrder>(pick(0, 2));
    const int gap = pick(0, timing.max_gap);
    const int apart = 1 + pick(0, timing.max_gap);
    int aw_at = gap, w_at = gap;
    if (order == WriteOrder::aw_first) w_at += apart;
    if (order == WriteOrder::w_first) aw_at += apart;
    bool aw_done = false, w_done = false, b_seen = false, b_done = false;
    uint8_t resp = 0xff;
    for (int c = 0; !b_done; ++c) {
      if (c > 1000) {
        fail("write to 0x" + hex(addr) + ": no B response in 1000 cycles");
        break;
      }
      idle();
      if (!aw_done && c >= aw_at) {
        dut_.s_axil_awvalid = 1;
        dut_.s_axil_awaddr = addr;
      }
      if (!w_done && c >= w_at) {
        dut_.s_axil_wvalid = 1;
        dut_.s_axil_wdata = data;
        dut_.s_axil_wstrb = strb;
      }
      dut_.s_axil_bready = coin(timing.bready);
      dut_.s_axil_rready = coin(timing.rready);
      step([&] {
        if (dut_.s_axil_awvalid && dut_.s_axil_awready) aw_done = true;
        if (dut_.s_axil_wvalid && dut_.s_axil_wready) w_done = true;
        if (dut_.s_axil_bvalid && !b_seen) {
          b_seen = true;
          last_bvalid_cycle_ = cycle_;
        }
        if (dut_.s_axil_bvalid && dut_.s_axil_bready) {
          resp = dut_.s_axil_bresp;
          b_done = true;
        }
      });
    }
    idle();
    return resp;
  }

  ReadResult read(uint32_t addr) {
    const int gap = pick(0, timing.max_gap);
    bool ar_done = false, r_done = false;
    ReadResult r{0, 0xff};
    for (int c = 0; !r_done; ++c) {
      if (c > 1000) {
        fail("read of 0x" + hex(addr) + ": no R response in 1000 cycles");
        break;
      }
      idle();
      if (!ar_done && c >= gap) {
        dut_.s_axil_arvalid = 1;
        dut_.s_axil_araddr = addr;
      }
      dut_.s_axil_bready = coin(timing.bready);
      dut_.s_axil_rready = coin(timing.rready);
      step([&] {
        if (dut_.s_axil_arvalid && dut_.s_axil_arready) ar_done = true;
        if (dut_.s_axil_rvalid && dut_.s_axil_rready) {
          r = {dut_.s_axil_rdata, static_cast<uint8_t>(dut_.s_axil_rresp)};
          r_done = true;
        }
      });
    }
    idle();
    return r;
  }

  // Low-level: one cycle with the ports as the caller left them (for tests that drive
  // the channels by hand); the protocol checks still run.
  void raw_cycle() { step([] {}); }

 private:
  void idle() {
    dut_.s_axil_awvalid = 0;
    dut_.s_axil_wvalid = 0;
    dut_.s_axil_arvalid = 0;
    // Garbage while not valid: the slave must not take it.
    dut_.s_axil_awaddr = static_cast<uint32_t>(rng_());
    dut_.s_axil_wdata = static_cast<uint32_t>(rng_());
    dut_.s_axil_wstrb = static_cast<uint8_t>(rng_() & 0xf);
    dut_.s_axil_araddr = static_cast<uint32_t>(rng_());
    dut_.s_axil_awprot = static_cast<uint8_t>(rng_() & 7);
    dut_.s_axil_arprot = static_cast<uint8_t>(rng_() & 7);
  }

  template <class Sample>
  void step(Sample sample) {
    if (before_eval) before_eval();
    dut_.clk_i = 0;
    dut_.eval();
    check();
    sample();
    if (after_eval) after_eval();
    const bool aw = dut_.s_axil_awvalid && dut_.s_axil_awready;
    const bool w = dut_.s_axil_wvalid && dut_.s_axil_wready;
    const bool b = dut_.s_axil_bvalid && dut_.s_axil_bready;
    const bool ar = dut_.s_axil_arvalid && dut_.s_axil_arready;
    const bool r = dut_.s_axil_rvalid && dut_.s_axil_rready;
    b_stall_ = dut_.s_axil_bvalid && !dut_.s_axil_bready;
    r_stall_ = dut_.s_axil_rvalid && !dut_.s_axil_rready;
    held_bresp_ = dut_.s_axil_bresp;
    held_rdata_ = dut_.s_axil_rdata;
    held_rresp_ = dut_.s_axil_rresp;
    tick(dut_);
    aw_acc_ += aw;
    w_acc_ += w;
    b_done_ += b;
    ar_acc_ += ar;
    r_done_ += r;
    ++cycle_;
  }

  void check() {
    if (b_stall_) {
      if (!dut_.s_axil_bvalid) fail("bvalid fell without a B transfer");
      else if (dut_.s_axil_bresp != held_bresp_) fail("bresp changed while B was stalled");
    }
    if (r_stall_) {
      if (!dut_.s_axil_rvalid) fail("rvalid fell without an R transfer");
      else if (dut_.s_axil_rdata != held_rdata_ || dut_.s_axil_rresp != held_rresp_)
        fail("rdata/rresp changed while R was stalled");
    }
    if (dut_.s_axil_bvalid && b_done_ >= std::min(aw_acc_, w_acc_))
      fail("bvalid without an accepted AW and W (AW " + std::to_string(aw_acc_) + ", W " +
           std::to_string(w_acc_) + ", B " + std::to_string(b_done_) + ")");
    if (dut_.s_axil_rvalid && r_done_ >= ar_acc_)
      fail("rvalid without an accepted AR (AR " + std::to_string(ar_acc_) + ", R " + std::to_string(r_done_) + ")");
  }

  void fail(const std::string& what) {
    if (errors_.size() < 20) errors_.push_back("cycle " + std::to_string(cycle_) + ": " + what);
  }
  bool coin(double p) { return p >= 1.0 || std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
  int pick(int lo, int hi) { return hi <= lo ? lo : std::uniform_int_distribution<int>(lo, hi)(rng_); }
  static std::string hex(uint32_t v) {
    std::ostringstream s;
    s << std::hex << v;
    return s.str();
  }

  V& dut_;
  std::mt19937 rng_;
  long cycle_ = 0;
  long aw_acc_ = 0, w_acc_ = 0, b_done_ = 0, ar_acc_ = 0, r_done_ = 0;
  long last_bvalid_cycle_ = -1;
  bool b_stall_ = false, r_stall_ = false;
  uint32_t held_bresp_ = 0, held_rdata_ = 0, held_rresp_ = 0;
  std::vector<std::string> errors_;
};

// AXI4-Stream pixel sink on m_axis_px_*: random tready (probability `ready`), the master
// rules checked every cycle (tvalid held and tdata / tlast / tuser stable until the
// transfer), the transfers recorded in order.
struct SinkPixel {
  uint32_t data = 0;
  bool last = false;
  uint32_t user = 0;
  bool operator==(const SinkPixel&) const = default;
};

template <class V>
class PixelSink {
 public:
  PixelSink(V& dut, uint32_t seed) : dut_(dut), rng_(seed) {}
  double ready = 1.0;
  std::vector<SinkPixel> got;
  std::vector<std::string> errors;
  long first_valid_cycle = -1;

  void drive() {
    dut_.m_axis_px_tready = ready >= 1.0 || std::uniform_real_distribution<double>(0, 1)(rng_) < ready;
  }
  void sample(long cycle) {
    const SinkPixel px{static_cast<uint32_t>(dut_.m_axis_px_tdata), dut_.m_axis_px_tlast != 0,
                       static_cast<uint32_t>(dut_.m_axis_px_tuser)};
    if (stalled_) {
      if (!dut_.m_axis_px_tvalid) fail(cycle, "m_axis_px_tvalid fell without a transfer");
      else if (!(px == held_)) fail(cycle, "pixel changed while stalled");
    }
    if (dut_.m_axis_px_tvalid && first_valid_cycle < 0) first_valid_cycle = cycle;
    if (dut_.m_axis_px_tvalid && dut_.m_axis_px_tready) got.push_back(px);
    stalled_ = dut_.m_axis_px_tvalid && !dut_.m_axis_px_tready;
    held_ = px;
  }
  void clear() {
    got.clear();
    stalled_ = false;
    first_valid_cycle = -1;
  }

 private:
  void fail(long cycle, const std::string& what) {
    if (errors.size() < 20) errors.push_back("cycle " + std::to_string(cycle) + ": " + what);
  }
  V& dut_;
  std::mt19937 rng_;
  bool stalled_ = false;
  SinkPixel held_;
};

}  // namespace specular::rtl_test
