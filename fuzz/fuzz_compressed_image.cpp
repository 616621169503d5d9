// libFuzzer target for the compressed_image entry point (see fuzz_entry_points.hpp and docs/fuzzing.md).
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_entry_points.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return rdsf::fuzz::fuzz_one("compressed_image", data, size);
}
