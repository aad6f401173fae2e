// SPDX-License-Identifier: Apache-2.0
// Harness around one verilated specular_stream: owns the Verilator model (its context and
// an on-demand VCD writer, verilated_model.hpp), the golden model of the same configuration
// and a scoreboard.
//
// Cycle convention (as harness.hpp): in cycle c the harness drives the inputs, evaluates
// with clk low and samples the outputs, then raises clk. A transfer happens in cycle c when
// valid and ready are both high in it; it takes effect at the edge that ends cycle c.
// span_ready_o depends combinationally on px_ready_i, so px_ready_i is driven first.
//
// The scoreboard: every accepted span appends its golden pixels (DeviceModel::stream_span)
// to a queue; every pixel transfer pops the front and must equal it in intensity, last
// and tag. An asynchronous reset clears the queue: everything in flight is dropped.
//
// run_back_to_back is the scene stage's fast path: spans back to back, px_ready_i always
// high, every transfer recorded (StreamRun) and compared with the golden model by the
// caller, on another thread while the run goes on or afterwards, so that a clock costs the
// two evaluations and little else.
#pragma once

#include "device_model.hpp"

#include "verilated_model.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace specular::sim {

struct StreamCounters {
  uint64_t cycles = 0;
  uint64_t spans_accepted = 0;
  uint64_t pixels = 0;          // pixel transfers checked against the golden model
  uint64_t mismatches = 0;      // intensity differs
  uint64_t protocol_errors = 0; // tag, last, order, handshake rule, pixel without a span
  uint64_t resets = 0;
  uint64_t dropped = 0;         // golden pixels dropped by resets
  std::vector<std::string> first_errors;  // at most 10 messages
};

// What run_back_to_back saw: every pixel transfer in order, every span's accept cycle. The
// arrays are sized before the run and never reallocated, and the run publishes how far it
// got (progress: pixels recorded, with kDone set at the end), so that another thread may
// read the entries below the published count while the run goes on.
struct StreamRun {
  static constexpr uint64_t kDone = 1ULL << 63;
  std::vector<uint32_t> intensity, tag;
  std::vector<uint8_t> last;
  std::vector<uint64_t> pixel_cycle;   // cycle of each transfer
  std::vector<uint64_t> accept_cycle;  // cycle in which each span was accepted
  std::atomic<uint64_t> progress{0};   // pixels recorded (release), | kDone when the run ended
  uint64_t pixels = 0, spans = 0;      // recorded, final (transfers beyond the arrays are errors)
  uint64_t first_accept = 0, last_transfer = 0;
  uint64_t cycles() const { return pixels ? last_transfer - first_accept + 1 : 0; }
  // Blocks until at least `count` pixels are recorded or the run ended; returns how many are.
  uint64_t wait_for(uint64_t count) const {
    uint64_t p = progress.load(std::memory_order_acquire);
    while ((p & ~kDone) < count && !(p & kDone)) {
      progress.wait(p, std::memory_order_acquire);
      p = progress.load(std::memory_order_acquire);
    }
    return p & ~kDone;
  }
};

template <class V>
class StreamHarness {
 public:
  StreamHarness(std::string name, device::DeviceModel model, int tag_bits)
      : name_(std::move(name)), model_(std::move(model)), tag_mask_((1ULL << tag_bits) - 1), vm_(name_) {
    top_->span_valid_i = 0;
    top_->px_ready_i = 0;
    vm_.power_up();
    reset(2);
  }
  StreamHarness(const StreamHarness&) = delete;
  StreamHarness& operator=(const StreamHarness&) = delete;

  const device::DeviceModel& model() const { return model_; }
  StreamCounters& counters() { return cnt_; }
  bool empty() const { return expect_.empty(); }
  size_t owed() const { return expect_.size(); }

  void open_vcd(const std::string& path) { vm_.open_vcd(path, cycle_); }
  void close_vcd() { vm_.close_vcd(); }

  // Asynchronous reset held for `cycles` clocks: drops everything in flight. While in
  // reset the core must show no valid pixel.
  void reset(int cycles) {
    top_->rst_ni = 0;
    top_->clk_i = 0;
    top_->eval();
    cnt_.dropped += expect_.size();
    expect_.clear();
    stalled_ = false;
    for (int c = 0; c < cycles; ++c) {
      top_->eval();
      if (top_->px_valid_o) error("px_valid_o high during reset");
      edge();
    }
    top_->rst_ni = 1;
    top_->eval();
    ++cnt_.resets;
  }

  // One cycle. `offer` (may be null) is the span offered on span_valid_i; returns true when
  // it was accepted at this edge. The caller keeps offering the same span until accepted
  // (the AXI source rule). `ready` drives px_ready_i. `transferred` tells whether a pixel
  // left at this edge.
  bool cycle(const device::Span* offer, bool ready, bool* transferred = nullptr) {
    top_->px_ready_i = ready;
    top_->span_valid_i = offer != nullptr;
    if (offer) drive_span(*offer);
    top_->clk_i = 0;
    top_->eval();
    // Handshake rules checked on the sampled outputs.
    const bool pv = top_->px_valid_o;
    const device::StreamPixel px{top_->px_intensity_o, top_->px_last_o != 0,
                                 static_cast<uint32_t>(top_->px_tag_o & tag_mask_)};
    if (stalled_) {
      if (!pv) error("px_valid_o fell without a transfer");
      else if (!(px == held_)) error("pixel changed while stalled");
    }
    if (!pv && (top_->px_intensity_o != 0 || top_->px_last_o)) error("px_intensity_o/px_last_o not 0 while px_valid_o is low");
    const bool span_fire = offer && top_->span_ready_o;
    // Every output port, every cycle (the tag included while px_valid_o is low).
    digest_add(vm_.digest_slot(), uint64_t{top_->px_intensity_o} | uint64_t{top_->px_tag_o} << 16 | uint64_t{top_->px_last_o} << 48 |
               uint64_t{pv} << 49 | uint64_t{top_->span_ready_o} << 50);
    const bool px_fire = pv && ready;
    if (px_fire) check_pixel(px);
    stalled_ = pv && !ready;
    held_ = px;
    vm_.dump(cycle_, false);
    edge();
    if (span_fire) {
      ++cnt_.spans_accepted;
      // The intensities are the golden model's; the count, the last flag and the tag follow
      // from the span as driven (l + 1 pixels of the span's tag, last on pixel l;
      // docs/interfaces.md), not from the model.
      std::vector<device::StreamPixel> tmp;
      model_.stream_span(*offer, tmp);
      const uint32_t len = offer->reg.len & static_cast<uint32_t>(model_.format().max_len());
      const uint32_t tag = static_cast<uint32_t>(offer->tag & tag_mask_);
      if (tmp.size() != size_t{len} + 1) error("the golden model's span has " + std::to_string(tmp.size()) +
                                               " pixels, the span " + std::to_string(len + 1));
      for (uint32_t i = 0; i <= len; ++i)
        expect_.push_back({i < tmp.size() ? tmp[i].intensity : 0u, i == len, tag});
    }
    if (transferred) *transferred = px_fire;
    return span_fire;
  }

  // Spans back to back (span_valid_i high whenever one is pending, each span held until
  // accepted) with px_ready_i always high, then 8 idle clocks in which nothing may come out.
  // `pixels` is what the spans hold (sum of l + 1): the run ends when that many transfers
  // happened. Every transfer is recorded in `run` (a fresh one), not checked: the caller
  // compares it with the golden model (tag, last, count, order, intensity), possibly on
  // another thread as the progress comes in. The handshake rules that apply here are checked
  // (nothing but zeros while px_valid_o is low, no pixel after the last span's); violations
  // count as protocol errors (counters()).
  void run_back_to_back(const std::vector<device::Span>& spans, uint64_t pixels, StreamRun& run) {
    // The progress ends with kDone whatever happens, or a reader would wait forever.
    struct Publish {
      StreamRun& r;
      uint64_t& got;
      ~Publish() {
        r.progress.store(std::min<uint64_t>(got, r.intensity.size()) | StreamRun::kDone, std::memory_order_release);
        r.progress.notify_all();
      }
    };
    uint64_t got = 0;
    Publish publish{run, got};
    const size_t n = spans.size();
    run.intensity.assign(pixels, 0), run.tag.assign(pixels, 0), run.last.assign(pixels, 0);
    run.pixel_cycle.assign(pixels, 0), run.accept_cycle.assign(n, 0);
    if (!expect_.empty()) error("run_back_to_back with " + std::to_string(expect_.size()) + " scoreboard pixels owed");
    size_t next = 0;
    top_->px_ready_i = 1;
    top_->span_valid_i = n > 0;
    if (n > 0) drive_span(spans[0]);
    const uint64_t limit = cycle_ + pixels + 4 * n + 1024;  // far above any sane run
    auto sample = [&]() {
      top_->clk_i = 0;
      top_->eval();
      const bool pv = top_->px_valid_o;
      const uint32_t intensity = top_->px_intensity_o, tag = top_->px_tag_o;
      const bool last = top_->px_last_o;
      digest_add(vm_.digest_slot(), uint64_t{intensity} | uint64_t{tag} << 16 | uint64_t{last} << 48 | uint64_t{pv} << 49 |
                                   uint64_t{top_->span_ready_o} << 50);
      if (pv) {
        if (got < pixels) {
          run.intensity[got] = intensity;
          run.tag[got] = static_cast<uint32_t>(tag & tag_mask_);
          run.last[got] = last;
          run.pixel_cycle[got] = cycle_;
          run.last_transfer = cycle_;
        }
        ++got;
      } else if (intensity != 0 || last) {
        error("px_intensity_o/px_last_o not 0 while px_valid_o is low");
      }
      return pv;
    };
    while ((next < n || got < pixels) && cycle_ < limit) {
      sample();
      const bool fire = next < n && top_->span_ready_o;
      vm_.dump(cycle_, false);
      edge();
      if (fire) {
        run.accept_cycle[next] = cycle_ - 1;
        if (++next < n) drive_span(spans[next]);
        else top_->span_valid_i = 0;
      }
      // Publish every 1024 clocks: a reader wakes a few hundred times per million pixels.
      if ((cycle_ & 1023) == 0) {
        run.progress.store(std::min(got, pixels), std::memory_order_release);
        run.progress.notify_all();
      }
    }
    if (next < n || got < pixels)
      error("back-to-back run did not finish: " + std::to_string(next) + " of " + std::to_string(n) + " spans, " +
            std::to_string(got) + " of " + std::to_string(pixels) + " pixels");
    top_->span_valid_i = 0;
    for (int i = 0; i < 8; ++i) {
      if (sample()) error("pixel after the last span's last pixel");
      vm_.dump(cycle_, false);
      edge();
    }
    if (got > pixels) error(std::to_string(got - pixels) + " pixels more than the spans hold");
    cnt_.spans_accepted += next;
    cnt_.pixels += got;
    run.pixels = std::min(got, pixels);
    run.spans = next;
    run.first_accept = n > 0 ? run.accept_cycle.front() : 0;
  }
  uint64_t tag_mask() const { return tag_mask_; }

  // Sampled in the current cycle (after the last cycle()): for idle checks.
  bool px_valid() {
    top_->eval();
    return top_->px_valid_o;
  }
  uint64_t now() const { return cycle_; }

  void error(const std::string& what) {
    ++cnt_.protocol_errors;
    if (cnt_.first_errors.size() < 10) cnt_.first_errors.push_back("cycle " + std::to_string(cycle_) + ": " + what);
  }

 private:
  void drive_span(const device::Span& s) {
    const auto& f = model_.format();
    const uint64_t am = (1ULL << f.angle_bits) - 1;
    top_->span_c_i = s.reg.c & ((1U << f.c_bits) - 1);
    top_->span_psi0_i = static_cast<uint32_t>(static_cast<uint64_t>(s.reg.psi0) & am);
    top_->span_dpsi_i = static_cast<uint32_t>(static_cast<uint64_t>(s.reg.dpsi) & am);
    top_->span_n_i = s.reg.n & ((1U << f.n_bits) - 1);
    top_->span_len_i = s.reg.len & static_cast<uint32_t>(f.max_len());
    top_->span_tag_i = static_cast<uint32_t>(s.tag & tag_mask_);
  }
  void check_pixel(const device::StreamPixel& px) {
    if (expect_.empty()) {
      error("pixel without an accepted span");
      return;
    }
    const device::StreamPixel e = expect_.front();
    expect_.pop_front();
    ++cnt_.pixels;
    if (px.tag != e.tag || px.last != e.last) {
      error("tag/last " + std::to_string(px.tag) + "/" + std::to_string(px.last) + ", expected " +
            std::to_string(e.tag) + "/" + std::to_string(e.last));
    }
    if (px.intensity != e.intensity) {
      ++cnt_.mismatches;
      if (cnt_.first_errors.size() < 10)
        cnt_.first_errors.push_back("cycle " + std::to_string(cycle_) + ": intensity " + std::to_string(px.intensity) +
                                    ", golden " + std::to_string(e.intensity) + " (tag " + std::to_string(e.tag) + ")");
    }
  }
  void edge() {
    top_->clk_i = 1;
    top_->eval();
    vm_.dump(cycle_, true);
    top_->clk_i = 0;
    ++cycle_;
    ++cnt_.cycles;
  }

  std::string name_;
  device::DeviceModel model_;
  uint64_t tag_mask_;
  VerilatedModel<V> vm_;
  V* const top_ = vm_.top();
  uint64_t cycle_ = 0;
  std::deque<device::StreamPixel> expect_;
  StreamCounters cnt_;
  bool stalled_ = false;
  device::StreamPixel held_;
};

}  // namespace specular::sim
