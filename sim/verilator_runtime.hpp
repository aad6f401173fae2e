// SPDX-License-Identifier: Apache-2.0
// Settings shared by every VerilatedContext the harnesses create, and what the run
// accumulates across them:
//   - Verilator runtime arguments (+verilator+seed+N, +verilator+rand+reset+2, ...): each
//     harness owns its own context, so sim_regression keeps the arguments here and every
//     harness applies them to its context before it constructs the model. With the models
//     verilated `--x-initial unique --x-assign unique` (sim/CMakeLists.txt), rand-reset 2
//     fills every register without reset, RAM word and X constant with seed-dependent values.
//   - The output digest: FNV-1a over every output port of every model, every cycle, in
//     order. Runs that differ only in the Verilator seed must give the same digest (no
//     output may depend on an uninitialized value): the ctest sim_xprop compares them.
//   - Coverage (models verilated with --coverage, VM_COVERAGE=1): each context's coverage
//     is written as DIR/<model>_<k>.dat when its harness ends; verilator_coverage merges them.
#pragma once

#include <verilated.h>
#if VM_COVERAGE
#include <verilated_cov.h>
#endif

#include <cerrno>
#include <cstdint>
#include <string>
#include <vector>

namespace specular::sim {

struct VerilatorRuntime {
  std::vector<std::string> args;  // "+verilator+..." arguments, in command-line order
  std::string coverage_dir;       // empty: coverage (when compiled in) is not written
  struct Digest {
    std::string model;
    uint64_t hash = 0xcbf29ce484222325ULL;  // FNV-1a offset basis
    uint64_t cycles = 0;
  };
  Digest total{"all models"};
  std::vector<Digest> per_model;  // one per harness, in construction order
  int coverage_files = 0;
};

inline VerilatorRuntime& verilator_runtime() {
  static VerilatorRuntime rt;
  return rt;
}

// Applies the +verilator+ arguments to a harness's context (before its model exists: the
// model's constructor draws the initial values).
inline void configure_context(VerilatedContext& ctx) {
  const auto& rt = verilator_runtime();
  if (rt.args.empty()) return;
  std::vector<const char*> argv{"sim_regression"};
  for (const auto& a : rt.args) argv.push_back(a.c_str());
  errno = 0;  // Verilator 5.006 tests errno after strtoull without clearing it first
  ctx.commandArgs(static_cast<int>(argv.size()), argv.data());
}

// A new digest for one harness (its outputs in every cycle); returns its slot.
inline size_t new_digest(const std::string& model) {
  auto& rt = verilator_runtime();
  rt.per_model.push_back({model + " #" + std::to_string(rt.per_model.size())});
  return rt.per_model.size() - 1;
}

// One output sample (all ports of one model in one cycle, packed by the caller).
inline void digest_add(size_t slot, uint64_t v) {
  auto& rt = verilator_runtime();
  for (auto* d : {&rt.total, &rt.per_model[slot]}) {
    for (int b = 0; b < 8; ++b) {
      d->hash ^= (v >> (8 * b)) & 0xff;
      d->hash *= 0x100000001b3ULL;
    }
    ++d->cycles;
  }
}

// Writes the context's coverage points (no-op unless built with --coverage and a directory is set).
inline void write_coverage([[maybe_unused]] VerilatedContext& ctx, [[maybe_unused]] const std::string& model) {
#if VM_COVERAGE
  auto& rt = verilator_runtime();
  if (rt.coverage_dir.empty()) return;
  const std::string path = rt.coverage_dir + "/" + model + "_" + std::to_string(rt.coverage_files++) + ".dat";
  ctx.coveragep()->write(path.c_str());
#endif
}

}  // namespace specular::sim
