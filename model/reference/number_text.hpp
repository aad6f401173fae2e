// SPDX-License-Identifier: Apache-2.0
// Numbers as text, both ways, for every tool and file format of the model: the shortest
// decimal text that parses back to the same value (docs/README.md#conventions-used-throughout),
// and the whole of a string as a double.
#pragma once

#include <charconv>
#include <cmath>
#include <exception>
#include <optional>
#include <string>

namespace specular {

// The shortest decimal text that parses back (strtod, std::stod, Python float) to exactly
// v, for float or double (std::to_chars); "nan", "inf", "-inf" for the non-finite values.
template <class T>
std::string shortest_text(T v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// The whole of s as a double (std::stod syntax), or nothing: empty, trailing characters,
// out of range. Infinities and NaN spelled out ("inf", "nan") are returned as such.
inline std::optional<double> whole_double(const std::string& s) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(s, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (used != s.size()) return std::nullopt;
  return v;
}

}  // namespace specular
