// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the span CSV reader of `specular setup-batch` (model/host/span_csv.hpp),
// and, differentially, the batched setup against the scalar reference on whatever spans it
// accepts. Contract: parse_span_csv returns spans or throws SpanCsvError; for every span the
// batch gives the scalar setup's status and flags, and registers whose pixels agree within
// the tolerance of docs/scanline_setup.md#batched-setup.
#include "span_csv.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace specular;
  host::SpanBatch spans;
  try {
    spans = host::parse_span_csv(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz");
  } catch (const host::SpanCsvError&) {
    return 0;
  }
  const device::Format f;
  host::RegisterBatch ref, got;
  host::setup_scalar(spans, f, ref);
  host::setup_batch(spans, f, got);
  if (got.size() != spans.size() || ref.size() != spans.size()) std::abort();
  for (size_t i = 0; i < spans.size(); ++i) {
    if (got.status[i] != ref.status[i] || got.flags[i] != ref.flags[i] || got.n[i] != ref.n[i] ||
        got.len[i] != ref.len[i])
      std::abort();
    if (!host::compare_pixels(got.registers(i), ref.registers(i), f).ok()) std::abort();
  }
  (void)host::register_csv(got, f);
  return 0;
}
