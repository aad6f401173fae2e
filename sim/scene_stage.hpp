// SPDX-License-Identifier: Apache-2.0
// Scene stage of the regression: every scenes/*.json rasterized into spans (model/scene/raster),
// each span's registers from the batched setup (host::setup_batch, model/host/setup_batch.hpp),
// the spans streamed back to back through the configuration's verilated specular_stream
// (px_ready_i high, stream_harness.hpp run_back_to_back), every pixel checked by the same
// Checker as the regression lines ((a)-(c)) plus the stream's tag, last flag, count and
// latency, the setup error (batch against scalar registers) reported separately, and five
// images per scene:
//   <scene>_phong.png         per-pixel Phong truth (pixel_truth)
//   <scene>_float.png         spherical-interpolation float model (scanline_setup, pixel_blinn)
//   <scene>_rtl.png           the RTL output
//   <scene>_device_error.png  heatmap RTL - C cos^n(psi_i) from the loaded registers (check (c))
//   <scene>_interp_error.png  heatmap float model - Phong truth
//
// Speed: the stage models only what a scene needs. The RTL runs one pixel per clock and only
// records its output; the golden model (DeviceModel::stream_span per span), the double
// references and the setup comparison need only the registers, so they run on a second
// thread beside the RTL (SceneOptions::threads), which then compares the pixels as the RTL
// publishes them. What does not depend on the configuration (the span batch, the scalar
// setup, the Phong and float images) is made by the first configuration that runs the scene
// and kept in LoadedScene::shared.
#pragma once

#include "checks.hpp"
#include "image.hpp"
#include "raster.hpp"
#include "scene.hpp"
#include "setup_batch.hpp"
#include "stream_harness.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <latch>
#include <string>
#include <vector>

namespace specular::sim {

// What every configuration shares for one scene (made once, by the first run_scene).
struct SceneShared {
  bool ready = false;
  host::SpanBatch batch;               // the spans' setup inputs, structure of arrays
  std::vector<ScanlineSetup> setups;   // the scalar setup of every span (docs/scanline_setup.md)
  Image phong, flt;                    // Phong truth and float model
  ImageErrorStats interp_image;        // float model - Phong truth
  double peak_phong = 0.0;
};

struct LoadedScene {
  Scene scene;
  Raster raster;
  double raster_seconds = 0.0;
  SceneShared shared;
};

// Every DIR/*.json in file-name order, loaded and rasterized. Throws SceneError (message
// names the file) for a bad scene, std::runtime_error when DIR is not a directory.
std::vector<LoadedScene> load_scenes(const std::string& dir);

struct SceneOptions {
  std::string images_dir;  // write the PNGs here; empty: none
  int threads = 2;         // 2: golden model, references, checks beside the RTL (SceneRun); 1: around it
  // Test only: flip bit 0 of dpsi of this span on its way to the RTL (the golden model keeps
  // the true registers), so the stage must fail; -1: none.
  long corrupt_span = -1;
};

// The setup error: pixels C cos^n(psi_i) from the batch registers against those from the
// scalar setup's (host::compare_pixels, tolerance 0.01 % of the pixel in the epicenter,
// of C elsewhere, + 1 LSB of C). Spans whose codes are equal agree exactly and are not
// evaluated.
struct SetupErrorStats {
  uint64_t spans_differ = 0;       // spans whose register codes differ
  uint64_t status_mismatches = 0;  // setup status differs from scanline_setup's
  uint64_t violations = 0;         // spans over the tolerance
  double rel_epicenter = 0.0;      // max relative error in the epicenter (compare_pixels: P >= 2^-10)
  double abs_lsb = 0.0;            // max absolute error in LSB of C
  double worst = 0.0;              // max error / allowance (<= 1 passes)
  std::vector<std::string> first;  // the first few violations
  bool ok() const { return violations == 0 && status_mismatches == 0; }
};

struct SceneStats {
  std::string name, policy;
  int width = 0, height = 0;
  size_t triangles = 0, spans = 0, covered_pixels = 0, max_l = 0;
  size_t c_saturated_spans = 0;  // setup's C >= 2 clamped into reg 1: reported, not a failure
  PolicyStats checks;            // (a)-(d) over the scene's spans; lines = spans, latency per span
  SetupErrorStats setup;
  Extreme dev_abs;               // max |RTL - C cos^n(psi_i)| over span pixels, intensity units
  ImageErrorStats device_image;  // the device-error heatmap (lights summed)
  ImageErrorStats interp_image;  // float model - Phong truth
  ImageErrorStats register_image;  // float model - C cos^n(psi_i) of the loaded registers: C saturation, rounding
  double peak_phong = 0.0;
  uint64_t stream_cycles = 0;    // first accept .. last transfer
  int threads = 1;
  double raster_seconds = 0.0, image_seconds = 0.0;  // rasterization; PNG encoding and writing
  double setup_seconds = 0.0;        // the batched setup (and the span batch, first configuration)
  double setup_check_seconds = 0.0;  // scalar setup and the comparison of the two
  double compare_seconds = 0.0;      // the RTL's pixels against the golden model and the references
  double stage_seconds = 0.0;        // wall time of the scene on this configuration, PNG writing excluded
  double cpu_seconds = 0.0;          // process CPU time of the same (every thread)
  // CPU time of each thread's share (thread clocks): the RTL's thread (setup, RTL, tasks,
  // finish without the PNGs) and the other. On an idle machine the wall time is about the
  // larger of the two; on a busy one it says how far the wall time is from that.
  double rtl_thread_cpu_seconds = 0.0, side_thread_cpu_seconds = 0.0;
  std::vector<std::string> images;   // files written (empty when this policy wrote none)

  double checked_mpix_per_s() const { return stage_seconds > 0 ? checks.pixels / stage_seconds / 1e6 : 0.0; }
  bool ok() const {
    return checks.lines > 0 && checks.mismatches == 0 && checks.protocol_errors == 0 &&
           checks.quant_violations == 0 && checks.rel_violations == 0 && checks.abs_violations == 0 &&
           checks.latency.size() == 1 && checks.latency.begin()->first == checks.expected_latency && setup.ok();
  }
  nlohmann::json to_json() const;
};

// One scene on one configuration, everything but the RTL run (scene_stage.cpp):
//   setup()           the batched setup: the registers the RTL gets (the RTL's thread)
//   prepare_shared()  the scalar setup of every span, when no configuration made it yet
//   prepare()         waits for setup(), then the golden model, the references and the
//                     reference image: what compare() needs
//   task()            claims and does one of the parts that need neither the RTL's output nor
//                     each other, if one is left (the setup error; the float model and the
//                     Phong truth, when no configuration made them yet): either thread
//   compare()         the recorded stream against prepare()'s results, as far as the run got
//   finish()          what is left after both threads: the statistics, the images
// With two threads the second runs prepare_shared, prepare, then compare as far as the RTL
// got and a task whenever it waits, while this one runs setup and the RTL, then tasks.
class SceneRun {
 public:
  SceneRun(const device::DeviceModel& model, const Checker& checker, const std::string& policy, LoadedScene& ls,
           const SceneOptions& opt, uint64_t tag_mask);
  void setup();
  void prepare_shared();
  bool task();
  void prepare();
  // Compares every span whose pixels the run has published; with `wait`, waits for the rest.
  // Returns true when every span is compared.
  bool compare(const StreamRun& run, bool wait);
  const std::vector<device::Span>& rtl_spans() const { return corrupt_.empty() ? spans_ : corrupt_; }
  uint64_t pixels() const { return pixels_; }
  // rtl_thread_cpu0: this thread's CPU clock when the scene began; side_cpu: the other's CPU time.
  SceneStats finish(const StreamRun& run, double rtl_seconds, uint64_t protocol_errors,
                    const std::vector<std::string>& protocol_messages, double rtl_thread_cpu0, double side_cpu);

 private:
  void setup_check();
  void compare_span(size_t j, const StreamRun& run, uint64_t recorded);
  void note(const std::string& what);

  const device::DeviceModel& model_;
  const Checker& checker_;
  LoadedScene& ls_;
  SceneOptions opt_;
  SceneStats s_;
  std::string kind_;  // "scene:<name>", once per scene
  uint64_t tag_mask_;
  double lsb_ = 0.0;  // of C and the output
  std::chrono::steady_clock::time_point t0_;
  double cpu0_ = 0.0;
  std::latch registers_ready_{1};          // setup() ended: prepare() may read the registers
  bool setup_done_ = false;                // ... and it did not throw
  std::atomic<bool> setups_ready_{false};  // prepare_shared() ended: the float model may start
  std::atomic<bool> check_claimed_{false}, phong_claimed_{false}, float_claimed_{false};
  double shared_seconds_[2] = {0.0, 0.0};  // float model, Phong truth (whoever made them)
  host::RegisterBatch regs_;
  std::vector<device::Span> spans_, corrupt_;  // latched registers + tag; the RTL's copy when corrupted
  std::vector<uint64_t> offset_;               // first pixel of each span in the stream
  uint64_t pixels_ = 0;
  // prepare()'s results, one entry per pixel
  std::vector<device::StreamPixel> golden_;
  std::vector<uint32_t> golden_intensity_;
  std::vector<double> psi_, ref_b_, ref_c_;
  Image reference_;  // C cos^n(psi_i) of the loaded registers, lights summed
  // compare()'s state and results
  size_t next_span_ = 0;
  uint64_t stream_errors_ = 0;  // tag/last against the golden stream view
  Image rtl_;
};

// CPU time of the calling thread, seconds.
double thread_cpu_now();

// Runs `side` on a second thread while `main` runs on this one; rethrows the side's exception
// after both ended.
void run_beside(const std::function<void()>& side, const std::function<void()>& main);

// The scene through the stream: the setup and the RTL on this thread, the rest on another
// (opt.threads > 1) or before and after them.
template <class V>
SceneStats run_scene(StreamHarness<V>& h, const Checker& checker, const std::string& policy, LoadedScene& ls,
                     const SceneOptions& opt) {
  const double cpu0 = thread_cpu_now();
  SceneRun sr(h.model(), checker, policy, ls, opt, h.tag_mask());
  StreamRun run;
  double side_cpu = 0.0;
  const uint64_t errors0 = h.counters().protocol_errors;
  const size_t messages0 = h.counters().first_errors.size();
  double rtl_seconds = 0.0;
  auto rtl = [&]() {
    sr.setup();
    const auto t = std::chrono::steady_clock::now();
    h.run_back_to_back(sr.rtl_spans(), sr.pixels(), run);
    rtl_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  if (opt.threads > 1) {
    run_beside(
        [&]() {
          const double c0 = thread_cpu_now();
          sr.prepare_shared();
          sr.prepare();
          // Compare what the RTL delivered so far; while it is ahead, do a task.
          while (!sr.compare(run, false))
            if (!sr.task()) sr.compare(run, true);
          while (sr.task()) {
          }
          side_cpu = thread_cpu_now() - c0;
        },
        [&]() {
          rtl();
          while (sr.task()) {
          }
        });
  } else {
    sr.prepare_shared();
    rtl();
    sr.prepare();
    sr.compare(run, true);
    while (sr.task()) {
    }
  }
  const auto& c = h.counters();
  const std::vector<std::string> messages(c.first_errors.begin() + static_cast<long>(messages0), c.first_errors.end());
  return sr.finish(run, rtl_seconds, c.protocol_errors - errors0, messages, cpu0, side_cpu);
}

// Scene rows of the summary (one per scene and policy).
void print_scene_table(const std::vector<SceneStats>& all);

}  // namespace specular::sim
