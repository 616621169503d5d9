// libFuzzer target for the model_file parser (see fuzz_entry_points.hpp and docs/fuzzing.md).
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_entry_points.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return rdsf::fuzz::fuzz_one("model_file", data, size);
}
