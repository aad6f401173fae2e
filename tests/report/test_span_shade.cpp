// SPDX-License-Identifier: Apache-2.0
// The span evaluators of model/reference/span_shade.hpp and `specular shade`, against
// independent references: cos^n by std::pow/std::cos in long double, and the geometry of the
// lerped normal worked out in long double here. No timing assertions.
#include "span_shade.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <sys/wait.h>
#include <vector>

using namespace specular;

namespace {

long double cosn_ref(long double psi, long double n) {
  const long double c = std::cos(psi);
  return c > 0 ? std::pow(c, n) : 0.0L;
}

long double epicenter_end_ref(long double n) { return n > 1 ? std::atan(1.0L / std::sqrt(n - 1)) : 1.5707963267948966L; }

// Worst relative error over the epicenter [0, x_e(n)] at 4001 pixels of one span.
double worst_epicenter(double n, SimdPath path) {
  const int len = 4000;
  const double xe = static_cast<double>(epicenter_end_ref(n));
  const double dpsi = xe / len;
  std::vector<float> out(len + 1);
  device_span(make_device_span_plan(n), 0.0, dpsi, len, 1.0f, out.data(), path);
  double worst = 0.0;
  for (int i = 0; i <= len; ++i) {
    const long double ref = cosn_ref(static_cast<long double>(i) * dpsi, n);
    worst = std::max(worst, static_cast<double>(std::abs((out[i] - ref) / ref)));
  }
  return worst;
}

struct Run {
  int code;
  std::string out;
};
Run run_cli(const std::string& args) {
  const std::string cmd = std::string(SPECULAR_CLI) + " " + args + " 2>/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p);
  std::string out;
  std::array<char, 4096> buf{};
  size_t got;
  while ((got = fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), got);
  const int st = pclose(p);
  return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, out};
}

std::vector<std::vector<std::string>> csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  size_t pos = 0;
  while (pos < text.size()) {
    const size_t eol = text.find('\n', pos);
    const std::string line = text.substr(pos, eol - pos);
    std::vector<std::string> cells;
    size_t a = 0;
    for (size_t b; (b = line.find(',', a)) != std::string::npos; a = b + 1) cells.push_back(line.substr(a, b - a));
    cells.push_back(line.substr(a));
    rows.push_back(cells);
    if (eol == std::string::npos) break;
    pos = eol + 1;
  }
  return rows;
}

}  // namespace

TEST_CASE("device_span: within 0.1 % of cos^n over the epicenter", "[span]") {
  // Integer n (the device's exponents) plus two reals inside wide banks; see the next test
  // for reals in (2, 3).
  const double n = GENERATE(2.0, 3.0, 5.0, 7.0, 9.0, 11.0, 13.0, 15.0, 17.0, 20.0, 31.0, 33.0, 47.0, 63.0, 65.0,
                            100.0, 333.0, 500.0, 999.0, 1000.0, 20.5, 250.5);
  const double w_scalar = worst_epicenter(n, SimdPath::scalar);
  INFO("n = " << n << ": scalar path worst " << w_scalar);
  CHECK(w_scalar <= 1e-3);
  if (cpu_has_avx2()) {
    const double w_avx2 = worst_epicenter(n, SimdPath::avx2);
    INFO("avx2 path worst " << w_avx2);
    CHECK(w_avx2 <= 1e-3);
  }
}

TEST_CASE("device_span: real n between the first banks is the weak spot (n = 2.5: k = 2)", "[span]") {
  // Documented in span_shade.hpp: the bank set is tuned for integer n; n = 2.5 with k = 2
  // measures 0.254 %. Kept here so a change of the bank rule shows up.
  CHECK(make_device_span_plan(2.5).k == 2);
  CHECK(worst_epicenter(2.5, SimdPath::scalar) <= 3e-3);
}

TEST_CASE("device_span: exact banks (k = n, a = 1) are float-accurate", "[span]") {
  for (int n : {1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 24, 32, 48, 64}) {
    const DeviceSpanPlan& p = device_span_plan(n);
    CHECK(p.k == n);
    CHECK(p.a == 1.0);
    // n = 1 too: over [0, pi/3] (cos >= 1/2) the relative error stays at float rounding.
    const double xe = n > 1 ? static_cast<double>(epicenter_end_ref(n)) : 1.0471975511965976;
    const int len = 500;
    std::vector<float> out(len + 1);
    device_span(p, 0.0, xe / len, len, 1.0f, out.data());
    for (int i = 0; i <= len; ++i) {
      const long double ref = cosn_ref(static_cast<long double>(i) * (xe / len), n);
      REQUIRE(std::abs((out[i] - ref) / ref) < 2e-5L);
    }
  }
}

TEST_CASE("device_span: AVX2 and scalar paths agree, C scales, both directions", "[span]") {
  if (!cpu_has_avx2()) {
    CHECK_THROWS_AS(resolve(SimdPath::avx2), std::runtime_error);
    return;
  }
  CHECK(resolve(SimdPath::automatic) == SimdPath::avx2);
  for (int n : {1, 5, 11, 50, 500, 1000}) {
    const int len = 2047;  // not a multiple of the vector width: the tails are covered
    std::vector<float> a(len + 1), s(len + 1);
    const double psi0 = -2.0, dpsi = 4.0 / len;  // crosses both cut-offs at +-pi/2 / a
    device_span(device_span_plan(n), psi0, dpsi, len, 0.75f, a.data(), SimdPath::avx2);
    device_span(device_span_plan(n), psi0, dpsi, len, 0.75f, s.data(), SimdPath::scalar);
    for (int i = 0; i <= len; ++i) {
      const double psi = psi0 + i * dpsi;
      const long double ref = 0.75L * cosn_ref(psi, n);
      // Both paths: within 0.1 % of the reference in the epicenter (plus float rounding),
      // within 1e-2 absolute over the rest of the lobe (the shape's own lobe error).
      const long double tol = std::abs(psi) <= epicenter_end_ref(n) ? 1e-3L * ref + 1e-7L : 1e-2L;
      REQUIRE(std::abs(a[i] - ref) <= tol);
      REQUIRE(std::abs(s[i] - ref) <= tol);
      REQUIRE(std::abs(a[i] - s[i]) <= 1e-5f * s[i] + 1e-7f);
    }
  }
}

TEST_CASE("device_span: edge cases", "[span]") {
  const DeviceSpanPlan& p = device_span_plan(50);
  SECTION("len = 0 writes exactly one pixel") {
    std::vector<float> out{-1.0f, -1.0f};
    device_span(p, 0.0, 0.1, 0, 1.0f, out.data());
    CHECK(out[0] == 1.0f);
    CHECK(out[1] == -1.0f);
  }
  SECTION("negative len writes nothing") {
    float out = -1.0f;
    device_span(p, 0.0, 0.1, -1, 1.0f, &out);
    CHECK(out == -1.0f);
  }
  SECTION("beyond +-pi/2 gives 0 for every n, also n = 1") {
    for (int n : {1, 2, 50, 1000}) {
      std::vector<float> out(9);
      device_span(device_span_plan(n), 1.5708, 0.5, 8, 1.0f, out.data());  // 1.5708 .. 5.57
      for (float v : out) CHECK(v == 0.0f);
      device_span(device_span_plan(n), -1.5708, -0.5, 8, 1.0f, out.data());
      for (float v : out) CHECK(v == 0.0f);
    }
  }
  SECTION("n = 1 is cos psi") {
    std::vector<float> out(101);
    device_span(device_span_plan(1), -1.5, 0.03, 100, 2.0f, out.data());
    for (int i = 0; i <= 100; ++i) {
      const long double ref = 2.0L * cosn_ref(-1.5L + i * 0.03L, 1.0L);
      REQUIRE(std::abs(out[i] - ref) < 1e-6L);
    }
  }
  SECTION("plans reject n outside [1, 1000]") {
    CHECK_THROWS_AS(make_device_span_plan(0.5), std::invalid_argument);
    CHECK_THROWS_AS(make_device_span_plan(1000.5), std::invalid_argument);
    CHECK_THROWS_AS(device_span_plan(0), std::invalid_argument);
    CHECK_THROWS_AS(device_span_plan(1001), std::invalid_argument);
  }
}

TEST_CASE("pow_cos_span: double cos^n", "[span]") {
  std::vector<double> out(201);
  pow_cos_span(37.0, -3.0, 0.03, 200, 0.5, out.data());
  for (int i = 0; i <= 200; ++i) {
    const double psi = -3.0 + i * 0.03;  // the span's pixel angle, as defined (double)
    const long double ref = 0.5L * cosn_ref(psi, 37.0L);
    REQUIRE(std::abs(out[i] - ref) <= 1e-13L * ref);
  }
}

TEST_CASE("phong_span: scalar and SLEEF paths against the lerped-normal geometry", "[span]") {
  const double n = GENERATE(1.0, 5.0, 50.0, 500.0);
  const int len = 1001;
  const Vec3f n0{-0.6f, 0.0f, 0.8f}, n1{0.28f, 0.0f, 0.96f}, h{0.0f, 0.0f, 1.0f};
  std::vector<float> sc(len + 1), vec(len + 1);
  phong_span(n0, n1, h, static_cast<float>(n), len, 1.0f, sc.data(), SimdPath::scalar);
  phong_span(n0, n1, h, static_cast<float>(n), len, 1.0f, vec.data(), SimdPath::automatic);
  for (int i = 0; i <= len; ++i) {
    // Independent reference: the lerped normal in long double, its angle to h, cos^n.
    const long double t = static_cast<long double>(i) / len;
    const long double x = n0[0] + t * (n1[0] - n0[0]), z = n0[2] + t * (n1[2] - n0[2]);
    const long double c = z / std::sqrt(x * x + z * z);
    const long double ref = std::pow(c, static_cast<long double>(n));
    // float: c to a few ulp, c^n relative error about n * 1.2e-7 * a few
    const long double tol = (2e-6L + 4e-7L * n) * ref + 1e-37L;  // + float underflow
    REQUIRE(std::abs(sc[i] - ref) <= tol);
    REQUIRE(std::abs(vec[i] - ref) <= tol);
    CHECK(phong_pixel_angle(n0, n1, h, len, i) == Approx(static_cast<double>(std::atan2(std::abs(x), z))).margin(1e-7));
  }
  if (cpu_has_avx2()) {
    std::vector<float> forced(len + 1);
    phong_span(n0, n1, h, static_cast<float>(n), len, 1.0f, forced.data(), SimdPath::avx2);
    CHECK(forced == vec);
  }
}

TEST_CASE("phong_span: back-facing and degenerate normals give 0", "[span]") {
  const Vec3f h{0.0f, 0.0f, 1.0f};
  for (SimdPath p : {SimdPath::scalar, SimdPath::automatic}) {
    std::vector<float> out(3, -1.0f);
    phong_span({0.0f, 0.0f, -1.0f}, {1.0f, 0.0f, -0.1f}, h, 10.0f, 2, 1.0f, out.data(), p);
    for (float v : out) CHECK(v == 0.0f);
    phong_span({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, h, 10.0f, 2, 1.0f, out.data(), p);  // |N| = 0
    for (float v : out) CHECK(v == 0.0f);
  }
}

TEST_CASE("specular shade: CSV against cos^n", "[span][cli]") {
  const std::string ev = GENERATE(as<std::string>{}, "device_simd", "pow_cos", "phong_scalar", "phong_sleef", "pow",
                                  "exp2poly", "lut256", "patent_minimax", "device_minimax");
  const Run r = run_cli("shade --evaluator " + ev + " --n 40 --psi0 -0.2 --dpsi 0.01 --len 40 --c 0.5");
  REQUIRE(r.code == 0);
  const auto rows = csv(r.out);
  REQUIRE(rows.size() == 42);
  CHECK(rows[0] == std::vector<std::string>{"i", "psi", "value"});
  // Accuracy by evaluator class: exact ones to 1e-6, the approximations to their documented
  // epicenter bounds (here all pixels are inside the epicenter, x_e(40) = 0.159... covers
  // |psi| <= 0.159; outside it, absolute 5e-3).
  const double rel = ev == "lut256" ? 0.2 : (ev == "device_minimax" || ev == "patent_minimax") ? 0.01 : 1e-3;
  for (int i = 0; i <= 40; ++i) {
    const auto& row = rows[i + 1];
    REQUIRE(row.size() == 3);
    CHECK(row[0] == std::to_string(i));
    const double psi = std::stod(row[1]), v = std::stod(row[2]);
    const long double ref = 0.5L * cosn_ref(psi, 40.0L);
    if (ev != "phong_scalar" && ev != "phong_sleef" && ev != "device_minimax") CHECK(psi == -0.2 + i * 0.01);
    INFO(ev << " i = " << i << " psi = " << psi << " value " << v << " ref " << static_cast<double>(ref));
    CHECK(std::abs(v - ref) <= rel * ref + (std::abs(psi) > 0.159 ? 5e-3 : 1e-6));
  }
}

TEST_CASE("specular shade: shortest round-trip numbers", "[span][cli]") {
  const Run r = run_cli("shade --evaluator pow_cos --n 1 --psi0 0 --dpsi 0.1 --len 1");
  REQUIRE(r.code == 0);
  // cos(0.1) = 0.9950041652780258 (shortest round-trip text of the double)
  CHECK(r.out == "i,psi,value\n0,0,1\n1,0.1," + std::string([] {
                   char b[64];
                   std::snprintf(b, sizeof b, "%.17g", std::cos(0.1));
                   std::string s(b);
                   return std::stod(s) == std::stod("0.9950041652780258") ? std::string("0.9950041652780258") : s;
                 }()) + "\n");
}

TEST_CASE("specular shade: bad input exits 2 with nothing on stdout", "[span][cli]") {
  const std::string ok = " --n 50 --psi0 0 --dpsi 0.01 --len 10";
  for (const std::string& args : {
           std::string("shade --evaluator nope") + ok,
           std::string("shade --evaluator device_simd --n 0 --psi0 0 --dpsi 0.01 --len 10"),
           std::string("shade --evaluator device_simd --n 1001 --psi0 0 --dpsi 0.01 --len 10"),
           std::string("shade --evaluator device --n 50.5 --psi0 0 --dpsi 0.01 --len 10"),
           std::string("shade --evaluator device_simd --n 50 --psi0 7 --dpsi 0.01 --len 10"),
           std::string("shade --evaluator device_simd --n 50 --psi0 0 --dpsi 2 --len 10"),
           std::string("shade --evaluator device_simd --n 50 --psi0 0 --dpsi 0.01 --len 2048"),
           std::string("shade --evaluator device_simd --n 50 --psi0 0 --dpsi 0.01 --len 1.5"),
           std::string("shade --evaluator device_simd --n 50 --psi0 0 --dpsi 0.01 --len -1"),
           std::string("shade --evaluator device_simd --n x --psi0 0 --dpsi 0.01 --len 10"),
           std::string("shade --evaluator device_simd") + ok + " --c -1",
           std::string("shade --evaluator device") + ok + " --c 2",
           std::string("shade --evaluator device_simd") + ok + " --simd sse9",
           std::string("shade --evaluator pow") + ok + " --simd scalar",
           std::string("shade --evaluator phong_scalar --n 50 --psi0 0 --dpsi 0.5 --len 10"),
           std::string("shade --evaluator device_simd --n 50 --psi0 0 --dpsi 0.01"),
       }) {
    const Run r = run_cli(args);
    INFO(args);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
  }
}
