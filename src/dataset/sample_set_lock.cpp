#include "rdsf/dataset/sample_set_lock.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <utility>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "rdsf/core/durable_io.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {

namespace {

std::string read_holder(int fd) {
  char text[256] = {};
  const ssize_t n = pread(fd, text, sizeof text - 1, 0);
  std::string holder = n > 0 ? std::string(text, static_cast<std::size_t>(n)) : std::string();
  while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' ')) holder.pop_back();
  return holder.empty() ? "an unknown process" : holder;
}

std::string this_process() {
  char host[256] = {};
  if (gethostname(host, sizeof host - 1) != 0) std::strcpy(host, "unknown");
  return "pid " + std::to_string(getpid()) + " on host " + host;
}

}  // namespace

SampleSetLock::SampleSetLock(const std::string& dir) : path_((std::filesystem::path(dir) / "lock").string()) {
  for (int attempt = 0; attempt < 10; ++attempt) {
    bool created = true;
    int fd = io::open(path_, O_RDWR | O_CREAT | O_EXCL);
    if (fd < 0 && errno == EEXIST) {
      created = false;
      fd = io::open(path_, O_RDWR);
      if (fd < 0 && errno == ENOENT) continue;  // released meanwhile: try again
    }
    if (fd < 0) fail(path_, "cannot create the sample set's lock file: " + errno_text(errno));
    if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      const std::string holder = read_holder(fd);
      io::close(fd);
      if (error == EWOULDBLOCK) {
        fail(dir, "sample set is being written by another program (" + holder + ", lock file " + path_ +
                      "); wait for it to finish or stop it first");
      }
      fail(path_, std::string("cannot lock: ") + std::strerror(error));
    }
    // The file we locked must still be the one under the name (a releasing holder unlinks it).
    struct stat opened {}, named {};
    if (fstat(fd, &opened) != 0 || stat(path_.c_str(), &named) != 0 || opened.st_ino != named.st_ino ||
        opened.st_dev != named.st_dev) {
      io::close(fd);
      continue;
    }
    if (!created) {
      took_over_stale_ = true;
      stale_holder_ = read_holder(fd);
    }
    const std::string me = this_process() + "\n";
    if (io::ftruncate(fd, 0) != 0 || lseek(fd, 0, SEEK_SET) != 0 ||
        io::write(fd, me.data(), me.size()) != static_cast<long>(me.size())) {
      const int error = errno;
      io::close(fd);
      fail(path_, "cannot write the lock file: " + errno_text(error));
    }
    fd_ = fd;
    return;
  }
  fail(path_, "lock file keeps changing under this program; is another writer starting and stopping?");
}

SampleSetLock::~SampleSetLock() { release(); }

SampleSetLock::SampleSetLock(SampleSetLock&& other) noexcept
    : path_(std::move(other.path_)),
      fd_(std::exchange(other.fd_, -1)),
      took_over_stale_(other.took_over_stale_),
      stale_holder_(std::move(other.stale_holder_)) {}

SampleSetLock& SampleSetLock::operator=(SampleSetLock&& other) noexcept {
  if (this != &other) {
    release();
    path_ = std::move(other.path_);
    fd_ = std::exchange(other.fd_, -1);
    took_over_stale_ = other.took_over_stale_;
    stale_holder_ = std::move(other.stale_holder_);
  }
  return *this;
}

void SampleSetLock::release() {
  if (fd_ < 0) return;
  io::unlink(path_);  // while still holding the flock, so nobody locks the old file meanwhile
  io::close(fd_);
  fd_ = -1;
}

}  // namespace rdsf
