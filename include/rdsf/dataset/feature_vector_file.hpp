#pragma once
// vectors.<feature spec hash>.f32 in a sample set: the stored feature vectors of samples that have no crop
// (imported from the thesis's text format). Binary, append-only, little-endian: per sample the int64 id
// followed by `dimension` float32 values. A torn last record (killed writer) is ignored by readers and cut
// off by the next writer; when an id appears twice the later record wins.
#include <cstdint>
#include <string>
#include <unordered_map>

namespace rdsf {

class FeatureVectorFile {
 public:
  /// "<dir>/vectors.<spec_hash>.f32"
  static std::string path_in(const std::string& dir, const std::string& spec_hash);

  /// Indexes the file (ids and offsets); a missing file holds nothing. Throws Error naming the file when it
  /// cannot be read.
  FeatureVectorFile(std::string path, int dimension);
  ~FeatureVectorFile();
  FeatureVectorFile(const FeatureVectorFile&) = delete;
  FeatureVectorFile& operator=(const FeatureVectorFile&) = delete;

  bool contains(std::int64_t id) const { return offsets_.count(id) != 0; }
  /// Reads the vector of `id` into `out` (dimension floats); throws Error when absent. Thread-safe.
  void read(std::int64_t id, float* out) const;
  const std::string& path() const { return path_; }
  /// Bytes of complete records.
  std::uint64_t complete_bytes() const { return complete_bytes_; }
  /// Offset of the first record whose id is >= `id` (complete_bytes() when none): where a writer cuts off
  /// vectors of samples whose index row was never written.
  std::uint64_t first_offset_from(std::int64_t id) const;
  std::uint64_t record_bytes() const { return 8 + 4 * static_cast<std::uint64_t>(dimension_); }

 private:
  std::string path_;
  int dimension_;
  std::unordered_map<std::int64_t, std::uint64_t> offsets_;
  std::uint64_t complete_bytes_ = 0;
  int fd_ = -1;
};

}  // namespace rdsf
