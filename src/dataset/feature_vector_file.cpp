#include "rdsf/dataset/feature_vector_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <limits>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#include "rdsf/core/error.hpp"

namespace rdsf {

std::string FeatureVectorFile::path_in(const std::string& dir, const std::string& spec_hash) {
  return (std::filesystem::path(dir) / ("vectors." + spec_hash + ".f32")).string();
}

FeatureVectorFile::FeatureVectorFile(std::string path, int dimension) : path_(std::move(path)), dimension_(dimension) {
  std::error_code ec;
  if (!std::filesystem::exists(path_, ec)) return;
  const std::uint64_t size = std::filesystem::file_size(path_, ec);
  if (ec) fail(path_, "cannot be read: " + ec.message());
  fd_ = open(path_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) fail(path_, std::string("cannot be opened: ") + std::strerror(errno));
  const int fd = fd_;
  const std::uint64_t step = record_bytes();
  const std::uint64_t records = size / step;
  complete_bytes_ = records * step;
  offsets_.reserve(static_cast<std::size_t>(records));
  for (std::uint64_t r = 0; r < records; ++r) {
    std::int64_t id = 0;
    if (pread(fd, &id, sizeof id, static_cast<off_t>(r * step)) != static_cast<ssize_t>(sizeof id)) {
      fail(path_, "read failed at record " + std::to_string(r));
    }
    offsets_[id] = r * step;
  }
}

FeatureVectorFile::~FeatureVectorFile() {
  if (fd_ >= 0) close(fd_);
}

std::uint64_t FeatureVectorFile::first_offset_from(std::int64_t id) const {
  std::uint64_t first = complete_bytes_;
  for (const auto& [record_id, offset] : offsets_) {
    if (record_id >= id && offset < first) first = offset;
  }
  return first;
}

void FeatureVectorFile::read(std::int64_t id, float* out) const {
  const auto found = offsets_.find(id);
  if (found == offsets_.end()) fail(path_, "holds no feature vector for sample " + std::to_string(id));
  const std::size_t bytes = 4 * static_cast<std::size_t>(dimension_);
  const ssize_t n = pread(fd_, out, bytes, static_cast<off_t>(found->second + 8));
  if (n != static_cast<ssize_t>(bytes)) fail(path_, "short read of sample " + std::to_string(id));
}

}  // namespace rdsf
