// SPDX-License-Identifier: Apache-2.0
// Bit-accurate golden model of the device datapath; the contract is the header comment
// of device_model.hpp. Integer arithmetic only between the registers and the output.
#include "device_model.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace specular::device {
namespace {

int64_t sign_extend(int64_t v, int bits) {
  const uint64_t mask = (bits >= 64) ? ~0ULL : ((1ULL << bits) - 1);
  uint64_t u = static_cast<uint64_t>(v) & mask;
  if (bits < 64 && (u >> (bits - 1)) & 1U) u |= ~mask;
  return static_cast<int64_t>(u);
}

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("device::Format/ROM: " + what);
}

// 2^e for -1022 <= e <= 1023, exactly, without a library call (x * 2^e is then what
// std::ldexp(x, e) gives: one correctly rounded multiplication).
double pow2(int e) { return std::bit_cast<double>(static_cast<uint64_t>(1023 + e) << 52); }

// std::round(x) (half away from zero) inline: below 2^51 by the 1.5 * 2^52 addition, which
// rounds to nearest exactly; a - r is exact, and a tie taken to even is moved away from zero.
// From 2^51 on a double is a multiple of 1/2 or an integer: std::round itself.
double round_half_away(double x) {
  constexpr double kMagic = 6755399441055744.0;  // 1.5 * 2^52
  const double a = std::fabs(x);
  if (!(a < 0x1p51)) return std::round(x);
  const double r = (a + kMagic) - kMagic;
  return std::copysign(a - r >= 0.5 ? r + 1.0 : r, x);
}

// x * 2^frac rounded to nearest (ties away from zero) and clamped to [lo, hi]; NaN gives 0.
// *saturated (when given) says whether it was clamped or NaN.
double quantize(double x, int frac, double lo, double hi, bool* saturated) {
  bool sat = false;
  double q = 0.0;
  if (std::isnan(x)) {
    sat = true;
  } else {
    q = round_half_away(x * pow2(frac));
    if (q < lo) { q = lo; sat = true; }
    if (q > hi) { q = hi; sat = true; }
  }
  if (saturated) *saturated = sat;
  return q;
}

}  // namespace

int64_t quantize_fixed(double x, int frac, int64_t lo, int64_t hi, bool* saturated) {
  return static_cast<int64_t>(quantize(x, frac, static_cast<double>(lo), static_cast<double>(hi), saturated));
}

uint32_t quantize_n(double n, const Format& f) {
  const double n_max = pow2(f.n_bits) - 1.0;
  return std::isfinite(n) ? static_cast<uint32_t>(std::clamp(round_half_away(n), 0.0, n_max)) : 0U;
}

uint32_t quantize_len(int l, const Format& f) { return static_cast<uint32_t>(std::clamp(l, 0, f.max_len())); }

uint32_t quantize_c(double c, const Format& f, bool* saturated) {
  return static_cast<uint32_t>(quantize(c, f.c_frac, 0.0, pow2(f.c_bits) - 1.0, saturated));
}

int64_t quantize_angle(double rad, const Format& f, bool* saturated) {
  const double half = pow2(f.angle_bits - 1);
  return static_cast<int64_t>(quantize(rad, f.angle_frac, -half, half - 1.0, saturated));
}

double c_value(uint32_t code, const Format& f) { return std::ldexp(static_cast<double>(code), -f.c_frac); }
double angle_value(int64_t code, const Format& f) { return std::ldexp(static_cast<double>(code), -f.angle_frac); }
RegisterLoad load_registers(const ScanlineSetup& s, double n, int l, const Format& f) {
  RegisterLoad out;
  bool psi0_sat = false, dpsi_sat = false;
  out.reg.c = quantize_c(s.C, f, &out.c_saturated);
  out.reg.psi0 = quantize_angle(s.psi0, f, &psi0_sat);
  out.reg.dpsi = quantize_angle(s.dpsi, f, &dpsi_sat);
  out.angle_saturated = psi0_sat || dpsi_sat;
  out.reg.n = quantize_n(n, f);
  out.reg.len = quantize_len(l, f);
  return out;
}

Format Format::patent() {
  Format f;
  f.coef_bits = 18;
  f.coef_frac = 15;
  f.cos_interp = false;
  f.cos_addr_bits = 12;
  f.cos_data_bits = 16;
  f.banks.assign(kPatentBanks.begin(), kPatentBanks.end());
  f.bank_max_n.assign(kPatentBankMaxN.begin(), kPatentBankMaxN.end());
  return f;
}

int64_t Format::half_pi_code() const {
  return static_cast<int64_t>(std::ceil(std::ldexp(std::numbers::pi_v<long double> / 2.0L, angle_frac)));
}

double coef_value(uint32_t code, const Format& f) {
  return std::ldexp(static_cast<double>(code), -f.coef_frac) * (std::numbers::pi / 2.0);
}

DeviceModel::DeviceModel(Format f, std::vector<uint32_t> coef_rom, std::vector<uint32_t> cos_rom)
    : f_(std::move(f)), coef_rom_(std::move(coef_rom)), cos_rom_(std::move(cos_rom)) {
  require(!f_.blend, "blend mode needs ROM 9's a2 and weight fields (the BlendRoms constructor)");
  check();
}

DeviceModel::DeviceModel(Format f, std::vector<uint32_t> coef_rom, std::vector<uint32_t> cos_rom, BlendRoms blend)
    : f_(std::move(f)), coef_rom_(std::move(coef_rom)), cos_rom_(std::move(cos_rom)), blend_(std::move(blend)) {
  require(f_.blend, "BlendRoms given to a format without blend");
  check();
  require(f_.weight_bits >= 1 && f_.weight_bits <= 24, "weight_bits (1..24)");
  require(static_cast<int>(blend_.coef2.size()) == f_.coef_rom_depth() &&
              static_cast<int>(blend_.weight.size()) == f_.coef_rom_depth(),
          "blend ROM 9 fields a2 and w need " + std::to_string(f_.coef_rom_depth()) + " words each");
  for (uint32_t w : blend_.coef2) require((static_cast<uint64_t>(w) >> f_.coef_bits) == 0, "a2 word too wide");
  for (uint32_t w : blend_.weight) require((static_cast<uint64_t>(w) >> f_.weight_bits) == 0, "weight word too wide");
}

void DeviceModel::check() const {
  // Widths for which the 64-bit products below cannot overflow.
  require(f_.c_bits >= 1 && f_.c_bits <= 31 && f_.c_frac >= 0 && f_.c_frac <= f_.c_bits, "c_bits/c_frac");
  require(f_.angle_bits >= 4 && f_.angle_bits <= 48 && f_.angle_frac >= 3 && f_.angle_frac <= f_.angle_bits - 1,
          "angle_bits/angle_frac");
  require(f_.acc_bits >= f_.angle_bits && f_.acc_bits <= 62, "acc_bits");
  require(f_.n_bits >= 1 && f_.n_bits <= 16 && (1 << f_.n_bits) > f_.max_n(), "n_bits must hold max_n");
  require(f_.len_bits >= 1 && f_.len_bits <= 24, "len_bits");
  require(f_.coef_bits >= 4 && f_.coef_bits <= 31 && f_.coef_frac >= 3 && f_.coef_frac <= f_.coef_bits,
          "coef_bits/coef_frac");
  require(f_.psi_mul_frac >= 0 && f_.psi_mul_frac <= f_.angle_frac && f_.coef_bits + 1 + f_.psi_mul_frac <= 63,
          "psi_mul_frac (at most angle_frac; the product must fit 63 bits)");
  require(f_.acc_bits >= f_.angle_frac + 2, "acc_bits must hold the sign and an integer bit");
  require(f_.cos_addr_bits >= 1 && f_.cos_addr_bits < f_.coef_frac + f_.psi_mul_frac, "cos_addr_bits");
  require(f_.cos_data_bits >= 1 && f_.cos_data_bits <= 30 && f_.c_bits + f_.cos_data_bits + 1 <= 63,
          "cos_data_bits");
  if (f_.cos_interp) {
    require(f_.cos_frac_bits >= 1 && f_.cos_addr_bits + f_.cos_frac_bits <= f_.coef_frac + f_.psi_mul_frac,
            "cos_frac_bits (address and step weight must fit in the fraction of zeta)");
    require(f_.cos_delta_bits >= 1 && f_.cos_word_bits() <= 32, "cos_delta_bits (ROM 12 word at most 32 bits)");
  }
  require(!f_.banks.empty() && (f_.banks.size() == f_.bank_max_n.size() ||
                                 (f_.blend && f_.bank_max_n.size() + 1 == f_.banks.size())),
          "banks/bank_max_n sizes");
  for (size_t j = 0; j < f_.banks.size(); ++j) require(f_.banks[j] >= 1, "bank k must be >= 1");
  for (size_t j = 0; j < f_.bank_max_n.size(); ++j)
    require(f_.bank_max_n[j] >= 1 && (j == 0 || f_.bank_max_n[j] > f_.bank_max_n[j - 1]),
            "bank_max_n must increase");
  require(f_.bank_shift.empty() || f_.bank_shift.size() == f_.banks.size(), "bank_shift: one per bank, or none");
  for (int s : f_.bank_shift) require(s >= 0 && s <= 8, "bank_shift (0..8)");
  require(f_.bank_max_n.back() == f_.max_n(), "last bank must end at max_n");
  require(static_cast<int>(coef_rom_.size()) == f_.coef_rom_depth(),
          "coefficient ROM has " + std::to_string(coef_rom_.size()) + " words, expected " +
              std::to_string(f_.coef_rom_depth()));
  require(static_cast<int>(cos_rom_.size()) == f_.cos_rom_depth(),
          "cos^k ROM has " + std::to_string(cos_rom_.size()) + " words, expected " +
              std::to_string(f_.cos_rom_depth()));
  for (uint32_t w : coef_rom_) require((static_cast<uint64_t>(w) >> f_.coef_bits) == 0, "coefficient word too wide");
  for (uint32_t w : cos_rom_) require((static_cast<uint64_t>(w) >> f_.cos_word_bits()) == 0, "cos^k word too wide");
  if (f_.cos_interp)
    for (uint32_t w : cos_rom_)
      require((w >> f_.cos_delta_bits) <= (1U << f_.cos_data_bits) &&
                  (w & ((1U << f_.cos_delta_bits) - 1)) <= (w >> f_.cos_delta_bits),
              "cos^k word: value above 1 or step below 0");
}

int DeviceModel::bank_of(uint32_t n) const {
  // The constructor required bank_max_n.back() == max_n(): n above max_n() gets -1.
  return decoder_bank(f_.bank_max_n, n);
}

Registers DeviceModel::latch(const Registers& r) const {
  Registers q;
  q.c = r.c & static_cast<uint32_t>((1ULL << f_.c_bits) - 1);
  q.dpsi = sign_extend(r.dpsi, f_.angle_bits);
  q.psi0 = sign_extend(r.psi0, f_.angle_bits);
  q.n = r.n & static_cast<uint32_t>((1ULL << f_.n_bits) - 1);
  q.len = r.len & static_cast<uint32_t>(f_.max_len());
  return q;
}

PixelTrace DeviceModel::trace(const Registers& raw, int i) const {
  const Registers r = latch(raw);
  PixelTrace t;
  // Reg 8 after i additions of reg 2 (adder 6), wrapping at acc_bits like the hardware.
  t.psi = sign_extend(r.psi0 + static_cast<int64_t>(i) * r.dpsi, f_.acc_bits);
  const uint64_t acc_mask = (1ULL << f_.acc_bits) - 1;
  const bool neg = t.psi < 0;
  // One's complement: no carry chain in hardware; for negative psi it is |psi| - 1 code.
  t.abs_psi = neg ? (~static_cast<uint64_t>(t.psi)) & acc_mask : static_cast<uint64_t>(t.psi);
  const uint64_t half_pi = static_cast<uint64_t>(f_.half_pi_code());
  t.far = neg ? t.abs_psi + 1 >= half_pi : t.abs_psi >= half_pi;  // exactly |psi| >= pi/2
  t.bank = bank_of(r.n);
  if (t.far || t.bank < 0) return t;
  t.abs_psi_t = t.abs_psi >> (f_.angle_frac - f_.psi_mul_frac);  // < 2: 1 integer bit
  t.coef = coef_rom_[r.n];
  uint32_t cosk = 0;
  {
    const Read a = read_cos(t.bank, t.coef, t.abs_psi_t);
    t.zeta = a.zeta, t.addr = a.addr, t.frac = a.frac, t.overflow = a.overflow, t.word = a.word, t.cosk = a.cosk;
    cosk = a.cosk;
  }
  if (f_.blend) {
    t.bank2 = second_bank(t.bank);
    t.coef2 = blend_.coef2[r.n];
    const Read b = read_cos(t.bank2, t.coef2, t.abs_psi_t);
    t.zeta2 = b.zeta, t.addr2 = b.addr, t.frac2 = b.frac, t.overflow2 = b.overflow, t.word2 = b.word;
    t.cosk2 = b.cosk;
    t.weight = blend_.weight[r.n];
    // cosb = c1 + round((c2 - c1) w / 2^W), half up (>> on a signed value is floor in C++20): it
    // lies between c1 and c2, so it needs no wider word.
    const int64_t diff = static_cast<int64_t>(t.cosk2) - static_cast<int64_t>(t.cosk);
    const int64_t step = (diff * t.weight + (int64_t{1} << (f_.weight_bits - 1))) >> f_.weight_bits;
    t.blended = static_cast<uint32_t>(static_cast<int64_t>(t.cosk) + step);
    cosk = t.blended;
  } else if (t.overflow) {
    return t;
  }
  t.intensity = mul13(r.c, cosk);
  return t;
}

uint32_t DeviceModel::mul13(uint32_t c, uint32_t cosk) const {
  const uint64_t p = static_cast<uint64_t>(c) * cosk;
  return static_cast<uint32_t>((p + (1ULL << (f_.cos_data_bits - 1))) >> f_.cos_data_bits);
}

RgbC DeviceModel::rgb_pixel(const Registers& r, const RgbC& c, int i) const {
  const PixelTrace t = trace(r, i);
  RgbC out{};
  // The zero flags of trace(): past pi/2, an invalid n, or (one read) past ROM 12's domain.
  if (t.far || t.bank < 0 || (!f_.blend && t.overflow)) return out;
  const uint32_t cosk = f_.blend ? t.blended : t.cosk;
  const uint32_t c_mask = static_cast<uint32_t>((1ULL << f_.c_bits) - 1);
  for (size_t ch = 0; ch < out.size(); ++ch) out[ch] = mul13(c[ch] & c_mask, cosk);
  return out;
}

DeviceModel::Read DeviceModel::read_cos(int bank, uint32_t coef, uint64_t abs_psi_t) const {
  Read t;
  t.zeta = static_cast<uint64_t>(coef) * abs_psi_t;  // multiplier 11
  const int zf = f_.coef_frac + f_.psi_mul_frac;
  if (f_.cos_interp) {
    t.overflow = (t.zeta >> zf) != 0;
    if (t.overflow) return t;
    const int sa = zf - f_.cos_addr_bits;
    t.addr = (t.zeta >> sa) & ((1ULL << f_.cos_addr_bits) - 1);
    t.frac = static_cast<uint32_t>((t.zeta >> (sa - f_.cos_frac_bits)) & ((1ULL << f_.cos_frac_bits) - 1));
    t.word = cos_rom_[(static_cast<size_t>(bank) << f_.cos_addr_bits) + t.addr];
    const uint64_t v = t.word >> f_.cos_delta_bits;
    const uint64_t d = t.word & ((1ULL << f_.cos_delta_bits) - 1);
    t.cosk = static_cast<uint32_t>(v - ((d * t.frac + (1ULL << (f_.cos_frac_bits - 1))) >> f_.cos_frac_bits));
  } else {
    const int drop = zf - f_.cos_addr_bits;
    t.addr = (t.zeta + (1ULL << (drop - 1))) >> drop;  // round half up
    t.overflow = (t.addr >> f_.cos_addr_bits) != 0;
    if (t.overflow) return t;
    t.word = cos_rom_[(static_cast<size_t>(bank) << f_.cos_addr_bits) + t.addr];
    t.cosk = t.word;
  }
  return t;
}

std::vector<uint32_t> DeviceModel::line(const Registers& raw) const {
  const Registers r = latch(raw);
  std::vector<uint32_t> out(static_cast<size_t>(r.len) + 1);
  for (uint32_t i = 0; i <= r.len; ++i) out[i] = trace(r, static_cast<int>(i)).intensity;
  return out;
}

void DeviceModel::stream_span(const Span& s, std::vector<StreamPixel>& out) const {
  const Registers r = latch(s.reg);
  for (uint32_t i = 0; i <= r.len; ++i)
    out.push_back({trace(r, static_cast<int>(i)).intensity, i == r.len, s.tag});
}

std::vector<StreamPixel> DeviceModel::stream(const std::vector<Span>& spans) const {
  std::vector<StreamPixel> out;
  for (const Span& s : spans) stream_span(s, out);
  return out;
}

}  // namespace specular::device
