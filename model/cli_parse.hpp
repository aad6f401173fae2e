// SPDX-License-Identifier: Apache-2.0
// Command-line parsing shared by the tools (model/tools/*, sim_regression): help exits 0,
// a bad argument exits 2 with "<tool>: error: <what>" on stderr, the project's contract
// for bad input. Header-only so that the model library itself does not need CLI11.
#pragma once

#include "number_text.hpp"

#include <CLI/CLI.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace specular {

// The exit code when parsing ends the program (help, bad argument); nothing when the
// program should go on.
inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv, std::string_view tool) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << tool << ": error: " << e.what() << " (see " << tool << " --help)\n";
    return 2;
  }
  return std::nullopt;
}

// Argument values and output numbers of the tools. The parsers are fuzzed
// (tests/fuzz/fuzz_cli_parse.cpp): on any input they return a value inside the asked
// range or throw UsageError, nothing else.
namespace cli {

// A bad argument value: "<arg>: <what>"; the tools report it with exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

[[noreturn]] inline void bad(const std::string& arg, const std::string& what) { throw UsageError(arg + ": " + what); }

// The shortest decimal text that parses back (strtod, std::stod, Python float) to
// exactly v; "nan", "inf", "-inf" for the non-finite values. Every CSV number of the
// tools is printed with it, so that a reader recomputes from the CSV what the tool computed.
inline std::string num(double v) { return shortest_text(v); }

// The whole of s as a double, or nothing (empty, trailing characters, out of range).
inline std::optional<double> to_double(const std::string& s) { return whole_double(s); }

// A finite real in [lo, hi]; `range` names the range in the message.
inline double parse_real(const std::string& arg, const std::string& s, double lo, double hi, const std::string& range) {
  const auto v = to_double(s);
  if (!v || !std::isfinite(*v)) bad(arg, "'" + s + "' is not a number; allowed " + range);
  if (*v < lo || *v > hi) bad(arg, "'" + s + "' is outside the allowed range " + range);
  return *v;
}

// An integer in [lo, hi] (written as any real with no fraction: "7", "7.0", "7e0").
inline int parse_int(const std::string& arg, const std::string& s, int lo, int hi) {
  const std::string range = std::to_string(lo) + ".." + std::to_string(hi);
  const auto v = to_double(s);
  if (!v || !std::isfinite(*v) || *v != std::floor(*v)) bad(arg, "'" + s + "' is not an integer; allowed " + range);
  if (*v < lo || *v > hi) bad(arg, "'" + s + "' is outside the allowed range " + range);
  return static_cast<int>(*v);
}

inline std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, sep)) out.push_back(cur);
  if (!s.empty() && s.back() == sep) out.push_back("");
  return out;
}

// "1..1000", "1,2,7", "1..5,10,20..22"; ranges are integer, single items may be real
// when `reals` is set. Every value is in [lo, hi].
inline std::vector<double> parse_list(const std::string& arg, const std::string& s, int lo, int hi, bool reals) {
  const std::string range = std::to_string(lo) + ".." + std::to_string(hi);
  if (s.empty()) bad(arg, "empty list; expected items like 7, 1..1000 or 1,2,7 in " + range);
  std::vector<double> out;
  for (const std::string& item : split(s, ',')) {
    const auto dots = item.find("..");
    if (dots != std::string::npos) {
      const int a = parse_int(arg, item.substr(0, dots), lo, hi);
      const int b = parse_int(arg, item.substr(dots + 2), lo, hi);
      if (a > b) bad(arg, "range '" + item + "' is empty (first > last); allowed " + range);
      for (int v = a; v <= b; ++v) out.push_back(v);
    } else if (reals) {
      out.push_back(parse_real(arg, item, lo, hi, range));
    } else {
      out.push_back(parse_int(arg, item, lo, hi));
    }
  }
  return out;
}

// "X,Y,Z" with three finite numbers.
inline glm::dvec3 parse_vec(const std::string& arg, const std::string& s) {
  const auto parts = split(s, ',');
  if (parts.size() != 3) bad(arg, "'" + s + "' is not a vector; expected X,Y,Z with finite numbers");
  glm::dvec3 v;
  for (int i = 0; i < 3; ++i) {
    const auto d = to_double(parts[i]);
    if (!d || !std::isfinite(*d)) bad(arg, "'" + s + "' has a non-finite component; expected X,Y,Z with finite numbers");
    v[i] = *d;
  }
  return v;
}

}  // namespace cli

}  // namespace specular
