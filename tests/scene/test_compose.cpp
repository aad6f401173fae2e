// SPDX-License-Identifier: Apache-2.0
// Colour composition (model/scene/compose.hpp) against hand-computed closed forms, and the sRGB
// transfer function against published values of IEC 61966-2-1.
#include "compose.hpp"
#include "image.hpp"
#include "raster.hpp"
#include "rom_image.hpp"
#include "scene.hpp"

#include <catch2/catch.hpp>
#include <glm/common.hpp>

#include <cmath>
#include <numbers>
#include <string>

using namespace specular;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

// A plane z = 0 facing +z that fills an orthographic view along -z, one directional light
// towards (0.8, 0, 0.6). So at every pixel N = V = (0, 0, 1), N.L is 0.6, and
// H = (L + V) / |L + V| = (0.8, 0, 1.6) / sqrt(3.2), N.H = 1.6 / sqrt(3.2) = 2 / sqrt(5): (N.H)^2 = 0.8
// and (N.H)^4 = 0.64 exactly.
std::string plane_scene(const std::string& material, const std::string& lights, const std::string& ambient) {
  return R"({"image": {"width": 16, "height": 12},
    "camera": {"type": "orthographic", "position": [0, 0, 10], "look_at": [0, 0, 0], "height": 2},)" +
         (ambient.empty() ? std::string() : "\"ambient\": " + ambient + ",") + R"("materials": [)" + material +
         R"(], "lights": [)" + lights + R"(],
    "meshes": [{"type": "plane", "center": [0, 0, 0], "normal": [0, 0, 1], "tangent": [1, 0, 0], "size": [8, 8],
                "tessellation": 1, "material": "m"}]})";
}

const std::string kColourMaterial =
    R"({"name": "m", "n": 4, "ks": 0.5, "diffuse": [0.5, 0.25, 0.1], "specular": [0.2, 0.4, 0.6],
        "emission": [0.01, 0.02, 0.03]})";
const std::string kColourLight = R"({"type": "directional", "direction": [0.8, 0, 0.6], "intensity": 1, "color": [1, 0.5, 0.25]})";

// Every covered pixel of `img` equals `want` within `tol` per channel; returns the count.
size_t check_every_pixel(const RgbImage& img, const glm::dvec3& want, double tol) {
  size_t n = 0;
  for (size_t k = 0; k < img.value.size(); ++k) {
    if (!img.covered[k]) continue;
    ++n;
    for (int ch = 0; ch < 3; ++ch) {
      INFO("pixel " << k << " channel " << ch);
      REQUIRE_THAT(img.value[k][ch], WithinAbs(want[ch], tol));
    }
  }
  return n;
}

// Unit specular intensity S = s for every pixel of every light (a stand-in for the device).
Evaluator constant_specular(double s) {
  return [s](const Span&, std::span<double> out) {
    for (double& v : out) v = s;
  };
}

}  // namespace

TEST_CASE("compose: one light, known N.L and N.H, every term by hand", "[scene][colour]") {
  const Scene s = parse_scene(plane_scene(kColourMaterial, kColourLight, "[0.1, 0.2, 0.3]"), "plane.json");
  const Raster r = rasterize(s);
  REQUIRE(r.stats.covered_pixels == 16u * 12u);
  const ColourLayers c = compose(s, r, reference_unit_specular(s));
  // primary = emission + ambient diffuse + diffuse E N.L, with E = (1, 0.5, 0.25), N.L is 0.6:
  //   r: 0.01 + 0.1 * 0.5  + 0.5  * 1    * 0.6 = 0.36
  //   g: 0.02 + 0.2 * 0.25 + 0.25 * 0.5  * 0.6 = 0.145
  //   b: 0.03 + 0.3 * 0.1  + 0.1  * 0.25 * 0.6 = 0.075
  // secondary = specular E (N.H)^4 = (0.2, 0.4 * 0.5, 0.6 * 0.25) * 0.64 = (0.128, 0.128, 0.096)
  CHECK(check_every_pixel(c.primary, {0.36, 0.145, 0.075}, 1e-12) == 16u * 12u);
  CHECK(check_every_pixel(c.secondary, {0.128, 0.128, 0.096}, 1e-12) == 16u * 12u);
  CHECK(check_every_pixel(c.image, {0.488, 0.273, 0.171}, 1e-12) == 16u * 12u);
}

TEST_CASE("compose: the device's intensity with C = 1 on the plane is (N.H)^n to its rounding", "[scene][colour][device]") {
  const Scene s = parse_scene(plane_scene(kColourMaterial, kColourLight, "[0.1, 0.2, 0.3]"), "plane.json");
  const Raster r = rasterize(s);
  const device::DeviceModel dm = load_device_model(device::Format{}, kCoefMinimaxHex, kCosHex);
  const ColourLayers c = compose(s, r, device_unit_specular(dm));
  // N and H are the same at both ends of every span, so the setup is flat (scanline_setup.cpp):
  // psi = 0 and C = A^n = (N.H)^4 = 0.64, and the device returns C cos^k(0) = C as register 1
  // holds it (15 fraction bits), times the cosine ROM's value at 0 (1 to its rounding): within
  // 2 LSBs of 0.64 before the specular colour E scales it.
  const glm::dvec3 spec_e{0.2, 0.2, 0.15};  // specular E
  for (size_t k = 0; k < c.secondary.value.size(); ++k) {
    REQUIRE(c.secondary.covered[k]);
    for (int ch = 0; ch < 3; ++ch)
      REQUIRE_THAT(c.secondary.value[k][ch], WithinAbs(spec_e[ch] * 0.64, spec_e[ch] * 2.0 / 32768));
  }
  CHECK(check_every_pixel(c.primary, {0.36, 0.145, 0.075}, 1e-12) == 16u * 12u);  // no device in it
}

TEST_CASE("compose: the device image against the reference on spheres.json, within the device budget", "[scene][colour][device]") {
  // spheres.json has no colours: specular colour ks = 0.9, light colour Is = 1, n = 1, 5, 50, 500.
  // The two images differ in S only: the device's cos^k(a psi) with C = A^n against (N.H)^n at
  // the true H. Bound: the single-bank build's absolute budget over the lobe (0.01 C, C <= 1)
  // times ks Is, plus the interpolation model's error on this scene (test_repo_scenes.cpp:
  // below 1.6e-3 in intensity), plus 2 output LSBs.
  const Scene s = load_scene("scenes/spheres.json");
  const Raster r = rasterize(s);
  const device::DeviceModel dm = load_device_model(device::Format{}, kCoefMinimaxHex, kCosHex);
  const ColourLayers dev = compose(s, r, device_unit_specular(dm));
  const ColourLayers ref = compose(s, r, reference_unit_specular(s));
  const double bound = 0.9 * build_config("single").budget.abs_lobe + 1.6e-3 + 2.0 / 32768;
  double worst = 0.0;
  for (size_t k = 0; k < dev.image.value.size(); ++k)
    for (int ch = 0; ch < 3; ++ch) worst = std::max(worst, std::abs(dev.image.value[k][ch] - ref.image.value[k][ch]));
  CHECK(worst <= bound);
  CHECK(worst > 0.0);
}

TEST_CASE("compose: every BRDF name at a known N.H, with and without its normalization", "[scene][colour]") {
  const double c = 2.0 / std::sqrt(5.0), n = 4.0;
  // The shapes as their sources write them (docs/reflectance.md), at cos = c:
  const double blinn = 0.64;                                    // c^n = (4/5)^2
  const double schlick = c / (n - n * c + c);                   // Schlick 1994
  const double u = n * (1.0 - c);
  const double schlick_mod = c / (0.5 * u * u + n - n * c + c);  // modified Schlick
  const double lyon = std::pow((n / 16.0) * (c - 1.0) + 1.0, 16.0);  // Lyon 1993, m = 16
  const double bp_norm = (n + 8.0) / (8.0 * std::numbers::pi), f16_norm = (n + 6.0) / 24.55;
  const struct {
    const char* name;
    double value;
  } want[] = {{"blinn_phong", blinn},          {"blinn_phong_normalized", bp_norm * blinn},
              {"schlick", schlick},            {"schlick_normalized", bp_norm * schlick},
              {"schlick_mod", schlick_mod},    {"schlick_mod_normalized", bp_norm * schlick_mod},
              {"lyon", lyon},                  {"lyon_normalized", bp_norm * lyon},
              {"f16", f16_norm * lyon}};
  REQUIRE(brdf_choices().size() == std::size(want));
  for (const auto& w : want) {
    INFO(w.name);
    const std::string mat = R"({"name": "m", "n": 4, "ks": 1, "specular": [1, 0.5, 0.25], "brdf": ")" +
                            std::string(w.name) + "\"}";
    const Scene s = parse_scene(plane_scene(mat, R"({"type": "directional", "direction": [0.8, 0, 0.6], "intensity": 0.5})", ""),
                                "plane.json");
    CHECK(s.materials[0].brdf.name == w.name);
    const ColourLayers cl = compose(s, rasterize(s), reference_unit_specular(s));
    // Light colour [Is, Is, Is] = 0.5 (no "color"), no diffuse: the image is the specular term.
    const glm::dvec3 e = glm::dvec3(1, 0.5, 0.25) * 0.5 * w.value;
    CHECK(check_every_pixel(cl.image, glm::min(e, glm::dvec3(1.0)), 1e-12) == 16u * 12u);
  }
}

TEST_CASE("compose: the specular sum saturates at 1 per channel, the image clamps to [0, 1]", "[scene][colour]") {
  // Two lights, S = 0.5 everywhere (a stand-in evaluator), specular colour 1: the secondary sum is
  // 0.5 (E1 + E2) = (1.25, 0.2, 0.55) before saturation, (1, 0.2, 0.55) after; the primary is the
  // emission (0.5, 0.9, 0) (no diffuse), so the image is min(1, (1.5, 1.1, 0.55)) = (1, 1, 0.55).
  const std::string mat = R"({"name": "m", "n": 4, "ks": 1, "specular": [1, 1, 1], "emission": [0.5, 0.9, 0]})";
  const std::string lights = R"({"type": "directional", "direction": [0, 0, 1], "intensity": 1, "color": [1.5, 0.2, 1]},
                                {"type": "directional", "direction": [0, 1, 1], "intensity": 1, "color": [1, 0.2, 0.1]})";
  const Scene s = parse_scene(plane_scene(mat, lights, ""), "plane.json");
  const ColourLayers c = compose(s, rasterize(s), constant_specular(0.5));
  CHECK(check_every_pixel(c.secondary, {1.0, 0.2, 0.55}, 1e-12) == 16u * 12u);
  CHECK(check_every_pixel(c.primary, {0.5, 0.9, 0.0}, 1e-12) == 16u * 12u);  // emission once, not per light
  CHECK(check_every_pixel(c.image, {1.0, 1.0, 0.55}, 1e-12) == 16u * 12u);
}

TEST_CASE("compose: a light behind the surface adds neither diffuse nor specular", "[scene][colour]") {
  // L = (0, 0, -1): N.L = -1, so max(N.L, 0) = 0; L = -V, so H is undefined and the reference's S is 0.
  const std::string lights = R"({"type": "directional", "direction": [0, 0, -1], "intensity": 1, "color": [1, 1, 1]})";
  const Scene s = parse_scene(plane_scene(kColourMaterial, lights, "[0.1, 0.2, 0.3]"), "plane.json");
  const ColourLayers c = compose(s, rasterize(s), reference_unit_specular(s));
  // emission + ambient diffuse = (0.01 + 0.05, 0.02 + 0.05, 0.03 + 0.03)
  CHECK(check_every_pixel(c.image, {0.06, 0.07, 0.06}, 1e-12) == 16u * 12u);
}

TEST_CASE("compose: a scene without colours gives the grey Phong truth in every channel", "[scene][colour]") {
  // Defaults: specular colour [ks, ks, ks], light colour [Is, Is, Is], no diffuse, emission or
  // ambient, blinn_phong, so the reference image is min(1, sum Is ks s(n) (N.H)^n): the Phong
  // truth of raster.hpp (pixel_truth, pow of the cosine) against acos then cos^n here.
  const Scene s = load_scene("scenes/torus_point.json");
  const Raster r = rasterize(s);
  const Image truth = render(r, phong_evaluator(s));
  const ColourLayers c = compose(s, r, reference_unit_specular(s));
  size_t n = 0;
  for (size_t k = 0; k < truth.value.size(); ++k) {
    REQUIRE(c.image.covered[k] == truth.covered[k]);
    if (!truth.covered[k]) continue;
    ++n;
    for (int ch = 0; ch < 3; ++ch) REQUIRE_THAT(c.image.value[k][ch], WithinAbs(std::min(truth.value[k], 1.0), 1e-12));
  }
  CHECK(n == r.stats.covered_pixels);
}

TEST_CASE("sRGB: the transfer function of IEC 61966-2-1 at published values", "[scene][colour][srgb]") {
  // The standard's breakpoint: encode(0.0031308) = 12.92 * 0.0031308 = 0.040449936, where the
  // power segment 1.055 v^(1/2.4) - 0.055 meets it (0.0404499075: they agree to 3e-8).
  CHECK_THAT(srgb_encode(0.0031308), WithinAbs(0.040449936, 1e-12));
  CHECK_THAT(1.055 * std::pow(0.0031308, 1.0 / 2.4) - 0.055, WithinAbs(0.040449936, 1e-7));
  CHECK(srgb_encode(0.0) == 0.0);
  CHECK_THAT(srgb_encode(1.0), WithinAbs(1.0, 1e-15));  // 1.055 - 0.055
  // Linear values of 8-bit codes as tabulated from the standard's decoding (code / 255):
  //   1 -> 0.000303527 (linear segment), 10 -> 0.003035270, 11 -> 0.003346536 (first code on the
  //   power segment), 64 -> 0.051269458, 118 -> 0.181164244, 128 -> 0.215860500,
  //   188 -> 0.502886458, 192 -> 0.527115126, 254 -> 0.991102097.
  const struct {
    int code;
    double linear;
  } table[] = {{1, 0.000303527}, {10, 0.003035270}, {11, 0.003346536}, {64, 0.051269458}, {118, 0.181164244},
               {128, 0.215860500}, {188, 0.502886458}, {192, 0.527115126}, {254, 0.991102097}};
  for (const auto& t : table) {
    INFO("code " << t.code);
    CHECK_THAT(srgb_decode(t.code / 255.0), WithinAbs(t.linear, 5e-10));
    // The table's 9 decimals (5e-10) times the curve's slope (at most 12.92 here).
    CHECK_THAT(srgb_encode(t.linear), WithinAbs(t.code / 255.0, 1e-8));
    CHECK(srgb_code(t.linear) == t.code);
  }
  // Linear 0.5 encodes to 0.7353570 (code 188); 18 % grey to 0.4613561 (code 118).
  CHECK_THAT(srgb_encode(0.5), WithinAbs(0.7353569830524495, 1e-12));
  CHECK(srgb_code(0.5) == 188);
  CHECK(srgb_code(0.18) == 118);
  // Out of range clamps.
  CHECK(srgb_code(-0.25) == 0);
  CHECK(srgb_code(7.0) == 255);
}

TEST_CASE("sRGB: every 8-bit code survives decode then encode", "[scene][colour][srgb]") {
  // Second method: the inverse. Decoding each code and encoding it again returns the code, and
  // encode(decode(e)) = e on a sweep of both segments.
  for (int code = 0; code <= 255; ++code) {
    INFO("code " << code);
    CHECK(srgb_code(srgb_decode(code / 255.0)) == code);
  }
  for (int i = 0; i <= 1000; ++i) {
    const double e = i / 1000.0;
    CHECK_THAT(srgb_encode(srgb_decode(e)), WithinAbs(e, 1e-12));
  }
}

TEST_CASE("sRGB-code error: worst and mean per channel over the covered pixels", "[scene][colour][srgb]") {
  RgbImage a(2, 1), b(2, 1);
  // Pixel 0 covered: linear (0.5, 0, 1) against (0.5, 0.001, 0.9). Codes (188, 0, 255) against
  // (188, round(255 * 12.92 * 0.001) = 3, round(255 * 0.9546872) = 243): differences (0, 3, 12).
  a.value[0] = {0.5, 0.0, 1.0};
  b.value[0] = {0.5, 0.001, 0.9};
  a.covered[0] = 1;
  // Pixel 1 covered by neither: not counted whatever it holds.
  a.value[1] = {1, 1, 1};
  const ColourErrorStats st = srgb_code_error(a, b);
  CHECK(st.pixels == 1);
  CHECK(st.max_abs == std::array<int, 3>{0, 3, 12});
  CHECK(st.mean_abs == std::array<double, 3>{0.0, 3.0, 12.0});
  CHECK(st.argmax == std::array<int, 2>{0, 0});
  // Linear: |0.5 - 0.5|, |0 - 0.001|, |1 - 0.9|.
  CHECK_THAT(st.max_linear[0], WithinAbs(0.0, 1e-15));
  CHECK_THAT(st.max_linear[1], WithinAbs(0.001, 1e-15));
  CHECK_THAT(st.max_linear[2], WithinAbs(0.1, 1e-15));
  b.covered[1] = 1;  // now counted: |1 - 0| = 255 codes in every channel, means over two pixels
  const ColourErrorStats st2 = srgb_code_error(a, b);
  CHECK(st2.pixels == 2);
  CHECK(st2.max_abs == std::array<int, 3>{255, 255, 255});
  CHECK(st2.mean_abs == std::array<double, 3>{127.5, 129.0, 133.5});
  CHECK(st2.argmax == std::array<int, 2>{1, 0});
  CHECK(st2.max_linear == std::array<double, 3>{1.0, 1.0, 1.0});
}

TEST_CASE("bunny_colour.json, duck_colour.json: the grey scenes' geometry in colour, device within a few codes", "[scene][colour][repo]") {
  const device::DeviceModel dm = load_device_model(device::Format{}, kCoefMinimaxHex, kCosHex);
  const struct {
    const char* grey;
    const char* colour;
    size_t lights;
    int worst_codes;  // bound on the worst |device - reference| in sRGB codes, any channel
  } cases[] = {{"scenes/bunny.json", "scenes/bunny_colour.json", 2, 3}, {"scenes/duck.json", "scenes/duck_colour.json", 3, 6}};
  for (const auto& c : cases) {
    INFO(c.colour);
    const Scene g = load_scene(c.grey), s = load_scene(c.colour);
    REQUIRE(s.lights.size() == c.lights);
    for (const Light& l : s.lights) CHECK(l.color.has_value());
    CHECK(s.materials[0].diffuse != glm::dvec3(0.0));
    CHECK(s.materials[0].specular.has_value());
    // The same mesh, camera and image: the same visible runs, one span each per light.
    const Raster rg = rasterize(g), r = rasterize(s);
    CHECK(r.stats.covered_pixels == rg.stats.covered_pixels);
    CHECK(r.spans.size() == rg.spans.size() / g.lights.size() * s.lights.size());
    // Measured with the default device (render --colour): worst 2 codes (bunny), 5 (duck: the blue
    // channel, dark, where sRGB is steepest), mean below 0.11 codes in every channel; bounds at
    // one code above the worst and 0.2 codes on the mean.
    const ColourErrorStats e = srgb_code_error(compose(s, r, device_unit_specular(dm)).image,
                                               compose(s, r, reference_unit_specular(s)).image);
    CHECK(e.pixels == r.stats.covered_pixels);
    for (int ch = 0; ch < 3; ++ch) {
      CHECK(e.max_abs[ch] <= c.worst_codes);
      CHECK(e.mean_abs[ch] < 0.2);
    }
  }
}
