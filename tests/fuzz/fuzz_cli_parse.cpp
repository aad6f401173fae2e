// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the tools' argument parsers (model/cli_parse.hpp: parse_real,
// parse_int, parse_list, parse_vec) and the round-trip number format cli::num.
// The first byte picks the parser and its range; the rest is the argument text.
// Contract: a value inside the asked range, or cli::UsageError; and num(v) parses back to v.
#include "cli_parse.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {
void require(bool ok) {
  if (!ok) std::abort();
}
void round_trips(double v) {
  const std::string t = specular::cli::num(v);
  const double back = std::strtod(t.c_str(), nullptr);
  require(std::memcmp(&back, &v, sizeof v) == 0 || (v == 0 && back == 0));
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace specular::cli;
  if (size < 1) return 0;
  const int sel = data[0];
  const std::string s(reinterpret_cast<const char*>(data + 1), size - 1);
  // The ranges the tools use: n in 1..1000, k in 1..64, l in 0..2047.
  const int lo = (sel & 0x10) ? 0 : 1;
  const int hi = (sel & 0x20) ? 2047 : ((sel & 0x40) ? 64 : 1000);
  try {
    switch (sel % 4) {
      case 0: {
        const double v = parse_real("--x", s, lo, hi, "range");
        require(std::isfinite(v) && v >= lo && v <= hi);
        round_trips(v);
        break;
      }
      case 1: {
        const int v = parse_int("--x", s, lo, hi);
        require(v >= lo && v <= hi);
        break;
      }
      case 2: {
        const auto vs = parse_list("--x", s, lo, hi, (sel & 0x80) != 0);
        require(!vs.empty());
        for (double v : vs) {
          require(std::isfinite(v) && v >= lo && v <= hi);
          round_trips(v);
        }
        break;
      }
      default: {
        const glm::dvec3 v = parse_vec("--x", s);
        for (int i = 0; i < 3; ++i) {
          require(std::isfinite(v[i]));
          round_trips(v[i]);
        }
      }
    }
  } catch (const UsageError&) {
  }
  // Any 8 bytes as a double (NaN payloads and infinities print as nan/inf).
  if (size >= 9) {
    double d;
    std::memcpy(&d, data + 1, sizeof d);
    if (std::isfinite(d)) round_trips(d);
  }
  return 0;
}
