#pragma once
// Unsigned integers stored in a byte order of their own, read from bytes in memory (any alignment): the one
// reader of ROS bag record lengths (little-endian), PNG chunk fields (big-endian) and compressedDepth headers
// (little-endian).
#include <cstdint>

namespace rdsf {

/// The `count` (1..8) bytes at `bytes` as an unsigned little-endian integer.
inline std::uint64_t load_little_endian(const void* bytes, int count) {
  const auto* p = static_cast<const unsigned char*>(bytes);
  std::uint64_t value = 0;
  for (int i = count - 1; i >= 0; --i) value = (value << 8) | p[i];
  return value;
}

/// The 4 bytes at `bytes` as an unsigned little-endian integer.
inline std::uint32_t load_little_endian_u32(const void* bytes) {
  return static_cast<std::uint32_t>(load_little_endian(bytes, 4));
}

/// The 4 bytes at `bytes` as an unsigned big-endian integer.
inline std::uint32_t load_big_endian_u32(const void* bytes) {
  const auto* p = static_cast<const unsigned char*>(bytes);
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | p[3];
}

}  // namespace rdsf
