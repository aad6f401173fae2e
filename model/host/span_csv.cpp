// SPDX-License-Identifier: Apache-2.0
// Span and register CSV (model/host/span_csv.hpp).
#include "span_csv.hpp"

#include "number_text.hpp"

#include <fmt/format.h>

#include <charconv>
#include <iterator>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace specular::host {

namespace {

constexpr const char* kColumns[] = {"n1x", "n1y", "n1z", "n2x", "n2y", "n2z", "h1x", "h1y",
                                    "h1z", "hex", "hey", "hez", "n",   "l",   "scale"};
constexpr int kColumnCount = 15;

[[noreturn]] void fail(const std::string& source, size_t line, const std::string& what) {
  throw SpanCsvError(source + ":" + std::to_string(line) + ": " + what);
}

// The whole field as a double (strtod syntax), or false.
bool to_double(std::string_view f, double& v) {
  if (f.empty() || f.size() > 64 || std::isspace(static_cast<unsigned char>(f.front()))) return false;
  const std::string s(f);
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}


}  // namespace

SpanBatch parse_span_csv(std::string_view text, const std::string& source) {
  SpanBatch b;
  size_t line_no = 0, pos = 0;
  bool header = false;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.empty()) continue;
    if (!header) {
      if (line != kSpanCsvHeader)
        fail(source, line_no, "the header must be exactly " + std::string(kSpanCsvHeader));
      header = true;
      continue;
    }
    double v[kColumnCount];
    size_t start = 0;
    for (int c = 0; c < kColumnCount; ++c) {
      const size_t comma = line.find(',', start);
      const bool last = c == kColumnCount - 1;
      if (!last && comma == std::string_view::npos)
        fail(source, line_no, "has " + std::to_string(c + 1) + " columns; expected 15 (" + kSpanCsvHeader + ")");
      if (last && comma != std::string_view::npos) fail(source, line_no, "has more than 15 columns");
      const std::string_view field = line.substr(start, last ? std::string_view::npos : comma - start);
      start = comma + 1;
      if (!to_double(field, v[c]))
        fail(source, line_no, std::string("column ") + kColumns[c] + ": '" + std::string(field.substr(0, 40)) +
                                  "' is not a number");
      if (c == 13 && !(v[c] == std::floor(v[c]) && std::abs(v[c]) <= std::numeric_limits<int32_t>::max()))
        fail(source, line_no, "column l: '" + std::string(field.substr(0, 40)) +
                                  "' is not an integer in -2147483647..2147483647 (the device takes 0.." +
                                  std::to_string(kMaxLen) + ")");
    }
    ScanlineInput in;
    in.n1 = {v[0], v[1], v[2]};
    in.n2 = {v[3], v[4], v[5]};
    in.h1 = {v[6], v[7], v[8]};
    in.he = {v[9], v[10], v[11]};
    in.n = v[12];
    in.l = static_cast<int>(v[13]);
    in.is = v[14];
    b.push_back(in);
  }
  if (!header) fail(source, line_no + (line_no == 0), "no header line; expected " + std::string(kSpanCsvHeader));
  return b;
}

std::string register_csv(const RegisterBatch& r, const device::Format& f) {
  std::string out = "status,c_code,psi0_code,dpsi_code,n,l,C,psi0,dpsi\n";
  auto it = std::back_inserter(out);
  for (size_t i = 0; i < r.size(); ++i)
    fmt::format_to(it, "{},{},{},{},{},{},{},{},{}\n", to_string(r.setup_status(i)), r.c[i], r.psi0[i], r.dpsi[i], r.n[i],
                   r.len[i], shortest_text(device::c_value(r.c[i], f)), shortest_text(device::angle_value(r.psi0[i], f)),
                   shortest_text(device::angle_value(r.dpsi[i], f)));
  return out;
}

}  // namespace specular::host
