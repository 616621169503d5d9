#include "rdsf/core/atomic_file.hpp"

#include <cerrno>
#include <filesystem>
#include <streambuf>
#include <vector>

#include <fcntl.h>

#include "rdsf/core/durable_io.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {

/// A stream buffer over a file descriptor written through the I/O layer; remembers the first failure.
class AtomicTextFile::Buffer : public std::streambuf {
 public:
  Buffer(int fd, std::string path) : fd_(fd), path_(std::move(path)), space_(1 << 16) {
    setp(space_.data(), space_.data() + space_.size());
  }
  ~Buffer() override {
    if (fd_ >= 0) sync();  // best effort, as std::ofstream: the .partial file keeps what was written
    close();
  }

  /// Writes out what is buffered; throws Error with the first failure's cause.
  void drain() {
    if (sync() != 0 || !error_.empty()) fail(path_, error_.empty() ? "write failed" : error_);
  }
  void sync_to_disk() {
    drain();
    sync_data(fd_, path_);
  }
  void close_checked() {
    const int fd = fd_;
    fd_ = -1;
    if (fd >= 0 && io::close(fd) != 0) fail(path_, "write failed on close: " + errno_text(errno));
  }
  void close() {
    if (fd_ >= 0) io::close(fd_);
    fd_ = -1;
  }

 protected:
  int_type overflow(int_type c) override {
    if (sync() != 0) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override {
    if (!error_.empty()) return -1;
    const std::size_t size = static_cast<std::size_t>(pptr() - pbase());
    if (size == 0) return 0;
    try {
      write_all(fd_, pbase(), size, path_, "write failed");
    } catch (const Error& e) {
      const std::string what = e.what();
      const std::string prefix = path_ + ": ";
      error_ = what.compare(0, prefix.size(), prefix) == 0 ? what.substr(prefix.size()) : what;
      return -1;
    }
    setp(space_.data(), space_.data() + space_.size());
    return 0;
  }

 private:
  int fd_;
  std::string path_;
  std::vector<char> space_;
  std::string error_;
};

AtomicTextFile::AtomicTextFile(std::string path, bool overwrite)
    : path_(std::move(path)), partial_(path_ + ".partial") {
  std::error_code ec;
  if (!overwrite && std::filesystem::exists(path_, ec)) {
    throw AlreadyExists(path_ + ": already exists");
  }
  const int fd = io::open(partial_, O_WRONLY | O_CREAT | O_TRUNC);
  if (fd < 0) fail(partial_, "cannot be created: " + errno_text(errno));
  buffer_ = std::make_unique<Buffer>(fd, partial_);
  out_ = std::make_unique<std::ostream>(buffer_.get());
}

AtomicTextFile::~AtomicTextFile() {
  out_.reset();
  buffer_.reset();
}

std::ostream& AtomicTextFile::stream() { return *out_; }

void AtomicTextFile::flush() {
  out_->flush();
  buffer_->drain();
}

void AtomicTextFile::commit() {
  if (committed_) return;
  flush();
  buffer_->sync_to_disk();
  buffer_->close_checked();
  if (io::rename(partial_, path_) != 0) fail(path_, "cannot rename " + partial_ + " into place: " + errno_text(errno));
  sync_folder(parent_folder(path_));
  committed_ = true;
}

}  // namespace rdsf
