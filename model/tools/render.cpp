// SPDX-License-Identifier: Apache-2.0
// render: scene -> spans -> Phong truth and spherical-interpolation float model images.
//
//   render --scene scenes/spheres.json --out-dir out [--scale S] [--csv-header]
//
// Writes <out>/<scene>_phong.png, <scene>_float.png, <scene>_interp_error.png
// (heatmap of float - phong) and prints one CSV line of statistics on stdout.
// With --golden also <scene>_golden.png (bit-accurate device model fed with the
// quantized span registers) and <scene>_device_error.png (golden - float), and four
// more CSV columns. An RTL image is one more evaluator (see image.hpp).
// With --colour also the colour images of the scene (model/scene/compose.hpp, scenes/README.md):
// <scene>_colour_device.png (the golden device model's specular intensity with C = 1 per light),
// <scene>_colour_reference.png (the material's BRDF in double) and <scene>_colour_diff.png
// (device - reference in 8-bit sRGB codes, amplified), and seven more CSV columns: the worst and
// mean |device - reference| in sRGB codes per channel, and the time.
// Exit codes: 0 ok, 2 bad arguments or bad scene file, 1 I/O failure.
#include "cli_parse.hpp"
#include "compose.hpp"
#include "image.hpp"
#include "raster.hpp"
#include "rom_image.hpp"
#include "scene.hpp"


#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <system_error>

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Rasterize a scene into spans and render the Phong truth and the float model"};
  std::string scene_path, out_dir;
  double scale = 0.0;
  bool csv_header = false;
  bool golden = false;
  bool colour = false;
  std::string config = "default", coef_rom, cos_rom;
  app.add_option("--scene", scene_path, "scene JSON file (format: scenes/README.md)")->required();
  app.add_option("--out-dir", out_dir, "directory for the PNG images (created if missing)")->required();
  app.add_option("--scale", scale, "intensity multiplier for the grey images, (0, 1000]; default: 1 / peak of the Phong image");
  app.add_flag("--csv-header", csv_header, "print the CSV header line before the statistics");
  app.add_flag("--golden", golden, "also render the bit-accurate device model and the device-error heatmap");
  app.add_flag("--colour", colour,
               "also compose the colour images with the golden device model and the reference "
               "(<scene>_colour_device/_reference/_diff.png) and print their sRGB-code errors");
  app.add_option("--config", config, "build configuration of the device model for --golden and --colour "
                                      "(its format and ROM files; rom_image.hpp build_configs())")
      ->capture_default_str();
  app.add_option("--coef-rom", coef_rom, "ROM 9 hex file instead of the configuration's (same format)");
  app.add_option("--cos-rom", cos_rom, "ROM 12 hex file instead of the configuration's (same format)");
  if (const auto exit_code = specular::parse_command_line(app, argc, argv, "render")) return *exit_code;
  if (app.count("--scale") && !(scale > 0.0 && scale <= 1000.0)) {
    std::cerr << "render: --scale must be in (0, 1000], got " << scale << "\n";
    return 2;
  }

  specular::Scene scene;
  try {
    scene = specular::load_scene(scene_path);
  } catch (const specular::SceneError& e) {
    std::cerr << "render: " << e.what() << "\n";
    return 2;
  }

  std::optional<specular::device::DeviceModel> dm;
  if (golden || colour) {
    const specular::BuildConfig* bc = nullptr;
    try {
      bc = &specular::build_config(config);
    } catch (const std::invalid_argument& e) {
      std::cerr << "render: --config: " << e.what() << "\n";
      return 2;
    }
    if (coef_rom.empty()) coef_rom = bc->coef_hex();
    if (cos_rom.empty()) cos_rom = bc->cos_hex();
    try {
      dm.emplace(specular::load_device_model(bc->f, coef_rom, cos_rom));
    } catch (const std::exception& e) {
      std::cerr << "render: --coef-rom " << coef_rom << " / --cos-rom " << cos_rom
                << ": expected readable ROM hex files of configuration " << config << "'s format: " << e.what() << "\n";
      return 2;
    }
  }

  const auto t0 = Clock::now();
  const specular::Raster raster = specular::rasterize(scene);
  const double raster_ms = ms_since(t0);
  const auto t1 = Clock::now();
  const specular::Image phong = specular::render(raster, specular::phong_evaluator(scene));
  const double phong_ms = ms_since(t1);
  const auto t2 = Clock::now();
  const specular::Image flt = specular::render(raster, specular::float_model_evaluator());
  const double float_ms = ms_since(t2);
  const specular::Image err = specular::difference(flt, phong);
  const specular::ImageErrorStats es = specular::error_stats(err);
  specular::Image gold, dev_err;
  specular::ImageErrorStats ds;
  double golden_ms = 0;
  size_t saturated = 0;
  if (golden) {
    const auto t3 = Clock::now();
    gold = specular::render(raster, specular::golden_evaluator(*dm));
    golden_ms = ms_since(t3);
    dev_err = specular::difference(gold, flt);
    ds = specular::error_stats(dev_err);
    for (const auto& sp : raster.spans) {
      bool sat = false;
      specular::host::span_registers(sp.setup_in, dm->format(), &sat);
      saturated += sat;
    }
  }

  specular::ColourLayers colour_dev, colour_ref;
  specular::ColourErrorStats cs;
  double colour_ms = 0;
  if (colour) {
    const auto t4 = Clock::now();
    colour_dev = specular::compose(scene, raster, specular::device_unit_specular(*dm));
    colour_ref = specular::compose(scene, raster, specular::reference_unit_specular(scene));
    cs = specular::srgb_code_error(colour_dev.image, colour_ref.image);
    colour_ms = ms_since(t4);
  }

  double peak = 0;
  for (double v : phong.value) peak = std::max(peak, v);
  // Auto exposure: one scale for both grey images so they compare directly.
  if (scale == 0.0) scale = peak > 0 ? std::min(1.0 / peak, 1000.0) : 1.0;

  // Everything is computed; write to temporary names, then rename, so a failure
  // leaves no half-written image set behind.
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec) {
    std::cerr << "render: --out-dir " << out_dir << ": cannot create the directory: " << ec.message() << "\n";
    return 1;
  }
  const fs::path base = fs::path(out_dir) / scene.name;
  std::vector<std::string> names = {base.string() + "_phong.png", base.string() + "_float.png",
                                    base.string() + "_interp_error.png"};
  if (golden) {
    names.push_back(base.string() + "_golden.png");
    names.push_back(base.string() + "_device_error.png");
  }
  const size_t first_colour = names.size();
  if (colour) {
    names.push_back(base.string() + "_colour_device.png");
    names.push_back(base.string() + "_colour_reference.png");
    names.push_back(base.string() + "_colour_diff.png");
  }
  try {
    specular::write_png(names[0] + ".tmp", phong, scale);
    specular::write_png(names[1] + ".tmp", flt, scale);
    specular::write_heatmap_png(names[2] + ".tmp", err, "FLOAT - PHONG");
    if (golden) {
      specular::write_png(names[3] + ".tmp", gold, scale);
      specular::write_heatmap_png(names[4] + ".tmp", dev_err, "GOLDEN - FLOAT");
    }
    if (colour) {
      specular::write_srgb_png(names[first_colour] + ".tmp", colour_dev.image);
      specular::write_srgb_png(names[first_colour + 1] + ".tmp", colour_ref.image);
      specular::write_code_diff_png(names[first_colour + 2] + ".tmp", colour_dev.image, colour_ref.image,
                                    "DEVICE - REFERENCE");
    }
    for (const auto& n : names) fs::rename(n + ".tmp", n);
  } catch (const std::exception& e) {
    for (const auto& n : names) fs::remove(n + ".tmp", ec);
    std::cerr << "render: " << e.what() << "\n";
    return 1;
  }

  const auto& st = raster.stats;
  if (csv_header)
    std::printf(
        "scene,width,height,triangles,spans,covered_pixels,shaded_pixels,max_l,spans_l0,spans_l1,"
        "max_abs_interp_error,rms_interp_error,peak_phong,image_scale,raster_ms,phong_ms,float_ms%s%s\n",
        golden ? ",max_abs_device_error,rms_device_error,c_saturated_spans,golden_ms" : "",
        colour ? ",colour_max_code_r,colour_max_code_g,colour_max_code_b,colour_mean_code_r,colour_mean_code_g,"
                 "colour_mean_code_b,colour_ms"
               : "");
  // Every real printed as the shortest text that parses back to the same double.
  using specular::cli::num;
  std::printf("%s,%d,%d,%zu,%zu,%zu,%zu,%d,%zu,%zu,%s,%s,%s,%s,%s,%s,%s", scene.name.c_str(), scene.width,
              scene.height, st.triangles, st.spans, st.covered_pixels, st.shaded_pixels, st.max_l, st.spans_l0,
              st.spans_l1, num(es.max_abs).c_str(), num(es.rms).c_str(), num(peak).c_str(), num(scale).c_str(),
              num(raster_ms).c_str(), num(phong_ms).c_str(), num(float_ms).c_str());
  if (golden)
    std::printf(",%s,%s,%zu,%s", num(ds.max_abs).c_str(), num(ds.rms).c_str(), saturated, num(golden_ms).c_str());
  if (colour)
    std::printf(",%d,%d,%d,%s,%s,%s,%s", cs.max_abs[0], cs.max_abs[1], cs.max_abs[2], num(cs.mean_abs[0]).c_str(),
                num(cs.mean_abs[1]).c_str(), num(cs.mean_abs[2]).c_str(), num(colour_ms).c_str());
  std::printf("\n");
  return 0;
}
