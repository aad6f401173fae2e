// SPDX-License-Identifier: Apache-2.0
// The cross-span shaders of model/bench/shade_spans.hpp (scene_bench's methods) against their
// references, and scene_bench's JSON. No timing assertions.
//   device: the same pixels as device_span on the same registers (the same float arithmetic),
//           and within device_span's documented accuracy (model/reference/span_shade.hpp) of
//           C cos^n(psi_i) decoded from the registers in double;
//   phong:  the per-pixel truth of model/scene/raster.hpp (pixel_truth, double, true H per
//           pixel) within float accuracy, on scenes with a constant H, a point light, a
//           perspective camera and both;
//   pow_cos: pow_cos_span per span.
#include "shade_spans.hpp"

#include "metrics.hpp"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using namespace specular;

namespace {

host::RegisterBatch registers_of(const std::vector<ScanlineInput>& in, const device::Format& f) {
  host::SpanBatch b;
  for (const ScanlineInput& s : in) b.push_back(s);
  host::RegisterBatch r;
  host::setup_batch(b, f, r);
  return r;
}

// C cos^n(psi_i) from the registers in double, 0 where |psi_i| >= pi/2 or n is invalid.
double register_pixel(const host::RegisterBatch& r, size_t s, int i, const device::Format& f) {
  if (r.n[s] < 1 || r.n[s] > 1000) return 0.0;
  const double psi = device::angle_value(r.psi0[s], f) + i * device::angle_value(r.dpsi[s], f);
  if (!(std::abs(psi) < std::numbers::pi / 2)) return 0.0;
  return device::c_value(r.c[s], f) * std::pow(std::cos(psi), static_cast<double>(r.n[s]));
}

struct DeviceCheck {
  size_t pixels = 0, differ_from_device_span = 0;
  double worst_rel_epicenter = 0.0, worst_abs_over_c = 0.0;
};

// avx512: DeviceShader::shade_avx512, compared with device_span's AVX2 path (the same
// arithmetic, wider vectors).
DeviceCheck check_device(const host::RegisterBatch& r, const device::Format& f, SimdPath path, bool avx512 = false) {
  const host::DeviceShader shader(f);
  std::vector<float> out(host::pixel_count(r));
  if (avx512)
    shader.shade_avx512(r, out.data());
  else
    shader.shade(r, out.data(), path);
  DeviceCheck c;
  size_t at = 0;
  std::vector<float> ref;
  for (size_t s = 0; s < r.size(); ++s) {
    const int len = static_cast<int>(r.len[s]);
    ref.assign(static_cast<size_t>(len) + 1, 0.0f);
    const bool valid = r.n[s] >= 1 && r.n[s] <= 1000;
    if (valid)
      device_span(device_span_plan(static_cast<int>(r.n[s])), device::angle_value(r.psi0[s], f),
                  device::angle_value(r.dpsi[s], f), len, static_cast<float>(device::c_value(r.c[s], f)), ref.data(), path);
    const double C = device::c_value(r.c[s], f);
    const double xe = valid ? epicenter_end(r.n[s]) : 0.0;
    for (int i = 0; i <= len; ++i, ++at) {
      c.differ_from_device_span += out[at] != ref[static_cast<size_t>(i)];
      const double want = register_pixel(r, s, i, f);
      const double psi = device::angle_value(r.psi0[s], f) + i * device::angle_value(r.dpsi[s], f);
      if (C > 0) c.worst_abs_over_c = std::max(c.worst_abs_over_c, std::abs(out[at] - want) / C);
      if (valid && std::abs(psi) <= xe && want > 1e-3)
        c.worst_rel_epicenter = std::max(c.worst_rel_epicenter, std::abs(out[at] - want) / want);
    }
  }
  c.pixels = at;
  return c;
}

// Phong output against pixel_truth: the error as a fraction of what float arithmetic allows,
// |v - t| <= C (2e-6 + n 1.2e-6 t / C): a few ulp of the cosine, amplified n times by the
// power (d(c^n) = n c^(n-1) dc), plus a few ulp of C.
struct PhongCheck {
  size_t pixels = 0;
  double worst = 0.0;  // <= 1 passes
  double worst_abs = 0.0;
};

PhongCheck check_phong(const Scene& scene, const std::vector<Span>& spans, SimdPath path, bool avx512 = false) {
  const host::PhongSpans ps = host::phong_spans(scene, spans);
  std::vector<float> out(ps.pixels());
  if (avx512)
    host::shade_phong_avx512(ps, out.data());
  else
    host::shade_phong(ps, out.data(), path);
  PhongCheck c;
  size_t at = 0;
  for (const Span& s : spans) {
    const double C = s.setup_in.is * s.setup_in.ks * s.setup_in.norm;
    for (int i = 0; i <= s.length(); ++i, ++at) {
      const double t = pixel_truth(scene, s, i);
      const double err = std::abs(out[at] - t);
      const double allow = C * 2e-6 + s.setup_in.n * 1.2e-6 * t;
      c.worst = std::max(c.worst, err / allow);
      c.worst_abs = std::max(c.worst_abs, err);
    }
  }
  c.pixels = at;
  return c;
}

std::vector<SimdPath> paths() {
  std::vector<SimdPath> p{SimdPath::scalar};
  if (cpu_has_avx2()) p.push_back(SimdPath::avx2);
  return p;
}

}  // namespace

TEST_CASE("DeviceShader: device_span's pixels, across spans of every length and n", "[shade_spans]") {
  const device::Format f;
  // random_spans: n over 1..1000 in random order (k changes from span to span), l up to 2047
  // (stage-3 passes split between spans and whole long spans), hard cases, saturated C.
  const host::RegisterBatch r = registers_of(host::random_spans(6000, 77), f);
  for (SimdPath path : paths()) {
    INFO("path " << to_string(path));
    const DeviceCheck c = check_device(r, f, path);
    CHECK(c.pixels == host::pixel_count(r));
    CHECK(c.differ_from_device_span == 0);
    // model/reference/span_shade.hpp: 0.0545 % worst shape error in the epicenter over
    // n = 2..1000 plus a few 1e-6 of float; about 6e-3 of C over the lobe.
    CHECK(c.worst_rel_epicenter < 6e-4);
    CHECK(c.worst_abs_over_c < 6.5e-3);
  }
  if (host::cpu_has_avx512()) {
    const DeviceCheck c = check_device(r, f, SimdPath::avx2, true);
    CHECK(c.differ_from_device_span == 0);
    CHECK(c.worst_rel_epicenter < 6e-4);
  } else {
    std::vector<float> out(host::pixel_count(r));
    CHECK_THROWS_AS(host::DeviceShader(f).shade_avx512(r, out.data()), std::runtime_error);
  }
}

TEST_CASE("DeviceShader: material by material, short spans, one span", "[shade_spans]") {
  const device::Format f;
  for (int len : {0, 1, 2, 7, 8, 9, 1023, 2047}) {
    std::vector<ScanlineInput> in = host::random_spans_of_length(len > 100 ? 50 : 3000, 5 + len, len);
    std::stable_sort(in.begin(), in.end(), [](const ScanlineInput& a, const ScanlineInput& b) { return a.n < b.n; });
    const host::RegisterBatch r = registers_of(in, f);
    for (SimdPath path : paths()) {
      INFO("l = " << len << ", path " << to_string(path));
      const DeviceCheck c = check_device(r, f, path);
      CHECK(c.differ_from_device_span == 0);
      CHECK(c.worst_rel_epicenter < 6e-4);
    }
  }
  const host::RegisterBatch one = registers_of(host::random_spans_of_length(1, 9, 4), f);
  CHECK(check_device(one, f, SimdPath::automatic).differ_from_device_span == 0);
  const host::RegisterBatch none;
  host::DeviceShader(f).shade(none, nullptr);  // nothing to do, nothing written
}

TEST_CASE("DeviceShader: invalid n codes are dark, len above the counter throws", "[shade_spans]") {
  const device::Format f;
  host::RegisterBatch r = registers_of(host::random_spans_of_length(4, 3, 5), f);
  for (size_t s = 0; s < r.size(); ++s) r.c[s] = 1u << 14;  // C = 0.5
  r.n[1] = 0;
  r.n[2] = 1001;
  r.n[3] = 1023;
  std::vector<float> out(host::pixel_count(r), -1.0f);
  host::DeviceShader(f).shade(r, out.data());
  for (size_t i = 6; i < out.size(); ++i) CHECK(out[i] == 0.0f);
  r.len[0] = 2048;
  std::vector<float> big(host::pixel_count(r));
  CHECK_THROWS_AS(host::DeviceShader(f).shade(r, big.data()), std::invalid_argument);
}

TEST_CASE("order_for_shading: by light, material, flat spans first, raster order kept", "[shade_spans]") {
  // dense_mesh: two lights, two materials, flat and other spans in each.
  const std::vector<Span> in = rasterize(load_scene("scenes/dense_mesh.json")).spans;
  // Tag every input span with its index (triangle is not used by the order), so that the output
  // can be checked as a permutation and for stability.
  std::vector<Span> tagged = in;
  for (size_t i = 0; i < tagged.size(); ++i) tagged[i].triangle = static_cast<int>(i);
  const std::vector<Span> out = host::order_for_shading(tagged);
  REQUIRE(out.size() == in.size());
  std::vector<int> seen(in.size(), 0);
  size_t flats = 0;
  for (const Span& s : out) ++seen.at(static_cast<size_t>(s.triangle)), flats += host::is_flat(s.setup_in);
  CHECK(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }));
  CHECK(flats > 0);
  CHECK(flats < out.size());
  auto key = [](const Span& s) { return std::array<int, 3>{s.light, s.material, host::is_flat(s.setup_in) ? 0 : 1}; };
  for (size_t i = 1; i < out.size(); ++i) {
    INFO("position " << i);
    const auto a = key(out[i - 1]), b = key(out[i]);
    REQUIRE(a <= b);                                      // grouped, flat first in each group
    if (a == b) REQUIRE(out[i - 1].triangle < out[i].triangle);  // the input (raster) order within
  }
  // is_flat is the exact test: a one-pixel span is flat, a turn of one ulp is not.
  ScanlineInput s = in.front().setup_in;
  s.n2 = s.n1, s.he = s.h1;
  CHECK(host::is_flat(s));
  s.he.x = std::nextafter(s.he.x, 2.0);
  CHECK_FALSE(host::is_flat(s));
}

TEST_CASE("shade_phong: the per-pixel truth within float accuracy", "[shade_spans]") {
  // dense_mesh: orthographic, a directional light (constant H) and a point light, two
  // materials; torus_point: point light and perspective camera; duck: directional light and
  // perspective camera (a model mesh).
  for (const char* name : {"scenes/dense_mesh.json", "scenes/torus_point.json", "scenes/duck.json"}) {
    const Scene scene = load_scene(name);
    const std::vector<Span> spans = host::order_for_shading(rasterize(scene).spans);
    for (SimdPath path : paths()) {
      INFO(name << ", path " << to_string(path));
      const PhongCheck c = check_phong(scene, spans, path);
      CHECK(c.pixels > 10000);
      CHECK(c.worst <= 1.0);
      CHECK(c.worst_abs < 2e-4);
    }
    if (host::cpu_has_avx512()) {
      INFO(name << ", AVX-512");
      const PhongCheck c = check_phong(scene, spans, SimdPath::avx2, true);
      CHECK(c.worst <= 1.0);
    }
  }
}

TEST_CASE("shade_phong: synthetic spans with H per span against the lerped normal in double", "[shade_spans]") {
  std::vector<ScanlineInput> in = host::random_spans(3000, 11);
  for (ScanlineInput& s : in) s.he = s.h1;
  const host::PhongSpans ps = host::phong_spans(in);
  for (SimdPath path : paths()) {
    std::vector<float> out(ps.pixels());
    host::shade_phong(ps, out.data(), path);
    size_t at = 0;
    double worst = 0.0;
    for (const ScanlineInput& s : in)
      for (int i = 0; i <= s.l; ++i, ++at) {
        const double t = s.l > 0 ? static_cast<double>(i) / s.l : 0.0;
        const glm::dvec3 N = glm::normalize((1.0 - t) * glm::dvec3(glm::vec3(s.n1)) + t * glm::dvec3(glm::vec3(s.n2)));
        const double c = glm::dot(N, glm::dvec3(glm::vec3(s.h1)));
        const double C = s.is * s.ks * s.norm;
        const double want = c > 0 ? C * std::pow(c, s.n) : 0.0;
        // Opposite end normals make N vanish mid-span, where no float evaluation is stable.
        if (glm::length((1.0 - t) * s.n1 + t * s.n2) < 0.1) continue;
        worst = std::max(worst, std::abs(out[at] - want) / (C * 2e-6 + s.n * 1.2e-6 * want));
      }
    INFO("path " << to_string(path));
    CHECK(at == ps.pixels());
    CHECK(worst <= 1.0);
  }
}

TEST_CASE("shade_pow_cos: pow_cos_span per span", "[shade_spans]") {
  const device::Format f;
  const host::RegisterBatch r = registers_of(host::random_spans(500, 13), f);
  std::vector<double> out(host::pixel_count(r));
  host::shade_pow_cos(r, f, out.data());
  size_t at = 0;
  size_t bad = 0;
  for (size_t s = 0; s < r.size(); ++s)
    for (int i = 0; i <= static_cast<int>(r.len[s]); ++i, ++at) {
      const double psi = device::angle_value(r.psi0[s], f) + i * device::angle_value(r.dpsi[s], f);
      const double c = std::cos(psi);
      const double want = c > 0 ? device::c_value(r.c[s], f) * std::pow(c, static_cast<double>(r.n[s])) : 0.0;
      bad += std::abs(out[at] - want) > 1e-12;
    }
  CHECK(bad == 0);
}

TEST_CASE("scene_bench: JSON fields of one small scene", "[shade_spans][scene_bench]") {
  const std::string json_path =
      (std::filesystem::temp_directory_path() / ("scene_bench_test_" + std::to_string(getpid()) + ".json")).string();
  std::remove(json_path.c_str());
  const std::string cmd = std::string(SCENE_BENCH_CLI) +
                          " --reps 1 --min-time 0.001 --max-len 3 --break-even-spans 256 --json " + json_path +
                          " scenes/spheres.json > /dev/null";
  const int st = std::system(cmd.c_str());
  REQUIRE(WIFEXITED(st));
  REQUIRE(WEXITSTATUS(st) == 0);
  std::ifstream f(json_path);
  REQUIRE(f);
  const nlohmann::json j = nlohmann::json::parse(f);
  CHECK(j.at("fmax_mhz").get<double>() > 0);
  CHECK(!j.at("simd").get<std::string>().empty());
  REQUIRE(j.at("scenes").size() == 1);
  const auto& s = j["scenes"][0];
  CHECK(s.at("scene") == "spheres");
  CHECK(s.at("spans").get<double>() > 0);
  CHECK(s.at("pixels").get<double>() >= s.at("spans").get<double>());
  CHECK(s.at("mean_span").get<double>() >= 1.0);
  for (const char* m : {"device", "phong_sleef", "phong_scalar", "pow_cos"}) {
    CHECK(s.at("ns_per_pixel").at(m).get<double>() > 0);
    CHECK(s.at("speedup_vs_phong_sleef").at(m).get<double>() > 0);
  }
  for (const char* k : {"setup_mspans_per_s", "core_mspans_per_s_at_fmax", "host_cores_to_feed",
                        "device_setup_ns_per_pixel", "device_shade_ns_per_pixel"})
    CHECK(s.at(k).get<double>() > 0);
  for (const auto& [isa, m] : s.at("isa_matched").items())
    for (const char* k : {"device", "phong_sleef", "speedup"}) {
      INFO(isa << " " << k);
      CHECK(m.at(k).get<double>() > 0);
    }
  CHECK(s.at("isa_matched").contains("avx2") == cpu_has_avx2());
  CHECK(s.at("isa_matched").contains("avx512") == (cpu_has_avx2() && host::cpu_has_avx512()));
  // Its own sanity figures (the tests above are the real check): device against C cos^n
  // and Phong against the truth.
  CHECK(s.at("max_abs_device_vs_pow_cos").get<double>() < 1e-2);
  CHECK(s.at("max_abs_phong_sleef_vs_truth").get<double>() < 2e-4);
  REQUIRE(j.at("break_even").size() == 4);
  for (const auto& r : j["break_even"]) {
    CHECK(r.at("device").get<double>() > 0);
    CHECK(r.at("phong_sleef").get<double>() > 0);
  }
  std::remove(json_path.c_str());
}

TEST_CASE("scene_bench: bad arguments exit 2", "[shade_spans][scene_bench]") {
  for (const char* args : {" scenes/no_such_scene.json", " --reps 0 scenes/spheres.json", " --fpga-figures /nonexistent scenes/spheres.json", ""}) {
    const int st = std::system((std::string(SCENE_BENCH_CLI) + args + " > /dev/null 2>&1").c_str());
    INFO(args);
    REQUIRE(WIFEXITED(st));
    CHECK(WEXITSTATUS(st) == 2);
  }
}
