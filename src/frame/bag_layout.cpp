#include "rdsf/frame/bag_layout.hpp"

#include <cstdio>
#include <fstream>
#include <optional>
#include <set>
#include <vector>

#include "rdsf/core/byte_order.hpp"

namespace rdsf {
namespace {

/// The length of the first line (with its '\n') when librosbag reads it as version 2.0 (its own test:
/// "#ROS<word> V<major>.<minor>"), else 0.
std::uint64_t version_2_0_line_bytes(std::ifstream& in) {
  std::string head(4096, '\0');  // a version line longer than this is left to librosbag
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  const auto newline = head.find('\n');
  if (newline == std::string::npos || newline >= static_cast<std::size_t>(in.gcount())) return 0;
  const std::string line = head.substr(0, newline);
  std::vector<char> word(line.size() + 1);  // sscanf's %s: at most the whole line
  int major = 0, minor = 0;
  if (std::sscanf(line.c_str(), "#ROS%s V%d.%d", word.data(), &major, &minor) != 3 || major != 2 || minor != 0) {
    return 0;
  }
  return line.size() + 1;
}

/// The fields of one record header that the guard needs.
struct RecordFields {
  std::optional<int> op;
  std::optional<std::uint64_t> index_pos;   // bag header
  std::optional<std::uint64_t> chunk_size;  // chunk: its size unpacked
  std::string compression;                  // chunk
};

/// Reads the fields of `header` (field_len | name=value ...), the record's "header" or "data" (`part`); "" or
/// the problem.
std::string read_fields(const std::string& header, std::uint64_t at, RecordFields& fields, const std::string& part) {
  std::size_t i = 0;
  while (i < header.size()) {
    if (header.size() - i < 4) return "the record at byte " + std::to_string(at) + " has a " + part + " field cut short";
    const std::uint64_t length = load_little_endian(header.data() + i, 4);
    i += 4;
    if (length > header.size() - i) {
      return "the record at byte " + std::to_string(at) + " has a " + part + " field of " + std::to_string(length) +
             " bytes, beyond its " + part + "'s end";
    }
    const std::string field = header.substr(i, length);
    i += length;
    const auto equals = field.find('=');
    if (equals == std::string::npos) continue;  // librosbag refuses it with its own message
    const std::string name = field.substr(0, equals);
    const std::string value = field.substr(equals + 1);
    if (name == "op" && value.size() == 1) fields.op = static_cast<unsigned char>(value[0]);
    if (name == "index_pos" && value.size() == 8) fields.index_pos = load_little_endian(value.data(), 8);
    if (name == "size" && value.size() == 4) fields.chunk_size = load_little_endian(value.data(), 4);
    if (name == "compression") fields.compression = value;
  }
  return "";
}

/// Walks the records in [begin, end) of `in`: every length and header field inside its bounds, a connection
/// record's data (a header too) likewise, and an uncompressed chunk's records in turn. Collects the
/// top-level record starts and the bag header's index_pos. "" or the first problem.
class RecordWalk {
 public:
  RecordWalk(std::ifstream& in, std::uint64_t file_bytes) : in_(in), file_bytes_(file_bytes) {}

  std::string walk(std::uint64_t begin, std::uint64_t end, bool top_level) {
    std::uint64_t at = begin;
    char length_bytes[4];
    while (at < end) {
      if (top_level) starts.insert(at);
      if (end - at < 4) return "the record at byte " + std::to_string(at) + " is cut short";
      in_.seekg(static_cast<std::streamoff>(at));
      in_.read(length_bytes, 4);
      const std::uint64_t header_bytes = load_little_endian(length_bytes, 4);
      if (header_bytes > end - at - 4) return beyond(at, "header", header_bytes, end);
      std::string header(header_bytes, '\0');
      in_.read(header.data(), static_cast<std::streamsize>(header_bytes));
      const std::uint64_t data_len_at = at + 4 + header_bytes;
      if (end - data_len_at < 4) return "the record at byte " + std::to_string(at) + " is cut short";
      in_.read(length_bytes, 4);
      const std::uint64_t data_bytes = load_little_endian(length_bytes, 4);
      if (!in_) return "the record at byte " + std::to_string(at) + " could not be read";
      if (data_bytes > end - data_len_at - 4) return beyond(at, "data", data_bytes, end);
      const std::uint64_t data_at = data_len_at + 4;
      RecordFields fields;
      std::string problem = read_fields(header, at, fields, "header");
      if (!problem.empty()) return problem;
      if (top_level && fields.op == 0x03 && fields.index_pos) index_pos = fields.index_pos;
      if (fields.op == 0x07) {  // a connection: its data is read as a header as well
        std::string data(data_bytes, '\0');
        in_.read(data.data(), static_cast<std::streamsize>(data_bytes));
        RecordFields ignored;
        problem = read_fields(data, at, ignored, "data");
        if (!problem.empty()) return problem;
      }
      if (fields.op == 0x05 && fields.chunk_size) {
        const bool packed = !fields.compression.empty() && fields.compression != "none";
        if (!packed && *fields.chunk_size != data_bytes) {
          return "the chunk at byte " + std::to_string(at) + " says it holds " + std::to_string(*fields.chunk_size) +
                 " bytes, its data is " + std::to_string(data_bytes);
        }
        if (packed && *fields.chunk_size > kMaxChunkBytes) {
          return "the chunk at byte " + std::to_string(at) + " says it unpacks to " +
                 std::to_string(*fields.chunk_size) + " bytes (more than 1 GiB)";
        }
        if (!packed) {
          problem = walk(data_at, data_at + data_bytes, false);
          if (!problem.empty()) return problem;
        }
      }
      at = data_at + data_bytes;
    }
    return "";
  }

  std::set<std::uint64_t> starts;          ///< the top-level records' first bytes
  std::optional<std::uint64_t> index_pos;  ///< the bag header's

 private:
  std::string beyond(std::uint64_t at, const std::string& what, std::uint64_t bytes, std::uint64_t end) const {
    const std::string limit = end == file_bytes_ ? "the file's end (" + std::to_string(file_bytes_) +
                                                       " bytes: truncated or damaged)"
                                                 : "its chunk's end (byte " + std::to_string(end) + ")";
    return "the record at byte " + std::to_string(at) + " says its " + what + " is " + std::to_string(bytes) +
           " bytes long, beyond " + limit;
  }

  std::ifstream& in_;
  std::uint64_t file_bytes_;
};

}  // namespace

std::string bag_layout_problem(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";  // librosbag says why it cannot open it
  in.seekg(0, std::ios::end);
  const std::uint64_t file_bytes = static_cast<std::uint64_t>(in.tellg());
  in.seekg(0);
  const std::uint64_t version_bytes = version_2_0_line_bytes(in);
  if (version_bytes == 0) return "";
  in.clear();
  RecordWalk records(in, file_bytes);
  const std::string problem = records.walk(version_bytes, file_bytes, true);
  if (!problem.empty()) return problem;
  const auto index_pos = records.index_pos;
  if (index_pos && *index_pos != 0 && *index_pos != file_bytes && records.starts.count(*index_pos) == 0) {
    return "its index position (byte " + std::to_string(*index_pos) + ") is not the start of a record";
  }
  return "";
}

}  // namespace rdsf
