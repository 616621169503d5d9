#pragma once
// A guard for the ROS 1 bags BagSource hands to librosbag, found by fuzzing (fuzz/fuzz_bag.cpp): librosbag
// trusts the lengths a bag states, so a damaged one makes it reserve what a length field says (up to 4 GiB
// for one record header) before it finds the file too short. The guard reads only the lengths of the bag's
// top-level records, never their contents (librosbag stays the one reader of bags).
//
// A version 2.0 bag is a first line librosbag reads as such ("#ROSBAG V2.0\n"; librosbag takes any
// "#ROS<word> V2.0") and then records, each
//     header_len (uint32 little-endian) | header (fields: field_len uint32 | name=value) | data_len | data
// Refused, with the byte offset: a record whose stated lengths reach beyond the file's end (a truncated or
// damaged bag) or beyond its chunk's end, a header field beyond its header's end (also in a connection
// record's data, which librosbag reads as a header; ros::Header::parse does not check); a bag header (op
// 0x03) whose index_pos is neither 0 (unindexed: librosbag says so itself) nor the start of a record (nor
// the file's end); a chunk (op 0x05) whose uncompressed size differs from its data length when it is not
// compressed (its records are then walked the same way), or exceeds kMaxChunkBytes when it is (compressed
// chunks' records are not seen). Any other first line (a version 1.2 bag, no bag at all) is left to
// librosbag's own message.
#include <cstdint>
#include <string>

namespace rdsf {

/// A chunk unpacking to more than this is refused (rosbag record writes chunks of 768 KiB by default).
constexpr std::uint64_t kMaxChunkBytes = std::uint64_t{1} << 30;

/// The first problem of the bag at `path`'s record layout ("the record at byte N ..."), or "".
std::string bag_layout_problem(const std::string& path);

}  // namespace rdsf
