// SPDX-License-Identifier: Apache-2.0
// Spans as CSV text, the input of `specular setup-batch` (docs/scanline_setup.md#batched-setup):
//
//   n1x,n1y,n1z,n2x,n2y,n2z,h1x,h1y,h1z,hex,hey,hez,n,l,scale      (header line, exactly)
//   0,0,1,0.1,0,1,0,0,1,0,0,1,50,7,0.9                           (one line per span)
//
// Every field is a number as strtod reads it ("nan" and "inf" included: the setup gives such
// a span the status invalid_input); l is an integer in the int32 range; scale = Is * ks * s(n).
// Empty lines are skipped, a trailing '\r' is ignored. Anything else is malformed: SpanCsvError
// names the source, the line number (1 = the header) and the column.
#pragma once

#include "setup_batch.hpp"

#include <stdexcept>
#include <string>
#include <string_view>

namespace specular::host {

inline constexpr const char* kSpanCsvHeader = "n1x,n1y,n1z,n2x,n2y,n2z,h1x,h1y,h1z,hex,hey,hez,n,l,scale";

class SpanCsvError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Parses the whole text (`source` names it in messages). Throws SpanCsvError.
SpanBatch parse_span_csv(std::string_view text, const std::string& source);

// The register CSV written by `specular setup-batch`: a header
// status,c_code,psi0_code,dpsi_code,n,l,C,psi0,dpsi and one line per span: the status name,
// the register codes (psi0 and dpsi signed) and the decoded C, psi0, dpsi (shortest text that
// parses back to the same double).
std::string register_csv(const RegisterBatch& regs, const device::Format& f);

}  // namespace specular::host
