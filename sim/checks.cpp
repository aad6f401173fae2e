// SPDX-License-Identifier: Apache-2.0
#include "checks.hpp"

#include "metrics.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace specular::sim {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2.0;

void note(PolicyStats& st, const std::string& what) {
  if (st.failures.size() < 12) st.failures.push_back(what);
}

void keep_max(Extreme& e, double v, const device::Registers& r, const std::string& kind, int i, double psi, double c) {
  if (v > e.value) e = {v, r.n, psi, c, r.len, i, kind};
}

nlohmann::json ext_json(const Extreme& e) {
  return {{"value", e.value}, {"n", e.n}, {"psi", e.psi}, {"C", e.c}, {"l", e.len}, {"pixel", e.pixel},
          {"kind", e.kind}};
}

// x^n by squaring: n is an integer (n <= 1000, k <= 16), so a few multiplications replace
// std::pow; the result differs from pow's by a few ulp at most, far below one output LSB.
double ipow(double x, uint32_t n) {
  double r = 1.0;
  for (; n; n >>= 1, x *= x)
    if (n & 1) r *= x;
  return r;
}

// A code as a port of `bits` bits carries it: the low `bits` bits, read unsigned or as
// two's complement (docs/interfaces.md#register-interface-specular_unit: widths and formats).
uint64_t port_unsigned(uint64_t v, int bits) { return v % (uint64_t{1} << bits); }
int64_t port_signed(int64_t v, int bits) {
  const int64_t low = static_cast<int64_t>(port_unsigned(static_cast<uint64_t>(v), bits));
  return low >= (int64_t{1} << (bits - 1)) ? low - (int64_t{1} << bits) : low;
}

// The registers the device holds after the host wrote `w`: each field as its port carries
// it. Written here from the port formats rather than taken from DeviceModel::latch, so the
// references below share no code with the golden model but the format constants.
device::Registers as_loaded(const device::Registers& w, const device::Format& f) {
  device::Registers r;
  r.c = static_cast<uint32_t>(port_unsigned(w.c, f.c_bits));
  r.dpsi = port_signed(w.dpsi, f.angle_bits);
  r.psi0 = port_signed(w.psi0, f.angle_bits);
  r.n = static_cast<uint32_t>(port_unsigned(w.n, f.n_bits));
  r.len = static_cast<uint32_t>(port_unsigned(w.len, f.len_bits));
  return r;
}

}  // namespace

nlohmann::json PolicyStats::to_json() const {
  nlohmann::json lat = nlohmann::json::object();
  for (const auto& [l, cnt] : latency) lat[std::to_string(l)] = cnt;
  return {{"policy", policy},
          {"ok", ok()},
          {"budget", {{"rel_epicenter", budget.rel_epicenter}, {"abs_lobe", budget.abs_lobe}}},
          {"lines", lines},
          {"pixels", pixels},
          {"deterministic_lines", det_lines},
          {"deterministic_pixels", det_pixels},
          {"random_lines", rnd_lines},
          {"random_pixels", rnd_pixels},
          {"mismatches", mismatches},
          {"protocol_errors", protocol_errors},
          {"quant_violations", quant_violations},
          {"rel_violations", rel_violations},
          {"abs_violations", abs_violations},
          {"epicenter_pixels", epicenter_pixels},
          {"lobe_pixels", lobe_pixels},
          {"c_saturated_lines", c_saturated_lines},
          {"quant_max_lsb", ext_json(quant_lsb)},
          {"quant_max_over_bound", ext_json(quant_excess)},
          {"rel_epicenter_raw", ext_json(rel_raw)},
          {"rel_epicenter_raw_ref_ge_half", ext_json(rel_raw_big)},
          {"rel_epicenter_with_lsb", ext_json(rel_allow)},
          {"rel_epicenter_n1_with_lsb", ext_json(rel_allow_n1)},
          {"n1_pixels_over_rel_budget", n1_rel_over_budget},
          {"n1_rel_budget_holds_for_abs_psi_below", n1_budget_holds_below},
          {"abs_lobe_raw", ext_json(abs_raw)},
          {"abs_lobe_with_lsb", ext_json(abs_allow)},
          {"abs_outside_lobe_with_lsb", ext_json(abs_outside)},
          {"latency", lat},
          {"expected_latency", expected_latency},
          {"cycles", cycles},
          {"cycles_per_pixel", pixels ? static_cast<double>(cycles) / pixels : 0.0},
          {"cycles_per_pixel_long_lines",
           long_line_pixels ? static_cast<double>(long_line_cycles) / long_line_pixels : 0.0},
          {"seconds", seconds},
          {"sim_seconds", sim_seconds},
          {"rtl_seconds", sim_seconds},
          {"golden_seconds", golden_seconds},
          {"reference_seconds", reference_seconds},
          {"simulated_pixels_per_second", sim_seconds > 0 ? pixels / sim_seconds : 0.0},
          {"checked_pixels_per_second", seconds > 0 ? pixels / seconds : 0.0},
          {"failures", failures}};
}

Checker::Checker(const device::DeviceModel& model, const CoefSpec& spec, Budget budget)
    : model_(model), budget_(budget) {
  // max over x of |k cos^(k-1) x sin x|: at sin^2 x = 1/k (k > 1), 1 for k = 1.
  // max over x of |(cos^k)''| = |k cos^(k-2) ((k-1) sin^2 - cos^2)|: a dense scan on [0, pi/2]
  // (the curvature bound of the interpolated ROM 12; closed forms per k are not needed).
  for (int k : model_.format().banks) {
    if (k == 1) {
      dk_.push_back(1.0);
    } else {
      const double s2 = 1.0 / k;
      dk_.push_back(k * std::pow(1.0 - s2, (k - 1) / 2.0) * std::sqrt(s2));
    }
    double m2 = 0.0;
    for (int i = 0; i <= 20000; ++i) {
      const double x = kHalfPi * i / 20000.0, c = std::cos(x), sn = std::sin(x);
      const double d2 = k * (k >= 2 ? std::pow(c, k - 2) : 1.0 / std::max(c, 1e-300)) * ((k - 1) * sn * sn - c * c);
      m2 = std::max(m2, std::fabs(k >= 2 ? d2 : c));  // k = 1: |cos''| = cos
    }
    d2k_.push_back(m2);
  }
  // The format's constants of references() and compare(), once (ldexp per span is not free).
  // (b) first-order budget of the formats: the ROM 12 position error (direct: half an
  // address step; interpolated: the truncation of the step weight), the rounding of a(n)
  // to coef_frac bits times |psi|, the truncation of |psi| to psi_mul_frac bits times a
  // (and the one-code one's complement), all through the steepest slope of cos^k; the
  // interpolation error h^2/8 max|(cos^k)''| (interpolated only); one ROM 12 LSB (direct:
  // the saturation of cos^0; interpolated: the rounding of v and of d t); half an output LSB.
  const auto& f = model_.format();
  const double h = kHalfPi * std::ldexp(1.0, -f.cos_addr_bits);
  k_.lsb = std::ldexp(1.0, -f.c_frac);
  k_.half_step = f.cos_interp ? h * std::ldexp(1.0, -f.cos_frac_bits) : h / 2;
  k_.interp = f.cos_interp ? h * h / 8.0 : 0.0;
  k_.coef_err = kHalfPi * std::ldexp(1.0, -(f.coef_frac + 1));
  k_.trunc = std::ldexp(1.0, -f.psi_mul_frac) + std::ldexp(1.0, -f.angle_frac);
  k_.rom_lsb = std::ldexp(1.0, -f.cos_data_bits);
  // Decoder 10 from the format's table, not from the golden model (DeviceModel::bank_of):
  // n = 0 and n > 1000 select no bank, bank j serves bank_max_n[j-1] < n <= bank_max_n[j]
  // (docs/device.md#the-blocks, block 10, and docs/device.md#fixed-point-contract, step 6).
  for (uint32_t n = 0; n < static_cast<uint32_t>(f.coef_rom_depth()); ++n) {
    int bank = -1;
    if (n >= 1 && n <= static_cast<uint32_t>(f.max_n()))
      for (size_t j = f.bank_max_n.size(); j-- > 0;)
        if (n <= static_cast<uint32_t>(f.bank_max_n[j])) bank = static_cast<int>(j);
    bank_.push_back(bank);
    xe_.push_back(bank >= 0 ? epicenter_end(static_cast<double>(n)) : 0.0);
    if (!f.blend) {
      a_.push_back(bank >= 0 ? coefficient(static_cast<int>(n), f.banks[bank], spec) : 0.0);
      continue;
    }
    // The blend: the values the ROM 9 fields stand for (device_model.hpp), the shifts undone.
    const int bank2 = bank >= 0 ? model_.second_bank(bank) : -1;
    const double s1 = bank >= 0 ? std::ldexp(1.0, -f.shift_of(bank)) : 0.0;
    const double s2 = bank2 >= 0 ? std::ldexp(1.0, -f.shift_of(bank2)) : 0.0;
    a_.push_back(bank >= 0 ? device::coef_value(model_.coef_rom()[n], f) * s1 : 0.0);
    bank2_.push_back(bank2);
    a2_.push_back(bank2 >= 0 ? device::coef_value(model_.blend_roms().coef2[n], f) * s2 : 0.0);
    t_.push_back(bank >= 0 ? std::ldexp(static_cast<double>(model_.blend_roms().weight[n]), -f.weight_bits) : 0.0);
    end1_.push_back(kHalfPi * s1);
    end2_.push_back(kHalfPi * s2);
  }
  // The reference angle psi_i = psi0 + i dpsi is the exact sum (references()): register 8
  // holds it without wrapping (docs/device.md#fixed-point-contract: psi0 then psi + dpsi,
  // exact integer arithmetic; register 8 cannot overflow over a line) and a double holds it
  // exactly. Both are properties of the format; refuse one that breaks them.
  const int sum_bits = f.angle_bits - 1 + f.len_bits;  // |psi0 + l dpsi| <= 2^(angle_bits-1) * 2^len_bits
  if (sum_bits > f.acc_bits - 1 || sum_bits > 53)
    throw std::invalid_argument("Checker: register 8 (acc_bits) or a double cannot hold psi0 + l dpsi exactly");
}

void Checker::check_line(const Scanline& sl, const LineRun& run, bool random, PolicyStats& st) const {
  const auto& f = model_.format();
  const device::Registers r = as_loaded(sl.reg, f);
  ++st.lines;
  (random ? st.rnd_lines : st.det_lines) += 1;
  if (sl.c_saturated) ++st.c_saturated_lines;
  if (!run.protocol_error.empty()) {
    ++st.protocol_errors;
    note(st, st.policy + " protocol [" + sl.kind + " n=" + std::to_string(r.n) + " l=" + std::to_string(r.len) +
                 "]: " + run.protocol_error);
  }
  if (run.latency >= 0) ++st.latency[run.latency];
  st.cycles += run.cycles;
  if (r.len == static_cast<uint32_t>(f.max_len())) {
    st.long_line_cycles += run.cycles;
    st.long_line_pixels += r.len + 1;
  }

  const size_t npix = std::min<size_t>(run.pixels.size(), static_cast<size_t>(r.len) + 1);
  (random ? st.rnd_pixels : st.det_pixels) += npix;

  // Pass 1, the golden model alone (timed separately from the references).
  using Clock = std::chrono::steady_clock;
  const auto t_gold = Clock::now();
  golden_.resize(npix);
  for (size_t i = 0; i < npix; ++i) golden_[i] = model_.trace(r, static_cast<int>(i)).intensity;
  const auto t_ref = Clock::now();
  st.golden_seconds += std::chrono::duration<double>(t_ref - t_gold).count();
  // Pass 2, the double references: (b) C cos^k(a psi) and (c) C cos^n(psi).
  psi_.resize(npix);
  ref_b_.resize(npix);
  ref_c_.resize(npix);
  references(r, npix, psi_.data(), ref_b_.data(), ref_c_.data());
  st.reference_seconds += std::chrono::duration<double>(Clock::now() - t_ref).count();
  // Pass 3, the comparisons.
  compare(r, sl.kind, npix, run.pixels.data(), golden_.data(), psi_.data(), ref_b_.data(), ref_c_.data(), st);
}

void Checker::references(const device::Registers& written, size_t npix, double* psi_out, double* ref_b,
                         double* ref_c) const {
  const auto& f = model_.format();
  const device::Registers r = as_loaded(written, f);
  const double c = r.c * k_.lsb;  // exact, as device::c_value
  const int bank = bank_[r.n];
  const bool n_ok = bank >= 0;
  const uint32_t k = n_ok ? static_cast<uint32_t>(f.banks[bank]) : 0;
  const double a = n_ok ? a_[r.n] : 0.0;
  for (size_t i = 0; i < npix; ++i) {
    // psi_i = psi0 + i dpsi from the loaded register codes alone, exact integer arithmetic
    // (no wrap: the constructor checked that register 8 and a double hold every such sum),
    // then radians by the register format (angle_value: code * 2^-angle_frac, exact). Not
    // the golden model's accumulator: a bug shared by it and the RTL moves the RTL's pixels
    // away from these references and fails (b) and (c).
    const int64_t code = r.psi0 + static_cast<int64_t>(i) * r.dpsi;
    const double psi = device::angle_value(code, f);
    const double apsi = std::fabs(psi);
    psi_out[i] = psi;
    if (f.blend) {
      // Each read is 0 past its bank's domain, as in the device.
      double b = 0.0;
      if (n_ok && apsi < kHalfPi) {
        const double t = t_[r.n], a2 = a2_[r.n];
        const uint32_t k2 = static_cast<uint32_t>(f.banks[bank2_[r.n]]);
        const double c1 = a * apsi < end1_[r.n] ? ipow(std::cos(a * apsi), k) : 0.0;
        const double c2 = a2 * apsi < end2_[r.n] ? ipow(std::cos(a2 * apsi), k2) : 0.0;
        b = c * ((1.0 - t) * c1 + t * c2);
      }
      ref_b[i] = b;
    } else {
      ref_b[i] = n_ok && a * apsi < kHalfPi && apsi < kHalfPi ? c * ipow(std::cos(a * apsi), k) : 0.0;
    }
    ref_c[i] = n_ok && apsi < kHalfPi ? c * ipow(std::cos(psi), r.n) : 0.0;
  }
}

void Checker::compare(const device::Registers& written, const std::string& kind, size_t npix,
                      const uint32_t* got_px, const uint32_t* golden, const double* psi_in, const double* ref_b_in,
                      const double* ref_c_in, PolicyStats& st) const {
  const device::Registers r = as_loaded(written, model_.format());
  const double lsb = k_.lsb;
  const double c = r.c * lsb;  // exact, as device::c_value
  const int bank = bank_[r.n];
  const bool n_ok = bank >= 0;
  const double a = n_ok ? a_[r.n] : 0.0;
  const double xe = xe_[r.n];
  const double half_step = k_.half_step, interp = k_.interp, coef_err = k_.coef_err, trunc = k_.trunc;
  const double n1_floor = budget_.n1_min_ref_lsb * lsb;  // n = 1 checked where ref >= this (0: not)
  st.pixels += npix;

  for (size_t i = 0; i < npix; ++i) {
    const uint32_t got = got_px[i];
    // (a)
    if (got != golden[i]) {
      if (st.mismatches < 12) {
        const device::PixelTrace t = model_.trace(r, static_cast<int>(i));
        std::ostringstream m;
        m << st.policy << " mismatch [" << kind << "] n=" << r.n << " l=" << r.len << " C=0x" << std::hex << r.c
          << " psi0=0x" << r.psi0 << " dpsi=0x" << r.dpsi << std::dec << " pixel " << i << ": rtl " << got
          << " golden " << t.intensity << " (psi=" << t.psi << " addr=" << t.addr << " bank=" << t.bank
          << " cosk=" << t.cosk << ")";
        note(st, m.str());
      }
      ++st.mismatches;
    }
    const double psi = psi_in[i];
    const double apsi = std::fabs(psi);
    const double out = got * lsb;
    const int px = static_cast<int>(i);
    // (b)
    const double ref_b = ref_b_in[i];
    const double err_b = std::fabs(out - ref_b);
    keep_max(st.quant_lsb, err_b / lsb, r, kind, px, psi, c);
    if (n_ok) {
      const double ex = half_step + coef_err * std::min(apsi, kHalfPi) + a * trunc;
      double bound = c * (dk_[bank] * ex + d2k_[bank] * interp + k_.rom_lsb) + 0.5 * lsb;
      if (model_.format().blend) {
        // Each read's bound in its own domain (the shift scales the address step, the
        // coefficient's rounding and the interpolation's curvature term), weighted as the
        // blend weights the reads, plus the blend's rounding (one ROM 12 LSB).
        auto read_bound = [&](int j, double aj) {
          const double sc = std::ldexp(1.0, -model_.format().shift_of(j));
          const double exj = sc * (half_step + coef_err * std::min(apsi, kHalfPi)) + aj * trunc;
          return dk_[j] * exj + d2k_[j] * interp * sc * sc + k_.rom_lsb;
        };
        const double t = t_[r.n];
        bound = c * ((1.0 - t) * read_bound(bank, a) + t * read_bound(bank2_[r.n], a2_[r.n]) + k_.rom_lsb) +
                0.5 * lsb;
      }
      keep_max(st.quant_excess, err_b / bound, r, kind, px, psi, c);
      if (err_b > bound) {
        if (st.quant_violations < 4)
          note(st, st.policy + " quantization error " + std::to_string(err_b / lsb) + " LSB > bound " +
                       std::to_string(bound / lsb) + " at n=" + std::to_string(r.n) + " psi=" + std::to_string(psi));
        ++st.quant_violations;
      }
    } else if (got != 0) {
      ++st.quant_violations;
      note(st, st.policy + " invalid n=" + std::to_string(r.n) + " gave a nonzero pixel");
    }
    // (c)
    const double ref_c = ref_c_in[i];
    const double err_c = std::fabs(out - ref_c);
    const double err_allow = std::max(0.0, err_c - lsb);
    if (n_ok && apsi <= xe && ref_c > 0.0) {
      ++st.epicenter_pixels;
      keep_max(st.rel_raw, err_c / ref_c, r, kind, px, psi, c);
      if (ref_c >= 0.5) keep_max(st.rel_raw_big, err_c / ref_c, r, kind, px, psi, c);
      const bool over = err_c > budget_.rel_epicenter * ref_c + lsb;
      if (r.n == 1) {
        if (ref_c >= n1_floor) keep_max(st.rel_allow_n1, err_allow / ref_c, r, kind, px, psi, c);
        if (over) {
          ++st.n1_rel_over_budget;
          st.n1_budget_holds_below = std::min(st.n1_budget_holds_below, apsi);
        }
      } else {
        keep_max(st.rel_allow, err_allow / ref_c, r, kind, px, psi, c);
      }
      const bool checked = r.n != 1 || (n1_floor > 0.0 && ref_c >= n1_floor);
      if (over && checked) {
        if (st.rel_violations < 4)
          note(st, st.policy + " epicenter error " + std::to_string(100 * err_c / ref_c) + "% at n=" +
                       std::to_string(r.n) + " psi=" + std::to_string(psi) + " C=" + std::to_string(c));
        ++st.rel_violations;
        ++st.rel_violations_by_n[r.n];
      }
    }
    if (c > 0.0) {
      if (apsi <= kHalfPi) {
        ++st.lobe_pixels;
        keep_max(st.abs_raw, err_c / c, r, kind, px, psi, c);
        keep_max(st.abs_allow, err_allow / c, r, kind, px, psi, c);
      } else {
        keep_max(st.abs_outside, err_allow / c, r, kind, px, psi, c);
      }
    }
    // The absolute budget also holds past the lobe (reference 0 there).
    if (err_c > budget_.abs_lobe * c + lsb) {
      if (st.abs_violations < 4)
        note(st, st.policy + " absolute error " + std::to_string(err_c / std::max(c, lsb)) + " C at n=" +
                     std::to_string(r.n) + " psi=" + std::to_string(psi) + " C=" + std::to_string(c));
      ++st.abs_violations;
    }
  }
}

}  // namespace specular::sim
