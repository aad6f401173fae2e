// SPDX-License-Identifier: Apache-2.0
// `specular shade`: one span through one evaluator, CSV `i,psi,value`.
//
//   specular shade --evaluator NAME --n N --psi0 X --dpsi D --len L [--c C] [--simd PATH]
//
// Pixels i = 0..L at psi_i = X + i D (radians; the angle between N and H). `value` is
// C times the evaluator's approximation of cos^n(psi_i); `psi` is the angle the evaluator
// actually shaded:
//   device_simd                    psi0 + i dpsi (model/reference/span_shade.hpp device_span, float)
//   pow_cos                        psi0 + i dpsi (double std::pow(std::cos psi, n))
//   phong_scalar, phong_sleef      the normal is lerped between N(psi_0) and N(psi_L) and
//                                  renormalized, as a renderer does, so the angle is not
//                                  linear in i: psi is the angle of the lerped normal
//                                  (atan2 in double); needs |L D| <= 3
//   pow, exp2poly, lut256, schlick, schlick_mod, lyon16   cosine input c = cos psi_i
//   prototype, patent, patent_minimax                      angle input psi_i
//   device, device_minimax         the golden fixed-point model: psi0, dpsi and C are
//                                  quantized into its registers (psi is the quantized
//                                  angle); integer n, C < 2
// Numbers are the shortest text that parses back to the same value (std::to_chars; float
// results as floats). Bad arguments throw std::invalid_argument("<arg>: <what>"); the
// caller prints it and exits 2 with nothing on stdout.
#pragma once

#include "coefficients.hpp"
#include "device_model.hpp"
#include "evaluators.hpp"
#include "number_text.hpp"
#include "rom_image.hpp"
#include "span_shade.hpp"

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace specular::shade_cli {

inline constexpr const char* kEvaluators =
    "device_simd, pow_cos, phong_scalar, phong_sleef, pow, exp2poly, lut256, schlick, schlick_mod, lyon16, "
    "prototype, patent, patent_minimax, device, device_minimax";

struct Args {
  std::string evaluator, n, psi0, dpsi, len, c = "1", simd = "auto";
};

inline void add_options(CLI::App* sub, Args& a) {
  sub->add_option("--evaluator", a.evaluator, std::string("evaluator: ") + kEvaluators)->required();
  sub->add_option("--n", a.n, "specular exponent n, [1, " + std::to_string(kMaxN) + "] (integer for device, device_minimax)")
      ->required();
  sub->add_option("--psi0", a.psi0, "angle at pixel 0, radians, [-6.3, 6.3]")->required();
  sub->add_option("--dpsi", a.dpsi, "angle increment per pixel, radians, [-1, 1]")->required();
  sub->add_option("--len", a.len, "l: pixels 0..l, 0.." + std::to_string(kMaxLen))->required();
  sub->add_option("--c", a.c, "intensity C, [0, 1e6] (device, device_minimax: [0, 2)); default 1");
  sub->add_option("--simd", a.simd, "device_simd, phong_sleef: auto (default), scalar or avx2 (forced)");
}

[[noreturn]] inline void bad(const std::string& arg, const std::string& what) {
  throw std::invalid_argument(arg + ": " + what);
}

inline double real(const std::string& arg, const std::string& s, double lo, double hi, const std::string& range) {
  const std::optional<double> v = whole_double(s);
  if (!v || !std::isfinite(*v)) bad(arg, "'" + s + "' is not a number; allowed " + range);
  if (*v < lo || *v > hi) bad(arg, "'" + s + "' is outside the allowed range " + range);
  return *v;
}

// The CSV text of the span; throws std::invalid_argument on a bad argument.
inline std::string run(const Args& a) {
  const std::string e = a.evaluator;
  const std::vector<std::string> names{"device_simd", "pow_cos", "phong_scalar", "phong_sleef", "pow", "exp2poly",
                                       "lut256", "schlick", "schlick_mod", "lyon16", "prototype", "patent",
                                       "patent_minimax", "device", "device_minimax"};
  bool known = false;
  for (const auto& nm : names) known = known || nm == e;
  if (!known) bad("--evaluator", "'" + e + "' is not allowed; allowed " + kEvaluators);
  const bool golden = e == "device" || e == "device_minimax";
  const std::string max_n = std::to_string(kMaxN), max_len = std::to_string(kMaxLen);
  const double n = real("--n", a.n, 1.0, kMaxN, "[1, " + max_n + "]");
  if (golden && n != std::floor(n)) bad("--n", "'" + a.n + "' is not an integer; device evaluators allow 1.." + max_n);
  const double psi0 = real("--psi0", a.psi0, -6.3, 6.3, "[-6.3, 6.3]");
  const double dpsi = real("--dpsi", a.dpsi, -1.0, 1.0, "[-1, 1]");
  const double lenv = real("--len", a.len, 0.0, kMaxLen, "0.." + max_len);
  if (lenv != std::floor(lenv)) bad("--len", "'" + a.len + "' is not an integer; allowed 0.." + max_len);
  const int len = static_cast<int>(lenv);
  const double C = golden ? real("--c", a.c, 0.0, 1.99996948242187, "[0, 2) for device evaluators")
                          : real("--c", a.c, 0.0, 1e6, "[0, 1e6]");
  SimdPath path = SimdPath::automatic;
  if (a.simd == "scalar") path = SimdPath::scalar;
  else if (a.simd == "avx2") path = SimdPath::avx2;
  else if (a.simd != "auto") bad("--simd", "'" + a.simd + "' is not allowed; allowed auto, scalar, avx2");
  if (a.simd != "auto" && e != "device_simd" && e != "phong_sleef")
    bad("--simd", "applies to --evaluator device_simd or phong_sleef only");
  if (path == SimdPath::avx2 && !cpu_has_avx2()) bad("--simd", "avx2 forced but this CPU lacks AVX2/FMA; allowed auto, scalar");

  std::string out = "i,psi,value\n";
  auto row = [&](int i, double psi, const std::string& v) {
    out += std::to_string(i) + "," + shortest_text(psi) + "," + v + "\n";
  };
  const int count = len + 1;
  if (e == "device_simd") {
    std::vector<float> v(count);
    const double nn = n;
    const DeviceSpanPlan plan = nn == std::floor(nn) ? device_span_plan(static_cast<int>(nn)) : make_device_span_plan(nn);
    device_span(plan, psi0, dpsi, len, static_cast<float>(C), v.data(), path);
    for (int i = 0; i < count; ++i) row(i, psi0 + i * dpsi, shortest_text(v[i]));
  } else if (e == "pow_cos") {
    std::vector<double> v(count);
    pow_cos_span(n, psi0, dpsi, len, C, v.data());
    for (int i = 0; i < count; ++i) row(i, psi0 + i * dpsi, shortest_text(v[i]));
  } else if (e == "phong_scalar" || e == "phong_sleef") {
    if (std::abs(len * dpsi) > 3.0)
      bad("--dpsi", "phong evaluators lerp the normal between the span ends; |len * dpsi| must be <= 3 (got " +
                        shortest_text(len * dpsi) + ")");
    const double p1 = psi0 + len * dpsi;
    const Vec3f n0{float(std::sin(psi0)), 0.0f, float(std::cos(psi0))}, n1{float(std::sin(p1)), 0.0f, float(std::cos(p1))};
    const Vec3f h{0.0f, 0.0f, 1.0f};
    std::vector<float> v(count);
    phong_span(n0, n1, h, static_cast<float>(n), len, static_cast<float>(C), v.data(),
               e == "phong_scalar" ? SimdPath::scalar : path);
    for (int i = 0; i < count; ++i) {
      const double t = len > 0 ? static_cast<double>(i) / len : 0.0;
      const double x = n0[0] + t * (double(n1[0]) - n0[0]), z = n0[2] + t * (double(n1[2]) - n0[2]);
      row(i, std::atan2(x, z), shortest_text(v[i]));
    }
  } else if (golden) {
    const device::Format f;
    const CoefSpec spec{e == "device" ? CoefPolicy::maclaurin : CoefPolicy::minimax};
    const device::DeviceModel dm(f, coef_rom_image(f, spec), cos_rom_image(f));
    device::Registers r;
    r.c = device::quantize_c(C, f);
    r.psi0 = device::quantize_angle(psi0, f);
    r.dpsi = device::quantize_angle(dpsi, f);
    r.n = static_cast<uint32_t>(n);
    r.len = static_cast<uint32_t>(len);
    const std::vector<uint32_t> codes = dm.line(r);
    const double q0 = device::angle_value(r.psi0, f), dq = device::angle_value(r.dpsi, f);
    for (int i = 0; i < count; ++i) row(i, q0 + i * dq, shortest_text(device::c_value(codes[i], f)));
  } else {
    std::function<double(double)> cosine, angle;
    if (e == "pow") cosine = PowEval{n};
    if (e == "exp2poly") cosine = Exp2PolyEval{n};
    if (e == "lut256") cosine = LutEval(n);
    if (e == "schlick") cosine = SchlickEval{n};
    if (e == "schlick_mod") cosine = SchlickModEval{n};
    if (e == "lyon16") cosine = LyonEval(n, 4);
    if (e == "prototype") angle = prototype_eval(n);
    if (e == "patent" || e == "patent_minimax") {
      const int k = decoder_k_real(n);
      angle = CoskEval(k, coefficient(n, k, CoefSpec{e == "patent" ? CoefPolicy::maclaurin : CoefPolicy::minimax}));
    }
    for (int i = 0; i < count; ++i) {
      const double psi = psi0 + i * dpsi;
      row(i, psi, shortest_text(C * (cosine ? cosine(std::cos(psi)) : angle(psi))));
    }
  }
  return out;
}

}  // namespace specular::shade_cli
