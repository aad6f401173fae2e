// SPDX-License-Identifier: Apache-2.0
// Harness around one verilated specular_unit: owns the Verilator model (its context and an
// on-demand VCD writer, verilated_model.hpp) and the golden model of the same configuration. A template over the
// Verilator class so that the two policy builds (different --prefix) share one harness.
//
// Cycle convention: in cycle c the harness drives the inputs, evaluates with clk low and
// samples the outputs (the values "in cycle c"), then raises clk (the rising edge that
// ends cycle c). "start_i high in cycle s" therefore means sampled by the edge ending s.
#pragma once

#include "device_model.hpp"

#include "verilated_model.hpp"

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace specular::sim {

// What the harness observed while one line ran.
struct LineRun {
  std::vector<uint32_t> pixels;  // intensity_o of every valid cycle, in order
  int latency = -1;              // first valid cycle - start cycle
  uint64_t cycles = 0;           // start cycle .. first idle cycle (= when the next start is accepted)
  std::string protocol_error;    // empty when the protocol held
};

enum class WriteMode {
  before_start,    // registers written in the cycle before start_i
  with_start,      // registers written in the start cycle itself
  none,            // registers not written: the line reuses the previous values
};

template <class V>
class Harness {
 public:
  Harness(std::string name, device::DeviceModel model)
      : name_(std::move(name)), model_(std::move(model)), vm_(name_) {
    clear_inputs();
    vm_.power_up();
    reset();
  }
  Harness(const Harness&) = delete;
  Harness& operator=(const Harness&) = delete;

  const device::DeviceModel& model() const { return model_; }
  const std::string& name() const { return name_; }
  uint64_t cycle() const { return cycle_; }

  void open_vcd(const std::string& path) { vm_.open_vcd(path, cycle_); }
  void close_vcd() { vm_.close_vcd(); }

  // Asynchronous reset for two cycles, then one idle cycle.
  void reset() {
    top_->rst_ni = 0;
    top_->clk_i = 0;
    top_->eval();
    step();
    step();
    top_->rst_ni = 1;
    step();
  }

  // `cycles` idle clock cycles with no writes and no start.
  void idle(int cycles) {
    clear_inputs();
    for (int c = 0; c < cycles; ++c) step();
  }

  // Runs one line. `poke` (0..1) is the probability, per busy cycle, of driving random
  // register writes and a start pulse, all of which the device must ignore. `gap` idle
  // cycles follow the line; in them busy_o and valid_o must stay low.
  LineRun run_line(const device::Registers& r, WriteMode mode, double poke, int gap, std::mt19937_64& rng) {
    LineRun run;
    auto fail = [&](const std::string& why) {
      if (run.protocol_error.empty())
        run.protocol_error = "cycle " + std::to_string(cycle_) + ": " + why;
    };
    if (mode == WriteMode::before_start) {
      drive_writes(r);
      step();
      if (sampled_busy_) fail("busy_o high while idle before the start");
      if (sampled_valid_) fail("valid_o high while idle");
    }
    clear_inputs();
    if (mode == WriteMode::with_start) drive_writes(r);
    top_->start_i = 1;
    const uint64_t start = cycle_;
    step();
    if (sampled_busy_) fail("busy_o high in the start cycle (device not idle)");
    if (sampled_valid_) fail("valid_o high in the start cycle");
    clear_inputs();

    constexpr uint64_t kMargin = 64;  // clocks beyond the line's pixels: far above any sane latency
    const uint64_t limit = static_cast<uint64_t>(r.len) + kMargin;
    uint64_t last_valid = 0;
    bool seen_valid = false, valid_ended = false;
    std::bernoulli_distribution do_poke(poke);
    for (;;) {
      clear_inputs();
      settle();
      const bool busy = top_->busy_o;
      if (busy && poke > 0 && do_poke(rng)) drive_garbage(rng);
      step();  // samples busy/valid/intensity of this cycle
      const uint64_t c = cycle_ - 1;
      if (c == start + 1 && !sampled_busy_) fail("busy_o not high in the cycle after start_i");
      if (sampled_valid_) {
        if (!sampled_busy_) fail("valid_o high while busy_o low");
        if (valid_ended) fail("valid_o cycles not consecutive");
        if (!seen_valid) run.latency = static_cast<int>(c - start);
        seen_valid = true;
        last_valid = c;
        run.pixels.push_back(sampled_intensity_);
      } else if (seen_valid) {
        valid_ended = true;
      }
      if (!sampled_busy_) {
        run.cycles = c - start;
        if (!seen_valid) fail("busy_o fell before any valid pixel");
        else if (last_valid + 1 != c) fail("busy_o did not fall exactly one cycle after the last valid pixel");
        break;
      }
      if (c - start > limit) {
        fail("line did not end within l + " + std::to_string(kMargin) + " cycles");
        run.cycles = c - start;
        break;
      }
    }
    // The cycle in which busy fell was an idle cycle: the next start may come now. Any
    // further idle cycles must show nothing.
    for (int g = 0; g < gap; ++g) {
      clear_inputs();
      step();
      if (sampled_busy_) fail("busy_o high while idle after the line");
      if (sampled_valid_) fail("valid_o high while idle after the line");
    }
    if (run.pixels.size() != static_cast<size_t>(r.len) + 1)
      fail("expected " + std::to_string(r.len + 1) + " valid pixels, got " + std::to_string(run.pixels.size()));
    return run;
  }

 private:
  void clear_inputs() {
    top_->c_we_i = 0;
    top_->dpsi_we_i = 0;
    top_->psi0_we_i = 0;
    top_->n_we_i = 0;
    top_->len_we_i = 0;
    top_->start_i = 0;
  }
  void drive_writes(const device::Registers& r) {
    const auto& f = model_.format();
    top_->c_we_i = 1;
    top_->c_i = r.c;
    top_->dpsi_we_i = 1;
    top_->dpsi_i = static_cast<uint32_t>(static_cast<uint64_t>(r.dpsi) & ((1ULL << f.angle_bits) - 1));
    top_->psi0_we_i = 1;
    top_->psi0_i = static_cast<uint32_t>(static_cast<uint64_t>(r.psi0) & ((1ULL << f.angle_bits) - 1));
    top_->n_we_i = 1;
    top_->n_i = r.n;
    top_->len_we_i = 1;
    top_->len_i = r.len;
  }
  void drive_garbage(std::mt19937_64& rng) {
    const auto& f = model_.format();
    const uint64_t b = rng();
    top_->c_we_i = b & 1;
    top_->dpsi_we_i = (b >> 1) & 1;
    top_->psi0_we_i = (b >> 2) & 1;
    top_->n_we_i = (b >> 3) & 1;
    top_->len_we_i = (b >> 4) & 1;
    top_->start_i = (b >> 5) & 1;
    const uint64_t d = rng();
    top_->c_i = static_cast<uint32_t>(d & ((1ULL << f.c_bits) - 1));
    top_->dpsi_i = static_cast<uint32_t>((d >> 7) & ((1ULL << f.angle_bits) - 1));
    top_->psi0_i = static_cast<uint32_t>(rng() & ((1ULL << f.angle_bits) - 1));
    top_->n_i = static_cast<uint32_t>((d >> 40) & ((1ULL << f.n_bits) - 1));
    top_->len_i = static_cast<uint32_t>((d >> 50) & static_cast<uint64_t>(f.max_len()));
    settle();
  }
  void settle() {
    top_->clk_i = 0;
    top_->eval();
  }
  // One clock cycle: evaluate with clk low, sample the outputs, rising edge.
  void step() {
    settle();
    sampled_busy_ = top_->busy_o;
    sampled_valid_ = top_->valid_o;
    sampled_intensity_ = top_->intensity_o;
    digest_add(vm_.digest_slot(), uint64_t{sampled_intensity_} | uint64_t{sampled_valid_} << 32 | uint64_t{sampled_busy_} << 33);
    vm_.dump(cycle_, false);
    top_->clk_i = 1;
    top_->eval();
    vm_.dump(cycle_, true);
    ++cycle_;
  }

  std::string name_;
  device::DeviceModel model_;
  VerilatedModel<V> vm_;
  V* const top_ = vm_.top();
  uint64_t cycle_ = 0;
  bool sampled_busy_ = false, sampled_valid_ = false;
  uint32_t sampled_intensity_ = 0;
};

}  // namespace specular::sim
