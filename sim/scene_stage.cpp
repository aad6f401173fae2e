#include "scene_stage.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace specular::sim {
namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

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

void finish_scene(SceneStats& s, const LoadedScene& ls, const Image& rtl, const Image& reference,
                  const std::string& images_dir) {
  const auto t0 = Clock::now();
  const auto& st = ls.raster.stats;
  s.width = ls.raster.width;
  s.height = ls.raster.height;
  s.triangles = st.triangles;
  s.spans = ls.raster.spans.size();
  s.covered_pixels = st.covered_pixels;
  s.max_l = static_cast<size_t>(st.max_l);

  // The per-pixel Phong truth and the float model are references too.
  const auto t_ref = Clock::now();
  const Image phong = render(ls.raster, phong_evaluator(ls.scene));
  const Image flt = render(ls.raster, float_model_evaluator());
  s.checks.reference_seconds += since(t_ref);

  const Image dev_err = difference(rtl, reference);
  const Image interp_err = difference(flt, phong);
  s.device_image = error_stats(dev_err);
  s.interp_image = error_stats(interp_err);
  s.register_image = error_stats(difference(flt, reference));
  for (double v : phong.value) s.peak_phong = std::max(s.peak_phong, v);

  if (!images_dir.empty()) {
    const auto t_img = Clock::now();
    // One exposure for the three grey images so that they compare directly.
    const double scale = s.peak_phong > 0 ? std::min(1.0 / s.peak_phong, 1000.0) : 1.0;
    std::error_code ec;
    fs::create_directories(images_dir, ec);
    if (ec) throw std::runtime_error("--images-dir " + images_dir + ": cannot create the directory: " + ec.message());
    const std::string base = (fs::path(images_dir) / s.name).string();
    const std::vector<std::string> names = {base + "_phong.png", base + "_float.png", base + "_rtl.png",
                                            base + "_device_error.png", base + "_interp_error.png"};
    try {
      write_png(names[0] + ".tmp", phong, scale);
      write_png(names[1] + ".tmp", flt, scale);
      write_png(names[2] + ".tmp", rtl, scale);
      write_heatmap_png(names[3] + ".tmp", dev_err, "RTL - C COSN(PSI) " + s.policy);
      write_heatmap_png(names[4] + ".tmp", interp_err, "FLOAT - PHONG");
      for (const auto& n : names) fs::rename(n + ".tmp", n);
    } catch (...) {
      for (const auto& n : names) fs::remove(n + ".tmp", ec);
      throw;
    }
    s.images = names;
    s.image_seconds = since(t_img);
  }
  s.checks.seconds += since(t0);
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
          {"latency", c.latency.empty() ? -1 : c.latency.begin()->first},
          {"cycles", c.cycles},
          {"seconds", c.seconds},
          {"rtl_seconds", rtl_s},
          {"sim_seconds", rtl_s},
          {"golden_seconds", c.golden_seconds},
          {"reference_seconds", c.reference_seconds},
          {"raster_seconds", raster_seconds},
          {"image_seconds", image_seconds},
          {"simulated_pixels_per_second", rtl_s > 0 ? c.pixels / rtl_s : 0.0},
          {"images", images},
          {"failures", c.failures}};
}

void print_scene_table(const std::vector<SceneStats>& all) {
  const char* head[] = {"scene", "policy", "size", "spans", "pixels", "C sat. spans", "mismatches",
                        "max |dev err|", "max rel epi +1LSB", "max abs/C +1LSB", "max |interp err|",
                        "sim px/s", "RTL/golden/ref s", "result"};
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
                    fmt("%.3e", c.sim_seconds > 0 ? c.pixels / c.sim_seconds : 0.0),
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
