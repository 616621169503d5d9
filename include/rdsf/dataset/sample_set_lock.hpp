#pragma once
// The writer's lock on a sample set: the file "lock" in the set's folder, holding the writer's pid and
// host, with an exclusive flock() on it for as long as the writer lives. A second writer is refused with
// a message naming the set and the holder. When the holder was killed, the kernel has released its flock:
// the stale file is taken over. The file is removed when the lock is released normally.
// The lock file is not synced: after a power cut no process holds its flock, and it is taken over.
// (flock() is local to one machine on some network file systems: let each cluster job write its own set.)
#include <string>

namespace rdsf {

class SampleSetLock {
 public:
  /// Takes the lock on the set in `dir`; throws Error naming the set and the holder when it is held.
  explicit SampleSetLock(const std::string& dir);
  ~SampleSetLock();
  SampleSetLock(SampleSetLock&& other) noexcept;
  SampleSetLock& operator=(SampleSetLock&& other) noexcept;
  SampleSetLock(const SampleSetLock&) = delete;
  SampleSetLock& operator=(const SampleSetLock&) = delete;

  /// True when a lock file left by a killed writer was found and taken over.
  bool took_over_stale() const { return took_over_stale_; }
  /// "pid 1234 on host node7" of a stale lock taken over (empty otherwise).
  const std::string& stale_holder() const { return stale_holder_; }
  const std::string& path() const { return path_; }
  /// Releases the lock and removes the file (also done by the destructor).
  void release();

 private:
  std::string path_;
  int fd_ = -1;
  bool took_over_stale_ = false;
  std::string stale_holder_;
};

}  // namespace rdsf
