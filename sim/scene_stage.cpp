// SPDX-License-Identifier: Apache-2.0
#include "scene_stage.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <exception>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <thread>

namespace specular::sim {
namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// CPU time of the whole process (every thread): the stage's cost independent of what else
// runs on the machine.
double cpu_now() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// error_stats(difference(a, b)) without making the difference image (image.hpp): covered
// where either is, the same order and ties.
ImageErrorStats diff_stats(const Image& a, const Image& b) {
  ImageErrorStats st;
  double sum2 = 0;
  for (size_t k = 0; k < a.value.size(); ++k) {
    if (!(a.covered[k] | b.covered[k])) continue;
    const double e = a.value[k] - b.value[k];
    ++st.pixels;
    sum2 += e * e;
    if (std::abs(e) > st.max_abs || st.argmax_x < 0) {
      st.max_abs = std::max(st.max_abs, std::abs(e));
      st.argmax_x = static_cast<int>(k % static_cast<size_t>(a.width));
      st.argmax_y = static_cast<int>(k / static_cast<size_t>(a.width));
    }
  }
  st.rms = st.pixels ? std::sqrt(sum2 / st.pixels) : 0.0;
  return st;
}

nlohmann::json ext_json(const Extreme& e) {
  return {{"value", e.value}, {"n", e.n}, {"psi", e.psi}, {"C", e.c}, {"l", e.len}, {"pixel", e.pixel}};
}

nlohmann::json image_json(const ImageErrorStats& e) {
  return {{"max_abs", e.max_abs}, {"rms", e.rms}, {"x", e.argmax_x}, {"y", e.argmax_y}};
}

}  // namespace

std::vector<LoadedScene> load_scenes(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw std::runtime_error("not a directory");
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<LoadedScene> out;
  for (const auto& p : files) {
    LoadedScene ls;
    ls.scene = load_scene(p.string());
    const auto t0 = Clock::now();
    ls.raster = rasterize(ls.scene);
    ls.raster_seconds = since(t0);
    out.push_back(std::move(ls));
  }
  return out;
}

double thread_cpu_now() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void run_beside(const std::function<void()>& side, const std::function<void()>& main) {
  std::exception_ptr error;
  {
    std::jthread t([&]() {
      try {
        side();
      } catch (...) {
        error = std::current_exception();
      }
    });
    main();  // should it throw, the jthread joins before the exception leaves
  }
  if (error) std::rethrow_exception(error);
}

SceneRun::SceneRun(const device::DeviceModel& model, const Checker& checker, const std::string& policy,
                   LoadedScene& ls, const SceneOptions& opt, uint64_t tag_mask)
    : model_(model), checker_(checker), ls_(ls), opt_(opt), kind_("scene:" + ls.scene.name), tag_mask_(tag_mask) {
  t0_ = Clock::now();
  cpu0_ = cpu_now();
  s_.name = ls.scene.name;
  s_.policy = policy;
  s_.checks.policy = policy + " scene " + s_.name;
  s_.raster_seconds = ls.raster_seconds;
  s_.threads = opt.threads > 1 ? 2 : 1;
  lsb_ = std::ldexp(1.0, -model.format().c_frac);
}

void SceneRun::note(const std::string& what) {
  if (s_.checks.failures.size() < 12) s_.checks.failures.push_back(what);
}

void SceneRun::setup() {
  // prepare() waits for this; it must not wait forever should the setup throw.
  struct Done {
    std::latch& l;
    ~Done() { l.count_down(); }
  } done{registers_ready_};
  const auto t = Clock::now();
  const auto& f = model_.format();
  const auto& spans = ls_.raster.spans;
  // Registers of every span from the batched setup, in one call.
  auto& batch = ls_.shared.batch;
  if (batch.size() != spans.size()) {
    batch.clear();
    batch.reserve(spans.size());
    for (const Span& sp : spans) batch.push_back(sp.setup_in);
  }
  host::setup_batch(batch, f, regs_);
  spans_.resize(spans.size());
  offset_.resize(spans.size());
  for (size_t j = 0; j < spans.size(); ++j) {
    spans_[j] = {model_.latch(regs_.registers(j)), static_cast<uint32_t>(j & tag_mask_)};
    offset_[j] = pixels_;
    pixels_ += spans_[j].reg.len + 1;
    if (regs_.flags[j] & host::kCSaturated) ++s_.c_saturated_spans;
  }
  if (opt_.corrupt_span >= 0 && static_cast<size_t>(opt_.corrupt_span) < spans_.size()) {
    corrupt_ = spans_;
    corrupt_[static_cast<size_t>(opt_.corrupt_span)].reg.dpsi ^= 1;
  }
  s_.setup_seconds = since(t);
  setup_done_ = true;
}

void SceneRun::prepare_shared() {
  auto& sh = ls_.shared;
  if (!sh.ready) {
    // Once per scene: the scalar setup of every span, the setup error's reference and the
    // float model's input. Needs no register: runs while setup() does.
    const auto t = Clock::now();
    const auto& spans = ls_.raster.spans;
    sh.setups.resize(spans.size());
    for (size_t j = 0; j < spans.size(); ++j) sh.setups[j] = scanline_setup(spans[j].setup_in);
    s_.setup_check_seconds += since(t);
  }
  setups_ready_.store(true, std::memory_order_release);
}

bool SceneRun::task() {
  auto& sh = ls_.shared;
  // The setup check needs the registers: the RTL's thread calls task() after setup(), the
  // other after prepare(), which waits for it.
  if (setups_ready_.load(std::memory_order_acquire) && !check_claimed_.exchange(true)) {
    if (setup_done_) setup_check();
    return true;
  }
  if (sh.ready) return false;
  if (!phong_claimed_.exchange(true)) {
    const auto t = Clock::now();
    sh.phong = render(ls_.raster, phong_evaluator(ls_.scene));
    shared_seconds_[1] = since(t);
    return true;
  }
  if (setups_ready_.load(std::memory_order_acquire) && !float_claimed_.exchange(true)) {
    // The float model from the same scalar setup (float_model_evaluator's arithmetic).
    const auto t = Clock::now();
    const auto& spans = ls_.raster.spans;
    sh.flt = Image(ls_.raster.width, ls_.raster.height);
    for (size_t j = 0; j < spans.size(); ++j) {
      const Span& sp = spans[j];
      const size_t row = static_cast<size_t>(sp.y) * sh.flt.width + sp.x_start;
      for (int i = 0; i < sp.pixels(); ++i) {
        sh.flt.value[row + i] += pixel_blinn(sh.setups[j], sp.setup_in.n, i);
        sh.flt.covered[row + i] = 1;
      }
    }
    shared_seconds_[0] = since(t);
    return true;
  }
  return false;
}

void SceneRun::prepare() {
  registers_ready_.wait();
  if (!setup_done_) return;  // setup() threw; the exception reaches the caller
  const auto& spans = ls_.raster.spans;
  const size_t n = spans.size();
  // The golden model's stream view of every span (intensity, last, tag).
  auto t = Clock::now();
  golden_.clear();
  golden_.reserve(pixels_);
  for (const device::Span& sp : spans_) model_.stream_span(sp, golden_);
  golden_intensity_.resize(golden_.size());
  for (size_t k = 0; k < golden_.size(); ++k) golden_intensity_[k] = golden_[k].intensity;
  s_.checks.golden_seconds += since(t);
  // The double references (b) and (c), and the image of (c).
  t = Clock::now();
  psi_.resize(pixels_);
  ref_b_.resize(pixels_);
  ref_c_.resize(pixels_);
  reference_ = Image(ls_.raster.width, ls_.raster.height);
  for (size_t j = 0; j < n; ++j) {
    const size_t o = offset_[j], npix = spans_[j].reg.len + 1;
    checker_.references(spans_[j].reg, npix, &psi_[o], &ref_b_[o], &ref_c_[o]);
    const size_t row = static_cast<size_t>(spans[j].y) * reference_.width + spans[j].x_start;
    for (size_t i = 0; i < npix; ++i) {
      reference_.value[row + i] += ref_c_[o + i];
      reference_.covered[row + i] = 1;
    }
  }
  s_.checks.reference_seconds += since(t);
  rtl_ = Image(ls_.raster.width, ls_.raster.height);
}

void SceneRun::setup_check() {
  // The setup error: batch registers against the scalar setup's (host::span_registers).
  const auto& f = model_.format();
  const auto& spans = ls_.raster.spans;
  const size_t n = spans.size();
  const auto& sh = ls_.shared;
  const auto t = Clock::now();
  auto& se = s_.setup;
  for (size_t j = 0; j < n; ++j) {
    const ScanlineSetup& st = sh.setups[j];
    const device::Registers ref = device::load_registers(st, spans[j].setup_in.n, spans[j].length(), f).reg;
    const device::Registers got = regs_.registers(j);
    if (regs_.status[j] != static_cast<uint8_t>(st.status)) {
      if (se.first.size() < 6)
        se.first.push_back(s_.checks.policy + " setup status of span " + std::to_string(j) + ": batch " +
                           to_string(regs_.setup_status(j)) + ", scalar " + to_string(st.status));
      ++se.status_mismatches;
    }
    if (got.c == ref.c && got.psi0 == ref.psi0 && got.dpsi == ref.dpsi && got.n == ref.n && got.len == ref.len)
      continue;  // equal codes: equal pixels
    ++se.spans_differ;
    const host::PixelAgreement pa = host::compare_pixels(got, ref, f);
    se.rel_epicenter = std::max(se.rel_epicenter, pa.max_rel_epicenter);
    se.abs_lsb = std::max(se.abs_lsb, pa.max_abs_lsb);
    se.worst = std::max(se.worst, pa.worst);
    if (!pa.ok()) {
      if (se.first.size() < 6)
        se.first.push_back(s_.checks.policy + " setup error of span " + std::to_string(j) + ": " +
                           std::to_string(pa.worst) + " x the tolerance at pixel " + std::to_string(pa.worst_pixel) +
                           " (n=" + std::to_string(ref.n) + " l=" + std::to_string(ref.len) + ")");
      ++se.violations;
    }
  }
  s_.setup_check_seconds += since(t);
}

bool SceneRun::compare(const StreamRun& run, bool wait) {
  if (!setup_done_) return true;
  auto t = Clock::now();  // the comparisons' time, not the waits'
  uint64_t p = run.progress.load(std::memory_order_acquire);
  while (next_span_ < spans_.size()) {
    const uint64_t need = offset_[next_span_] + spans_[next_span_].reg.len + 1;
    if ((p & ~StreamRun::kDone) < need && !(p & StreamRun::kDone)) {
      s_.compare_seconds += since(t);
      if (!wait) return false;
      run.wait_for(need);
      p = run.progress.load(std::memory_order_acquire);
      t = Clock::now();
      continue;
    }
    compare_span(next_span_++, run, p & ~StreamRun::kDone);
  }
  s_.compare_seconds += since(t);
  return true;
}

void SceneRun::compare_span(size_t j, const StreamRun& run, uint64_t recorded) {
  auto& st = s_.checks;
  const Span& sp = ls_.raster.spans[j];
  const device::Registers& r = spans_[j].reg;
  const size_t o = offset_[j];
  ++st.lines;
  if (o >= recorded) return;  // the run ended short: finish() counts the missing pixels
  const size_t npix = std::min<size_t>(r.len + 1, recorded - o);
  // The stream view: every pixel carries its span's tag and only pixel l is last
  // (docs/interfaces.md), from the span as sent, not from the golden model.
  const uint32_t want_tag = spans_[j].tag;
  for (size_t k = o; k < o + npix; ++k) {
    const bool want_last = k - o == r.len;
    if (run.tag[k] != want_tag || (run.last[k] != 0) != want_last) {
      if (stream_errors_ < 6)
        note(st.policy + " stream: span " + std::to_string(j) + " pixel " + std::to_string(k - o) + ": tag/last " +
             std::to_string(run.tag[k]) + "/" + std::to_string(run.last[k]) + ", expected " + std::to_string(want_tag) +
             "/" + std::to_string(want_last));
      ++stream_errors_;
    }
  }
  // Latency: the span's pixel 0 after its accept.
  ++st.latency[static_cast<int>(run.pixel_cycle[o] - run.accept_cycle[j])];
  checker_.compare(r, kind_, npix, &run.intensity[o], &golden_intensity_[o], &psi_[o], &ref_b_[o], &ref_c_[o], st);
  const double lsb = lsb_;
  const size_t row = static_cast<size_t>(sp.y) * rtl_.width + sp.x_start;
  for (size_t i = 0; i < npix; ++i) {
    const double out = run.intensity[o + i] * lsb, ref = ref_c_[o + i];
    rtl_.value[row + i] += out;
    rtl_.covered[row + i] = 1;
    const double e = std::fabs(out - ref);
    if (e > s_.dev_abs.value) s_.dev_abs = {e, r.n, psi_[o + i], r.c * lsb, r.len, static_cast<int>(i), kind_};
  }
}

SceneStats SceneRun::finish(const StreamRun& run, double rtl_seconds, uint64_t protocol_errors,
                            const std::vector<std::string>& protocol_messages, double rtl_thread_cpu0,
                            double side_cpu) {
  auto& st = s_.checks;
  auto& sh = ls_.shared;
  st.sim_seconds = rtl_seconds;
  st.protocol_errors += protocol_errors + stream_errors_;
  for (const auto& m : protocol_messages) note(st.policy + " stream: " + m);
  st.c_saturated_lines = s_.c_saturated_spans;
  if (run.pixels != pixels_) {
    ++st.protocol_errors;
    note(st.policy + " stream: " + std::to_string(run.pixels) + " pixels recorded, the spans hold " +
         std::to_string(pixels_));
  }
  st.cycles = s_.stream_cycles = run.cycles();
  if (!sh.ready) {
    sh.interp_image = diff_stats(sh.flt, sh.phong);
    for (double v : sh.phong.value) sh.peak_phong = std::max(sh.peak_phong, v);
    st.reference_seconds += shared_seconds_[0] + shared_seconds_[1];
    sh.ready = true;
  }
  const auto& rs = ls_.raster.stats;
  s_.width = ls_.raster.width;
  s_.height = ls_.raster.height;
  s_.triangles = rs.triangles;
  s_.spans = ls_.raster.spans.size();
  s_.covered_pixels = rs.covered_pixels;
  s_.max_l = static_cast<size_t>(rs.max_l);
  s_.device_image = diff_stats(rtl_, reference_);
  s_.register_image = diff_stats(sh.flt, reference_);
  s_.interp_image = sh.interp_image;
  s_.peak_phong = sh.peak_phong;
  s_.stage_seconds = since(t0_);
  s_.cpu_seconds = cpu_now() - cpu0_;
  s_.rtl_thread_cpu_seconds = thread_cpu_now() - rtl_thread_cpu0;
  s_.side_thread_cpu_seconds = side_cpu;

  if (!opt_.images_dir.empty()) {
    const auto t_img = Clock::now();
    // One exposure for the three grey images so that they compare directly.
    const double scale = s_.peak_phong > 0 ? std::min(1.0 / s_.peak_phong, 1000.0) : 1.0;
    const std::string& dir = opt_.images_dir;
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw std::runtime_error("--images-dir " + dir + ": cannot create the directory: " + ec.message());
    const std::string base = (fs::path(dir) / s_.name).string();
    const std::vector<std::string> names = {base + "_phong.png", base + "_float.png", base + "_rtl.png",
                                            base + "_device_error.png", base + "_interp_error.png"};
    try {
      write_png(names[0] + ".tmp", sh.phong, scale);
      write_png(names[1] + ".tmp", sh.flt, scale);
      write_png(names[2] + ".tmp", rtl_, scale);
      write_heatmap_png(names[3] + ".tmp", difference(rtl_, reference_), "RTL - C COSN(PSI) " + s_.policy);
      write_heatmap_png(names[4] + ".tmp", difference(sh.flt, sh.phong), "FLOAT - PHONG");
      for (const auto& nm : names) fs::rename(nm + ".tmp", nm);
    } catch (...) {
      for (const auto& nm : names) fs::remove(nm + ".tmp", ec);
      throw;
    }
    s_.images = names;
    s_.image_seconds = since(t_img);
  }
  st.seconds = since(t0_);
  for (const auto& m : s_.setup.first) note(m);
  return std::move(s_);
}

nlohmann::json SceneStats::to_json() const {
  const auto& c = checks;
  const double rtl_s = c.sim_seconds;
  return {{"policy", policy},
          {"ok", ok()},
          {"width", width},
          {"height", height},
          {"triangles", triangles},
          {"spans", spans},
          {"pixels", c.pixels},
          {"covered_pixels", covered_pixels},
          {"max_l", max_l},
          {"c_saturated_spans", c_saturated_spans},
          {"mismatches", c.mismatches},
          {"protocol_errors", c.protocol_errors},
          {"quant_violations", c.quant_violations},
          {"rel_violations", c.rel_violations},
          {"abs_violations", c.abs_violations},
          {"budget", {{"rel_epicenter", c.budget.rel_epicenter}, {"abs_lobe", c.budget.abs_lobe}}},
          {"max_device_error_abs", dev_abs.value},
          {"max_device_error_abs_at", ext_json(dev_abs)},
          {"max_device_rel_epicenter", c.rel_allow.value},
          {"max_device_rel_epicenter_at", ext_json(c.rel_allow)},
          {"max_device_rel_epicenter_raw", c.rel_raw.value},
          {"max_device_rel_epicenter_n1", c.rel_allow_n1.value},
          {"max_device_abs_lobe_over_c", c.abs_allow.value},
          {"max_quant_lsb", c.quant_lsb.value},
          {"device_error_image", image_json(device_image)},
          {"max_interp_error_abs", interp_image.max_abs},
          {"rms_interp_error", interp_image.rms},
          {"interp_error_image", image_json(interp_image)},
          {"max_float_vs_registers_abs", register_image.max_abs},
          {"peak_phong", peak_phong},
          {"setup_rel_epicenter", setup.rel_epicenter},
          {"setup_abs_lsb", setup.abs_lsb},
          {"setup_worst_over_tolerance", setup.worst},
          {"setup_violations", setup.violations},
          {"setup_status_mismatches", setup.status_mismatches},
          {"setup_spans_differ", setup.spans_differ},
          {"latency", c.latency.empty() ? -1 : c.latency.begin()->first},
          {"expected_latency", c.expected_latency},
          {"cycles", c.cycles},
          {"stream_clocks_per_pixel", c.pixels ? double(stream_cycles) / c.pixels : 0.0},
          {"threads", threads},
          {"seconds", c.seconds},
          {"stage_seconds", stage_seconds},
          {"cpu_seconds", cpu_seconds},
          {"rtl_thread_cpu_seconds", rtl_thread_cpu_seconds},
          {"side_thread_cpu_seconds", side_thread_cpu_seconds},
          {"checked_mpix_per_s", checked_mpix_per_s()},
          {"checked_mpix_per_cpu_s", cpu_seconds > 0 ? c.pixels / cpu_seconds / 1e6 : 0.0},
          {"rtl_seconds", rtl_s},
          {"sim_seconds", rtl_s},
          {"golden_seconds", c.golden_seconds},
          {"reference_seconds", c.reference_seconds},
          {"setup_seconds", setup_seconds},
          {"setup_check_seconds", setup_check_seconds},
          {"compare_seconds", compare_seconds},
          {"raster_seconds", raster_seconds},
          {"image_seconds", image_seconds},
          {"simulated_pixels_per_second", rtl_s > 0 ? c.pixels / rtl_s : 0.0},
          {"images", images},
          {"failures", c.failures}};
}

void print_scene_table(const std::vector<SceneStats>& all) {
  const char* head[] = {"scene", "policy", "size", "spans", "pixels", "C sat. spans", "mismatches",
                        "max |dev err|", "max rel epi +1LSB", "max abs/C +1LSB", "max |interp err|",
                        "setup err rel epi / LSB", "stream clk/px", "checked Mpx/s (CPU)", "RTL/golden/ref s",
                        "result"};
  std::vector<std::vector<std::string>> rows;
  auto fmt = [](const char* f, double v) {
    char b[64];
    std::snprintf(b, sizeof b, f, v);
    return std::string(b);
  };
  for (const auto& s : all) {
    const auto& c = s.checks;
    rows.push_back({s.name, s.policy, std::to_string(s.width) + "x" + std::to_string(s.height),
                    std::to_string(s.spans), std::to_string(c.pixels), std::to_string(s.c_saturated_spans),
                    std::to_string(c.mismatches), fmt("%.3e", s.dev_abs.value), fmt("%.4f%%", 100 * c.rel_allow.value),
                    fmt("%.5f", c.abs_allow.value), fmt("%.3e", s.interp_image.max_abs),
                    fmt("%.2e%%", 100 * s.setup.rel_epicenter) + " / " + fmt("%.2e", s.setup.abs_lsb) +
                        (s.setup.ok() ? "" : " (" + std::to_string(s.setup.violations) + " over)"),
                    fmt("%.4f", c.pixels ? double(s.stream_cycles) / c.pixels : 0.0),
                    fmt("%.2f", s.checked_mpix_per_s()) + " (" +
                        fmt("%.2f", s.cpu_seconds > 0 ? c.pixels / s.cpu_seconds / 1e6 : 0.0) + ")",
                    fmt("%.3f", c.sim_seconds) + "/" + fmt("%.3f", c.golden_seconds) + "/" +
                        fmt("%.3f", c.reference_seconds),
                    s.ok() ? "PASS" : "FAIL"});
  }
  const size_t nc = std::size(head);
  std::vector<size_t> w(nc, 0);
  for (size_t j = 0; j < nc; ++j) w[j] = std::string(head[j]).size();
  for (const auto& r : rows)
    for (size_t j = 0; j < nc; ++j) w[j] = std::max(w[j], r[j].size());
  auto line = [&](const std::vector<std::string>& cells) {
    std::printf("|");
    for (size_t j = 0; j < nc; ++j) std::printf(" %-*s |", static_cast<int>(w[j]), cells[j].c_str());
    std::printf("\n");
  };
  line(std::vector<std::string>(std::begin(head), std::end(head)));
  std::printf("|");
  for (size_t j = 0; j < nc; ++j) std::printf("%s|", std::string(w[j] + 2, '-').c_str());
  std::printf("\n");
  for (const auto& r : rows) line(r);
}

}  // namespace specular::sim
