// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the ROM hex reader (model/device/rom_image.hpp read_hex, format in roms/README.md).
// The first two bytes choose the word width (0..40 bits, beyond the valid 1..32 on purpose)
// and the depth (0..63); the rest is the file. Contract: read_hex returns exactly `depth`
// words that fit in `bits`, or throws std::runtime_error / std::invalid_argument.
#include "rom_image.hpp"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  const int bits = data[0] % 41;
  const int depth = data[1] % 64;
  // read_hex takes a path: the file goes to a per-process temporary file.
  static const std::string path = "/tmp/fuzz_rom_hex_" + std::to_string(::getpid()) + ".hex";
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) std::abort();
  if (size > 2 && std::fwrite(data + 2, 1, size - 2, f) != size - 2) std::abort();
  std::fclose(f);
  try {
    const auto img = specular::read_hex(path, bits, depth);
    // A word wider than 32 bits cannot be returned in a uint32_t: such widths must be
    // refused, not truncated.
    if (bits < 1 || bits > 32) std::abort();
    if (static_cast<int>(img.size()) != depth) std::abort();
    for (uint32_t w : img)
      if (bits < 32 && (w >> bits) != 0) std::abort();
  } catch (const std::runtime_error&) {
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
