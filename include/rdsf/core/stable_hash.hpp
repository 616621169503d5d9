#pragma once
// A hash that never changes between builds, compilers or machines (64-bit FNV-1a), written as 16 hex
// digits. Used for feature spec hashes and file fingerprints; not for security.
#include <cstdint>
#include <string>
#include <string_view>

namespace rdsf {

std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t seed = 0xcbf29ce484222325ULL);
std::string to_hex16(std::uint64_t value);

}  // namespace rdsf
