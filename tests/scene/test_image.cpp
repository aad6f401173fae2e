// SPDX-License-Identifier: Apache-2.0
// Image accumulation, PNG and heatmap output, and the render tool's command line.
#include "compose.hpp"
#include "image.hpp"
#include "raster.hpp"
#include "rom_image.hpp"
#include "scene.hpp"

#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>

#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <algorithm>
#include <cstdlib>
#include <vector>

using namespace specular;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
namespace fs = std::filesystem;

namespace {

fs::path temp_dir(const std::string& tag) {
  const fs::path d = fs::temp_directory_path() / ("scene_tests_" + std::to_string(::getpid()) + "_" + tag);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

struct Png {
  int w = 0, h = 0;
  std::vector<uint8_t> rgb;
  const uint8_t* at(int x, int y) const { return &rgb[(static_cast<size_t>(y) * w + x) * 3]; }
};

Png read_png(const fs::path& p) {
  Png out;
  int comp = 0;
  unsigned char* data = stbi_load(p.c_str(), &out.w, &out.h, &comp, 3);
  REQUIRE(data != nullptr);
  out.rgb.assign(data, data + static_cast<size_t>(out.w) * out.h * 3);
  stbi_image_free(data);
  return out;
}

Raster two_spans() {
  Raster r;
  r.width = 8;
  r.height = 4;
  Span a;
  a.y = 1;
  a.x_start = 2;
  a.x_end = 5;
  Span b = a;
  b.light = 1;  // same pixels, second light: values add
  Span c;
  c.y = 3;
  c.x_start = c.x_end = 7;
  r.spans = {a, b, c};
  return r;
}

}  // namespace

TEST_CASE("render evaluates each span once and sums lights per pixel", "[scene][image]") {
  const Raster r = two_spans();
  int calls = 0;
  const Image img = render(r, [&](const Span& s, std::span<double> out) {
    ++calls;
    REQUIRE(out.size() == static_cast<size_t>(s.x_end - s.x_start + 1));
    for (size_t i = 0; i < out.size(); ++i) out[i] = 0.25 * (s.light + 1) + 0.01 * static_cast<double>(i);
  });
  CHECK(calls == 3);
  CHECK_THAT(img.at(2, 1), WithinAbs(0.25 + 0.5, 1e-15));
  CHECK_THAT(img.at(5, 1), WithinAbs(0.25 + 0.03 + 0.5 + 0.03, 1e-15));
  CHECK_THAT(img.at(7, 3), WithinAbs(0.25, 1e-15));
  int covered = 0;
  for (uint8_t c : img.covered) covered += c;
  CHECK(covered == 5);
  CHECK(img.at(0, 0) == 0.0);
  CHECK_FALSE(img.is_covered(1, 1));
}

TEST_CASE("difference and error statistics", "[scene][image]") {
  Image a(3, 2), b(3, 2);
  a.at(0, 0) = 0.5;
  a.covered[0] = 1;
  b.at(0, 0) = 0.25;
  b.covered[0] = 1;
  a.at(2, 1) = 0.1;
  a.covered[5] = 1;
  b.at(2, 1) = 0.4;
  b.covered[5] = 1;
  const Image d = difference(a, b);
  const ImageErrorStats st = error_stats(d);
  CHECK(st.pixels == 2);
  CHECK_THAT(st.max_abs, WithinAbs(0.3, 1e-15));
  CHECK(st.argmax_x == 2);
  CHECK(st.argmax_y == 1);
  CHECK_THAT(st.rms, WithinAbs(std::sqrt((0.25 * 0.25 + 0.3 * 0.3) / 2), 1e-15));
  CHECK_THROWS(difference(a, Image(2, 2)));
}

TEST_CASE("grey PNG: value * scale mapped to 0..255, uncovered pixels marked", "[scene][image]") {
  const fs::path dir = temp_dir("grey");
  Image img(4, 1);
  for (int x = 0; x < 3; ++x) {
    img.at(x, 0) = 0.25 * x;
    img.covered[x] = 1;
  }
  write_png((dir / "g.png").string(), img, 2.0);
  const Png p = read_png(dir / "g.png");
  REQUIRE(p.w == 4);
  REQUIRE(p.h == 1);
  CHECK(int(p.at(0, 0)[0]) == 0);
  CHECK(int(p.at(1, 0)[0]) == 128);  // 0.5 * 255 rounded
  CHECK(int(p.at(2, 0)[0]) == 255);  // 1.0 (clamped from 0.5 * 2)
  CHECK(p.at(3, 0)[2] != p.at(3, 0)[0]);  // background is not grey
  CHECK_THROWS_WITH(write_png("/nonexistent/dir/x.png", img), Contains("/nonexistent/dir/x.png"));
  fs::remove_all(dir);
}

TEST_CASE("heatmap: diverging colours, a colour bar and its range drawn below", "[scene][image]") {
  const fs::path dir = temp_dir("heat");
  Image err(300, 40);
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 300; ++x) {
      err.covered[static_cast<size_t>(y) * 300 + x] = x < 290;
      err.at(x, y) = (x - 150) * 1e-5;  // -1.5e-3 .. +1.39e-3
    }
  write_heatmap_png((dir / "h.png").string(), err, "TEST - ERR");
  const Png p = read_png(dir / "h.png");
  CHECK(p.w == 300);
  REQUIRE(p.h > 40 + 20);  // strip below the image
  // Most negative error: saturated blue; zero: white; positive: red.
  CHECK(p.at(0, 10)[2] > 150);
  CHECK(p.at(0, 10)[0] < 80);
  CHECK(int(p.at(150, 10)[0]) == 255);
  CHECK(int(p.at(150, 10)[1]) == 255);
  CHECK(p.at(280, 10)[0] > 150);
  CHECK(p.at(280, 10)[2] < 100);
  // The strip: some row of it is a colour bar running blue -> white -> red.
  bool bar = false;
  for (int y = 40; y < p.h && !bar; ++y) {
    const uint8_t *l = p.at(5, y), *m = p.at(150, y), *r = p.at(294, y);
    bar = l[2] > 150 && l[0] < 80 && m[0] > 240 && m[1] > 240 && m[2] > 240 && r[0] > 150 && r[2] < 80;
  }
  CHECK(bar);
  // Text (light ink on the dark strip) appears both above and below the bar.
  int ink = 0;
  for (int y = 40; y < p.h; ++y)
    for (int x = 0; x < 300; ++x) ink += p.at(x, y)[0] == 235 && p.at(x, y)[1] == 235 && p.at(x, y)[2] == 235;
  CHECK(ink > 100);
  fs::remove_all(dir);
}

TEST_CASE("the bitmap font covers numbers in scientific notation", "[scene][image]") {
  for (char c : std::string("0123456789.eE-+ ABCDEFGHIJKLMNOPQRSTUVWXYZ|:")) {
    INFO(c);
    CHECK(font_has_glyph(c));
  }
  // Distinct glyphs for all digits.
  std::vector<std::vector<uint8_t>> seen;
  for (char c : std::string("0123456789")) {
    std::vector<uint8_t> buf(6 * 7 * 3, 0);
    draw_text(buf, 6, 7, 0, 0, std::string(1, c), 1, {255, 255, 255});
    CHECK(std::find(seen.begin(), seen.end(), buf) == seen.end());
    seen.push_back(buf);
  }
  CHECK(text_width("1.00E-03", 1) == 8 * 6 - 1);
  CHECK(text_width("1.00E-03", 2) == 2 * (8 * 6 - 1));
}

// ---------------------------------------------------------------- render tool

namespace {

struct Run {
  int code = -1;
  std::string out, err;
};

Run run_render(const std::string& args, const fs::path& dir) {
  const std::string cmd = std::string(SCENE_RENDER_TOOL) + " " + args + " > " + (dir / "stdout.txt").string() +
                          " 2> " + (dir / "stderr.txt").string();
  const int status = std::system(cmd.c_str());
  Run r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  auto slurp = [](const fs::path& p) {
    std::ifstream in(p);
    std::ostringstream os;
    os << in.rdbuf();
    return os.str();
  };
  r.out = slurp(dir / "stdout.txt");
  r.err = slurp(dir / "stderr.txt");
  return r;
}

const char* kSmallScene = R"({
  "image": {"width": 48, "height": 32},
  "camera": {"type": "orthographic", "position": [0, 0, 10], "look_at": [0, 0, 0], "height": 2.2},
  "materials": [{"name": "m", "n": 30, "ks": 0.8}],
  "lights": [{"type": "directional", "direction": [0.2, 0.3, 1], "intensity": 1}],
  "meshes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "tessellation": 10, "material": "m"}]
})";

}  // namespace

TEST_CASE("render: writes the three images and one CSV line", "[scene][cli]") {
  const fs::path dir = temp_dir("cli_ok");
  std::ofstream(dir / "ball.json") << kSmallScene;
  const Run r = run_render("--scene " + (dir / "ball.json").string() + " --out-dir " + (dir / "img").string() +
                               " --csv-header",
                           dir);
  INFO(r.err);
  REQUIRE(r.code == 0);
  for (const char* suffix : {"_phong.png", "_float.png", "_interp_error.png"}) {
    const fs::path p = dir / "img" / (std::string("ball") + suffix);
    REQUIRE(fs::exists(p));
    const Png png = read_png(p);
    CHECK(png.w == 48);
  }
  CHECK_THAT(r.out, Contains("scene,width,height"));
  CHECK_THAT(r.out, Contains("\nball,48,32,"));
  fs::remove_all(dir);
}

TEST_CASE("render: bad input exits with 2, names the problem and writes nothing", "[scene][cli]") {
  const fs::path dir = temp_dir("cli_bad");
  std::string bad = kSmallScene;
  bad.replace(bad.find("\"radius\": 1"), 11, "\"radius\": -4");
  std::ofstream(dir / "bad.json") << bad;
  const fs::path out = dir / "img";

  Run r = run_render("--scene " + (dir / "bad.json").string() + " --out-dir " + out.string(), dir);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains((dir / "bad.json").string()));
  CHECK_THAT(r.err, Contains("meshes[0].radius"));
  CHECK_THAT(r.err, Contains("expected a number in (0, "));
  CHECK_FALSE(fs::exists(out));

  r = run_render("--scene " + (dir / "missing.json").string() + " --out-dir " + out.string(), dir);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("missing.json"));

  r = run_render("--out-dir " + out.string(), dir);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("--scene"));

  std::ofstream(dir / "good.json") << kSmallScene;
  r = run_render("--scene " + (dir / "good.json").string() + " --out-dir " + out.string() + " --scale -1", dir);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Contains("--scale"));
  CHECK_THAT(r.err, Contains("(0, 1000]"));
  CHECK_FALSE(fs::exists(out));
  fs::remove_all(dir);
}

// CSV numbers round-trip. render prints max_abs_interp_error, rms_interp_error and
// peak_phong as the shortest text that parses back to the same double, so they equal,
// bit for bit, what the same computation gives in this process (with the old %.6e / %.6f
// they differed from the seventh significant digit on).
TEST_CASE("render: CSV statistics round-trip to the exact doubles", "[scene][cli][roundtrip]") {
  const fs::path dir = temp_dir("cli_roundtrip");
  std::ofstream(dir / "ball.json") << kSmallScene;
  const Run r = run_render("--scene " + (dir / "ball.json").string() + " --out-dir " + (dir / "img").string(), dir);
  INFO(r.err);
  REQUIRE(r.code == 0);
  std::vector<std::string> cells;
  {
    std::istringstream in(r.out.substr(0, r.out.find('\n')));
    std::string c;
    while (std::getline(in, c, ',')) cells.push_back(c);
  }
  REQUIRE(cells.size() >= 13);
  const Scene s = parse_scene(kSmallScene, "ball.json");
  const Raster raster = rasterize(s);
  const Image phong = render(raster, phong_evaluator(s));
  const ImageErrorStats es = error_stats(difference(render(raster, float_model_evaluator()), phong));
  double peak = 0;
  for (double v : phong.value) peak = std::max(peak, v);
  REQUIRE(es.max_abs > 0.0);
  CHECK(std::strtod(cells[10].c_str(), nullptr) == es.max_abs);  // max_abs_interp_error
  CHECK(std::strtod(cells[11].c_str(), nullptr) == es.rms);      // rms_interp_error
  CHECK(std::strtod(cells[12].c_str(), nullptr) == peak);        // peak_phong
  fs::remove_all(dir);
}

// ---------------------------------------------------------------- colour images (compose.hpp)

TEST_CASE("colour difference PNG: 128 + gain (a - b) in sRGB codes, uncovered black", "[scene][image][colour]") {
  const fs::path dir = temp_dir("colour_diff");
  RgbImage a(64, 4), b(64, 4);
  // Pixel (0, 0): codes (188, 0, 255) against (188, 3, 243) (test_compose.cpp): a - b = (0, -3, +12).
  a.value[0] = {0.5, 0.0, 1.0};
  b.value[0] = {0.5, 0.001, 0.9};
  a.covered[0] = 1;
  // Pixel (1, 0): covered, equal: grey 128. Every other pixel is covered by neither: black.
  a.covered[1] = b.covered[1] = 1;
  write_code_diff_png((dir / "d.png").string(), a, b, "A - B");
  const Png png = read_png(dir / "d.png");
  CHECK(png.w == 64);
  CHECK(png.h > 4);  // the strip with the label and the range
  // R = 12 codes, gain = floor(127 / 12) = 10.
  CHECK(png.at(0, 0)[0] == 128);
  CHECK(png.at(0, 0)[1] == 128 - 30);
  CHECK(png.at(0, 0)[2] == 128 + 120);
  for (int ch = 0; ch < 3; ++ch) {
    CHECK(png.at(1, 0)[ch] == 128);
    CHECK(png.at(5, 2)[ch] == 0);
  }
  fs::remove_all(dir);
}

TEST_CASE("render --colour: the three colour images and the sRGB-code columns", "[scene][cli][colour]") {
  const fs::path dir = temp_dir("cli_colour");
  std::string scene = kSmallScene;
  const std::string ks = "\"ks\": 0.8}";
  scene.replace(scene.find(ks), ks.size(), R"("ks": 0.8, "diffuse": [0.4, 0.2, 0.1], "specular": [0.5, 0.5, 0.4]})");
  std::ofstream(dir / "ball.json") << scene;
  const Run r = run_render("--scene " + (dir / "ball.json").string() + " --out-dir " + (dir / "img").string() +
                               " --colour --csv-header",
                           dir);
  INFO(r.err);
  REQUIRE(r.code == 0);
  for (const char* suffix : {"_colour_device.png", "_colour_reference.png", "_colour_diff.png"}) {
    const fs::path p = dir / "img" / (std::string("ball") + suffix);
    REQUIRE(fs::exists(p));
    CHECK(read_png(p).w == 48);
  }
  CHECK(read_png(dir / "img" / "ball_colour_device.png").h == 32);
  CHECK_FALSE(fs::exists(dir / "img" / "ball_golden.png"));  // --golden was not given
  CHECK_THAT(r.out, Contains(",colour_max_code_r,colour_max_code_g,colour_max_code_b,colour_mean_code_r,"
                             "colour_mean_code_g,colour_mean_code_b,colour_ms\n"));
  // The CSV's colour columns are the statistics of the two images as this process composes them.
  std::vector<std::string> cells;
  {
    std::istringstream in(r.out.substr(r.out.find('\n') + 1));
    std::string line, c;
    std::getline(in, line);
    std::istringstream cs(line);
    while (std::getline(cs, c, ',')) cells.push_back(c);
  }
  REQUIRE(cells.size() == 17 + 7);
  const Scene s = parse_scene(scene, "ball.json");
  const Raster raster = rasterize(s);
  const BuildConfig& bc = build_config("default");  // render's --config default
  const device::DeviceModel dm = load_device_model(bc.f, bc.coef_hex(), bc.cos_hex());
  const ColourErrorStats st = srgb_code_error(compose(s, raster, device_unit_specular(dm)).image,
                                              compose(s, raster, reference_unit_specular(s)).image);
  for (int ch = 0; ch < 3; ++ch) {
    CHECK(std::stoi(cells[17 + static_cast<size_t>(ch)]) == st.max_abs[static_cast<size_t>(ch)]);
    CHECK(std::strtod(cells[20 + static_cast<size_t>(ch)].c_str(), nullptr) == st.mean_abs[static_cast<size_t>(ch)]);
  }
  fs::remove_all(dir);
}

TEST_CASE("render --colour: a bad colour field exits with 2, names file and field, writes nothing", "[scene][cli][colour]") {
  const fs::path dir = temp_dir("cli_colour_bad");
  const fs::path out = dir / "img";
  const struct {
    std::string from, to, field, expected;
  } cases[] = {
      {"\"ks\": 0.8}", R"("ks": 0.8, "diffuse": [0.4, -0.2, 0.1]})", "materials[0].diffuse",
       "an array of 3 finite numbers, each in [0, 1]"},
      {"\"ks\": 0.8}", R"("ks": 0.8, "brdf": "phong"})", "materials[0].brdf", "one of \"blinn_phong\""},
      {"\"intensity\": 1}", R"("intensity": 1, "color": [1, 1]})", "lights[0].color",
       "an array of 3 finite numbers, each in [0, 1000]"},
  };
  for (const auto& c : cases) {
    std::string bad = kSmallScene;
    bad.replace(bad.find(c.from), c.from.size(), c.to);
    std::ofstream(dir / "bad.json") << bad;
    const Run r = run_render("--scene " + (dir / "bad.json").string() + " --out-dir " + out.string() + " --colour", dir);
    INFO(c.field << ": " << r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Contains((dir / "bad.json").string()));
    CHECK_THAT(r.err, Contains("'" + c.field + "'"));
    CHECK_THAT(r.err, Contains(c.expected));
    CHECK_FALSE(fs::exists(out));
  }
  fs::remove_all(dir);
}
