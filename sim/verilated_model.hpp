// SPDX-License-Identifier: Apache-2.0
// The Verilator side of a harness (harness.hpp, stream_harness.hpp): one VerilatedContext
// configured with the run's +verilator+ arguments (verilator_runtime.hpp), the model, its
// output digest slot and an on-demand VCD writer (opened only when a trace is asked for).
// The harness owns one and drives its ports through top(); it keeps the cycle count.
//
// VCD time: 10 per clock from the cycle the file was opened in; the sample point of a cycle
// (clk low) at 10 c, its rising edge at 10 c + 5.
#pragma once

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <verilated.h>
#include <verilated_vcd_c.h>
#pragma GCC diagnostic pop
#include "verilator_runtime.hpp"

#include <cstdint>
#include <memory>
#include <string>

namespace specular::sim {

template <class V>
class VerilatedModel {
 public:
  explicit VerilatedModel(const std::string& name) : ctx_(std::make_unique<VerilatedContext>()) {
    ctx_->traceEverOn(true);
    configure_context(*ctx_);
    top_ = std::make_unique<V>(ctx_.get(), name.c_str());
    digest_slot_ = new_digest(top_->modelName());
  }
  ~VerilatedModel() {
    // Verilator 5.006 erases the model's scopes from the thread's current context, which is
    // the last one constructed: make it ours. A model of another harness must not outlive
    // this one on the same thread (its destructor would meet a deleted context).
    Verilated::threadContextp(ctx_.get());
    close_vcd();
    top_->final();
    write_coverage(*ctx_, top_->modelName());
  }
  VerilatedModel(const VerilatedModel&) = delete;
  VerilatedModel& operator=(const VerilatedModel&) = delete;

  V* top() const { return top_.get(); }
  size_t digest_slot() const { return digest_slot_; }

  // Settles once with rst_ni high and clk low, so that the harness's first reset is a
  // falling edge: Verilator takes the values before its first eval as the previous ones (no
  // edge at time 0), and without an edge the asynchronous reset would wait for the first
  // clock while the outputs show the registers' initial values (random under
  // +verilator+rand+reset+2). The RTL's assertions are off for this one evaluation: before
  // the first reset the state is undefined.
  void power_up() {
    top_->rst_ni = 1;
    top_->clk_i = 0;
    ctx_->assertOn(false);
    top_->eval();
    ctx_->assertOn(true);
  }

  // Starts a VCD file at `cycle` (time 0 in the file); replaces an open one.
  void open_vcd(const std::string& path, uint64_t cycle) {
    close_vcd();
    vcd_ = std::make_unique<VerilatedVcdC>();
    top_->trace(vcd_.get(), 99);
    vcd_->open(path.c_str());
    vcd_base_ = cycle;
  }
  void close_vcd() {
    if (vcd_) {
      vcd_->close();
      vcd_.reset();
    }
  }
  // Records the signals of `cycle` at its sample point (clk low) or after its rising edge.
  void dump(uint64_t cycle, bool after_edge) {
    if (vcd_) vcd_->dump(10 * (cycle - vcd_base_) + (after_edge ? 5 : 0));
  }

 private:
  std::unique_ptr<VerilatedContext> ctx_;
  std::unique_ptr<V> top_;
  std::unique_ptr<VerilatedVcdC> vcd_;
  size_t digest_slot_ = 0;
  uint64_t vcd_base_ = 0;
};

}  // namespace specular::sim
