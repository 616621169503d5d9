// The record-length guard in front of librosbag (rdsf/frame/bag_layout.hpp), on bags built byte by byte:
// no ROS needed. tests/test_bag_source.cpp checks it on bags written by python3-rosbag.
#include <gtest/gtest.h>

#include <fstream>

#include "rdsf/frame/bag_layout.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

std::string le(std::uint64_t value, int bytes) {
  std::string s;
  for (int i = 0; i < bytes; ++i) s += static_cast<char>((value >> (8 * i)) & 0xff);
  return s;
}

std::string field(const std::string& name, const std::string& value) {
  return le(name.size() + 1 + value.size(), 4) + name + "=" + value;
}

std::string record(const std::string& header, const std::string& data) {
  return le(header.size(), 4) + header + le(data.size(), 4) + data;
}

/// An uncompressed chunk's data: one message record of two bytes.
const std::string kChunkData = record(field("op", "\x02") + field("conn", le(0, 4)) + field("time", le(0, 8)), "xx");

/// A bag of a bag header, one uncompressed chunk and one connection record; index_pos at the connection.
std::string small_bag(std::uint64_t* index_pos = nullptr, const std::string& version = "#ROSBAG V2.0\n") {
  const std::string chunk = record(field("op", "\x05") + field("compression", "none") +
                                       field("size", le(kChunkData.size(), 4)),
                                   kChunkData);
  const std::string connection = record(field("op", "\x07") + field("conn", le(0, 4)) + field("topic", "/d"),
                                        field("type", "sensor_msgs/Image"));
  // The bag header's own length does not depend on index_pos's value: build it once to learn its size.
  const auto header_record = [](std::uint64_t pos) {
    return record(field("op", "\x03") + field("index_pos", le(pos, 8)) + field("conn_count", le(1, 4)) +
                      field("chunk_count", le(1, 4)),
                  std::string(64, ' '));
  };
  const std::uint64_t pos = version.size() + header_record(0).size() + chunk.size();
  if (index_pos != nullptr) *index_pos = pos;
  return version + header_record(pos) + chunk + connection;
}

std::string problem_of(const test::TempDir& dir, const std::string& bytes) {
  const std::string path = dir / "b.bag";
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return bag_layout_problem(path);
}

}  // namespace

TEST(BagLayout, AWholeBagPasses) {
  test::TempDir dir("rdsf-bag-layout");
  EXPECT_EQ(problem_of(dir, small_bag()), "");
}

TEST(BagLayout, LengthsBeyondTheFileAreRefusedWithTheirByte) {
  test::TempDir dir("rdsf-bag-layout");
  std::uint64_t index_pos = 0;
  std::string bag = small_bag(&index_pos);
  // The connection record's header length says 0x8A000000 bytes (what the fuzzer found: librosbag reserved
  // 2.3 GB for it).
  std::string damaged = bag;
  damaged.replace(index_pos, 4, le(0x8A000000u, 4));
  std::string p = problem_of(dir, damaged);
  EXPECT_NE(p.find("the record at byte " + std::to_string(index_pos) + " says its header is 2315255808 bytes long, "
                   "beyond the file's end"), std::string::npos) << p;
  // Cut inside the last record's data.
  p = problem_of(dir, bag.substr(0, bag.size() - 3));
  EXPECT_NE(p.find("says its data is"), std::string::npos) << p;
  EXPECT_NE(p.find("truncated or damaged"), std::string::npos) << p;
  // Cut inside a length field.
  p = problem_of(dir, bag.substr(0, index_pos + 2));
  EXPECT_NE(p.find("is cut short"), std::string::npos) << p;
}

TEST(BagLayout, AnIndexPositionInsideARecordIsRefused) {
  test::TempDir dir("rdsf-bag-layout");
  std::uint64_t index_pos = 0;
  std::string bag = small_bag(&index_pos);
  const std::string at = le(index_pos, 8), inside = le(index_pos - 5, 8);
  bag.replace(bag.find(at), 8, inside);
  const std::string p = problem_of(dir, bag);
  EXPECT_NE(p.find("its index position (byte " + std::to_string(index_pos - 5) + ") is not the start of a record"),
            std::string::npos) << p;
  // 0 is an unindexed bag: librosbag says so itself.
  bag.replace(bag.find(inside), 8, le(0, 8));
  EXPECT_EQ(problem_of(dir, bag), "");
}

TEST(BagLayout, ChunkSizesMustMatchTheirData) {
  test::TempDir dir("rdsf-bag-layout");
  std::string bag = small_bag();
  const std::size_t n = kChunkData.size();
  const std::string size8 = field("size", le(n, 4));
  bag.replace(bag.find(size8), size8.size(), field("size", le(n + 1, 4)));
  EXPECT_NE(problem_of(dir, bag).find("says it holds " + std::to_string(n + 1) + " bytes, its data is " +
                                      std::to_string(n)),
            std::string::npos);
  // Compressed: any size up to 1 GiB, not beyond.
  std::string packed = small_bag();
  const std::string none = field("compression", "none");
  packed.replace(packed.find(none), none.size(), field("compression", "lz4 "));  // the same length
  EXPECT_EQ(problem_of(dir, packed), "");
  packed.replace(packed.find(size8), size8.size(), field("size", le(0xF0000000u, 4)));
  EXPECT_NE(problem_of(dir, packed).find("says it unpacks to 4026531840 bytes (more than 1 GiB)"), std::string::npos);
}

TEST(BagLayout, HeaderFieldsMustEndInsideTheirHeaderWhateverTheVersionLineSays) {
  test::TempDir dir("rdsf-bag-layout");
  // librosbag reads "#ROS<word> V2.0" as version 2.0, so the guard does too.
  std::string bag = small_bag(nullptr, "#ROSBA?G V2.0\n");
  EXPECT_EQ(problem_of(dir, bag), "");
  const std::string op = field("op", "\x03");
  const std::size_t at = bag.find(op);
  bag.replace(at, 4, le(720903, 4));  // the bag header's first field now reaches beyond its header
  const std::string p = problem_of(dir, bag);
  EXPECT_NE(p.find("the record at byte 14 has a header field of 720903 bytes, beyond its header's end"),
            std::string::npos) << p;
}

TEST(BagLayout, AnUncompressedChunksRecordsAndAConnectionsDataAreWalkedToo) {
  test::TempDir dir("rdsf-bag-layout");
  std::string bag = small_bag();
  const std::size_t inner = bag.find(kChunkData);
  bag.replace(inner, 4, le(1000, 4));  // the message record's header now reaches beyond its chunk
  std::string p = problem_of(dir, bag);
  EXPECT_NE(p.find("the record at byte " + std::to_string(inner) + " says its header is 1000 bytes long, beyond its "
                   "chunk's end"), std::string::npos) << p;
  // A connection record's data is a header to librosbag: a field reaching beyond it is refused.
  bag = small_bag();
  const std::string type = field("type", "sensor_msgs/Image");
  bag.replace(bag.find(type), 4, le(500, 4));
  p = problem_of(dir, bag);
  EXPECT_NE(p.find("has a data field of 500 bytes, beyond its data's end"), std::string::npos) << p;
}

TEST(BagLayout, OtherFilesAreLeftToLibrosbag) {
  test::TempDir dir("rdsf-bag-layout");
  EXPECT_EQ(problem_of(dir, "#ROSBAG V1.2\n" + std::string(100, '\x7f')), "");
  EXPECT_EQ(problem_of(dir, "not a bag\n"), "");
  EXPECT_EQ(bag_layout_problem(dir / "missing.bag"), "");
}
