#include "rdsf/core/durable_io.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "rdsf/core/error.hpp"

namespace rdsf {

namespace io {

namespace {

struct Layer {
  std::mutex mutex;
  bool configured = false;
  Fault fault;
  std::int64_t calls = 0;
  int record_fd = -1;
  std::string count_path;
};

Layer& layer() {
  static Layer* instance = new Layer;  // never destroyed: used until the very end of the program
  return *instance;
}

int parse_errno(const std::string& name) {
  if (name == "ENOSPC") return ENOSPC;
  if (name == "EIO") return EIO;
  if (name == "EDQUOT") return EDQUOT;
  return 0;
}

void write_count_at_exit() {
  Layer& l = layer();
  if (l.count_path.empty()) return;
  if (FILE* f = std::fopen(l.count_path.c_str(), "w")) {
    std::fprintf(f, "%lld\n", static_cast<long long>(l.calls));
    std::fclose(f);
  }
}

/// Reads the environment once. Called with the mutex held.
void configure(Layer& l) {
  if (l.configured) return;
  l.configured = true;
  if (const char* text = std::getenv("RDSF_IO_FAULT"); text != nullptr && *text != '\0') {
    // "N:ERR[:short][:once]"
    std::string spec(text);
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (start <= spec.size()) {
      const std::size_t colon = spec.find(':', start);
      parts.push_back(spec.substr(start, colon == std::string::npos ? std::string::npos : colon - start));
      if (colon == std::string::npos) break;
      start = colon + 1;
    }
    char* end = nullptr;
    l.fault.at_call = std::strtoll(parts[0].c_str(), &end, 10);
    l.fault.error = parts.size() > 1 ? parse_errno(parts[1]) : 0;
    if (l.fault.at_call <= 0 || *end != '\0' || l.fault.error == 0) {
      std::fprintf(stderr, "RDSF_IO_FAULT: '%s' is not N:ENOSPC|EIO|EDQUOT[:short][:once]; ignored\n", text);
      l.fault = Fault{};
    }
    for (std::size_t i = 2; i < parts.size(); ++i) {
      if (parts[i] == "short") l.fault.short_write = true;
      if (parts[i] == "once") l.fault.once = true;
    }
  }
  if (const char* path = std::getenv("RDSF_IO_RECORD"); path != nullptr && *path != '\0') {
    l.record_fd = ::open(path, O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  }
  if (const char* path = std::getenv("RDSF_IO_COUNT"); path != nullptr && *path != '\0') {
    l.count_path = path;
    std::atexit(write_count_at_exit);
  }
}

enum class Verdict { proceed, fail, short_write };

/// Counts a call and says whether it fails. Called with the mutex held.
Verdict count(Layer& l, Call call) {
  configure(l);
  const std::int64_t n = ++l.calls;
  const Fault& f = l.fault;
  if (f.at_call == 0 || n < f.at_call || (f.once && n > f.at_call)) return Verdict::proceed;
  if (n == f.at_call && f.short_write && call == Call::write) return Verdict::short_write;
  return Verdict::fail;
}

std::string absolute(const std::string& path) {
  if (path.empty()) return path;
  std::error_code ec;
  const std::filesystem::path p = std::filesystem::absolute(path, ec);
  return ec ? path : p.lexically_normal().string();
}

void put(std::string& out, const void* data, std::size_t size) { out.append(static_cast<const char*>(data), size); }

void put_text(std::string& out, std::string_view text) {
  const std::uint64_t size = text.size();
  put(out, &size, sizeof size);
  out.append(text.data(), text.size());
}

/// One record: u8 kind, i32 fd, i64 value (flags, size or offset), then path, second path and data, each as
/// u64 length + bytes. Called with the mutex held, only for calls that succeeded.
void record(Layer& l, Call call, int fd, std::int64_t value, const std::string& path = {},
            const std::string& path2 = {}, std::string_view data = {}) {
  if (l.record_fd < 0) return;
  std::string out;
  const std::uint8_t kind = static_cast<std::uint8_t>(call);
  put(out, &kind, 1);
  put(out, &fd, sizeof fd);
  put(out, &value, sizeof value);
  put_text(out, absolute(path));
  put_text(out, absolute(path2));
  put_text(out, data);
  std::size_t done = 0;
  while (done < out.size()) {
    const ssize_t n = ::write(l.record_fd, out.data() + done, out.size() - done);
    if (n <= 0 && errno != EINTR) break;
    if (n > 0) done += static_cast<std::size_t>(n);
  }
}

int failed(const Fault& f) {
  errno = f.error;
  return -1;
}

}  // namespace

const char* call_name(Call call) {
  switch (call) {
    case Call::open: return "open";
    case Call::write: return "write";
    case Call::fdatasync: return "fdatasync";
    case Call::fsync: return "fsync";
    case Call::rename: return "rename";
    case Call::link: return "link";
    case Call::unlink: return "unlink";
    case Call::mkdir: return "mkdir";
    case Call::truncate: return "truncate";
    case Call::close: return "close";
    case Call::syncfs: return "syncfs";
  }
  return "?";
}

void set_fault(const Fault& fault) {
  Layer& l = layer();
  std::lock_guard<std::mutex> lock(l.mutex);
  configure(l);
  l.fault = fault;
  l.calls = 0;
}

std::int64_t calls_made() {
  Layer& l = layer();
  std::lock_guard<std::mutex> lock(l.mutex);
  return l.calls;
}

int open(const std::string& path, int flags, int mode) {
  Layer& l = layer();
  std::lock_guard<std::mutex> lock(l.mutex);
  if (count(l, Call::open) == Verdict::fail) return failed(l.fault);
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC, mode);
  if (fd >= 0) record(l, Call::open, fd, flags, path);
  return fd;
}

long write(int fd, const void* data, std::size_t size) {
  Layer& l = layer();
  std::lock_guard<std::mutex> lock(l.mutex);
  const Verdict verdict = count(l, Call::write);
  if (verdict == Verdict::fail) return failed(l.fault);
  if (verdict == Verdict::short_write) {
    if (size < 2) return failed(l.fault);  // nothing to cut short
    size /= 2;
  }
  std::int64_t offset = 0;
  if (l.record_fd >= 0) {
    struct stat st {};
    const int flags = ::fcntl(fd, F_GETFL);
    offset = (flags >= 0 && (flags & O_APPEND) != 0 && ::fstat(fd, &st) == 0) ? st.st_size : ::lseek(fd, 0, SEEK_CUR);
  }
  const ssize_t n = ::write(fd, data, size);
  if (n > 0) record(l, Call::write, fd, offset, {}, {}, std::string_view(static_cast<const char*>(data), n));
  return n;
}

// The wrappers below share one shape: count the call (it may be made to fail), make it, and record it
// when it succeeded. `record_it(l)` records; `result` is what the system call returned (0 is success).
template <typename Make, typename Record>
int intercepted(Call call, Make make, Record record_it) {
  Layer& l = layer();
  std::lock_guard<std::mutex> lock(l.mutex);
  if (count(l, call) == Verdict::fail) return failed(l.fault);
  const int result = make();
  if (result == 0) record_it(l);
  return result;
}

int fdatasync(int fd) {
  return intercepted(Call::fdatasync, [&] { return ::fdatasync(fd); }, [&](Layer& l) { record(l, Call::fdatasync, fd, 0); });
}

int fsync(int fd) {
  return intercepted(Call::fsync, [&] { return ::fsync(fd); }, [&](Layer& l) { record(l, Call::fsync, fd, 0); });
}

int rename(const std::string& from, const std::string& to) {
  return intercepted(Call::rename, [&] { return ::rename(from.c_str(), to.c_str()); },
                     [&](Layer& l) { record(l, Call::rename, -1, 0, from, to); });
}

int link(const std::string& from, const std::string& to) {
  return intercepted(Call::link, [&] { return ::link(from.c_str(), to.c_str()); },
                     [&](Layer& l) { record(l, Call::link, -1, 0, from, to); });
}

int unlink(const std::string& path) {
  return intercepted(Call::unlink, [&] { return ::unlink(path.c_str()); },
                     [&](Layer& l) { record(l, Call::unlink, -1, 0, path); });
}

int mkdir(const std::string& path, int mode) {
  return intercepted(Call::mkdir, [&] { return ::mkdir(path.c_str(), static_cast<mode_t>(mode)); },
                     [&](Layer& l) { record(l, Call::mkdir, -1, 0, path); });
}

int ftruncate(int fd, std::uint64_t size) {
  return intercepted(Call::truncate, [&] { return ::ftruncate(fd, static_cast<off_t>(size)); },
                     [&](Layer& l) { record(l, Call::truncate, fd, static_cast<std::int64_t>(size)); });
}

int close(int fd) {
  Layer& l = layer();
  std::lock_guard<std::mutex> lock(l.mutex);
  const Verdict verdict = count(l, Call::close);
  const int result = ::close(fd);  // always released, even when the call is made to fail
  record(l, Call::close, fd, 0);
  if (verdict == Verdict::fail) return failed(l.fault);
  return result;
}

int syncfs(int fd) {
  return intercepted(Call::syncfs, [&] { return ::syncfs(fd); }, [&](Layer& l) { record(l, Call::syncfs, fd, 0); });
}

}  // namespace io

std::string errno_text(int error) { return std::strerror(error); }

void write_all(int fd, const void* data, std::size_t size, const std::string& path, const std::string& what) {
  const char* bytes = static_cast<const char*>(data);
  std::size_t written = 0;
  while (written < size) {
    const long n = io::write(fd, bytes + written, size - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail(path, what + ": " + errno_text(errno));
    if (n == 0) fail(path, what + ": no byte written (disk full?)");
    written += static_cast<std::size_t>(n);
  }
}

void sync_data(int fd, const std::string& path) {
  if (io::fdatasync(fd) != 0) fail(path, "cannot flush to disk: " + errno_text(errno));
}

std::string parent_folder(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

namespace {

/// Opens `dir`, flushes it (fsync of the folder, or syncfs of its file system) and closes it.
void flush_folder(const std::string& dir, bool whole_file_system) {
  const int fd = io::open(dir, O_RDONLY | O_DIRECTORY);
  if (fd < 0) fail(dir, "cannot open the folder to flush it to disk: " + errno_text(errno));
  if ((whole_file_system ? io::syncfs(fd) : io::fsync(fd)) != 0) {
    const int error = errno;
    io::close(fd);
    fail(dir, std::string(whole_file_system ? "cannot flush the file system to disk: "
                                            : "cannot flush the folder to disk: ") +
                  errno_text(error));
  }
  if (io::close(fd) != 0) fail(dir, "cannot close the folder after flushing it: " + errno_text(errno));
}

}  // namespace

void sync_folder(const std::string& dir) { flush_folder(dir, false); }

void sync_file_system(const std::string& dir) { flush_folder(dir, true); }

void create_folders_durably(const std::string& dir) {
  std::error_code ec;
  if (dir.empty() || std::filesystem::is_directory(dir, ec)) return;
  const std::string parent = parent_folder(dir);
  if (parent != dir) create_folders_durably(parent);
  if (io::mkdir(dir) != 0) {
    if (errno == EEXIST && std::filesystem::is_directory(dir, ec)) return;
    fail(dir, "cannot create the folder: " + errno_text(errno));
  }
  sync_folder(parent);
}

namespace {

/// Closes `fd` and removes `temporary` after a failure, keeping the first error.
void abandon(int fd, const std::string& temporary) {
  if (fd >= 0) io::close(fd);
  io::unlink(temporary);
}

/// Writes `bytes` into `fd`, just opened on `path` by the caller, fdatasyncs it (Sync::now) and closes
/// it; on any failure removes `path` and throws Error naming it.
void fill_and_close(int fd, const std::string& path, std::string_view bytes, Sync sync) {
  try {
    write_all(fd, bytes.data(), bytes.size(), path, "write failed");
    if (sync == Sync::now) sync_data(fd, path);
  } catch (...) {
    abandon(fd, path);
    throw;
  }
  if (io::close(fd) != 0) {
    const int error = errno;
    io::unlink(path);
    fail(path, "write failed on close: " + errno_text(error));
  }
}

}  // namespace

void write_synced(const std::string& path, std::string_view bytes, Sync sync) {
  const int fd = io::open(path, O_WRONLY | O_CREAT | O_TRUNC);
  if (fd < 0) fail(path, "cannot be created: " + errno_text(errno));
  fill_and_close(fd, path, bytes, sync);
}

void write_new_file_unsynced(const std::string& path, std::string_view bytes) {
  const int fd = io::open(path, O_WRONLY | O_CREAT | O_EXCL);
  if (fd < 0) {
    fail(path, errno == EEXIST ? std::string("already exists (never overwritten)")
                               : "cannot be created: " + errno_text(errno));
  }
  fill_and_close(fd, path, bytes, Sync::later);
}

void write_file_durably(const std::string& path, std::string_view bytes, Replace replace) {
  std::error_code ec;
  if (replace == Replace::never && std::filesystem::exists(path, ec)) fail(path, "already exists");
  const std::string temporary = path + ".tmp";
  write_synced(temporary, bytes);
  if (replace == Replace::never) {
    bool linked = false;
    try {
      linked = link_durably(temporary, path);
    } catch (...) {
      io::unlink(temporary);
      throw;
    }
    io::unlink(temporary);
    if (!linked) fail(path, "already exists");
    return;
  }
  if (io::rename(temporary, path) != 0) {
    const int error = errno;
    io::unlink(temporary);
    fail(path, "cannot rename " + temporary + " into place: " + errno_text(error));
  }
  sync_folder(parent_folder(path));
}

void write_file_durably(const std::string& path, const std::vector<unsigned char>& bytes, Replace replace) {
  write_file_durably(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), replace);
}

void sync_file(const std::string& path) {
  const int fd = io::open(path, O_RDONLY);
  if (fd < 0) fail(path, "cannot be opened to flush it to disk: " + errno_text(errno));
  if (io::fdatasync(fd) != 0) {
    const int error = errno;
    io::close(fd);
    fail(path, "cannot flush to disk: " + errno_text(error));
  }
  io::close(fd);
}

void rename_durably(const std::string& from, const std::string& to) {
  sync_file(from);
  if (io::rename(from, to) != 0) fail(to, "cannot rename " + from + " into place: " + errno_text(errno));
  sync_folder(parent_folder(to));
  if (parent_folder(from) != parent_folder(to)) sync_folder(parent_folder(from));
}

bool link_durably(const std::string& from, const std::string& to) {
  if (io::link(from, to) != 0) {
    if (errno == EEXIST) return false;
    fail(to, "cannot put " + from + " in place: " + errno_text(errno));
  }
  sync_folder(parent_folder(to));
  return true;
}

void remove_file(const std::string& path) {
  if (io::unlink(path) != 0 && errno != ENOENT) fail(path, "cannot remove: " + errno_text(errno));
}

void cut_file_durably(const std::string& path, std::uint64_t size) {
  const int fd = io::open(path, O_WRONLY);
  if (fd < 0) fail(path, "cannot be opened to cut off a torn end: " + errno_text(errno));
  if (io::ftruncate(fd, size) != 0 || io::fdatasync(fd) != 0) {
    const int error = errno;
    io::close(fd);
    fail(path, "cannot cut off the torn end left by an interrupted writer: " + errno_text(error));
  }
  io::close(fd);
}

AppendFile::AppendFile(std::string path, bool create) : path_(std::move(path)) {
  std::error_code ec;
  const bool existed = std::filesystem::exists(path_, ec);
  fd_ = io::open(path_, O_WRONLY | O_APPEND | (create ? O_CREAT : 0));
  if (fd_ < 0) fail(path_, "cannot be opened for appending: " + errno_text(errno));
  if (!existed) {
    try {
      sync_folder(parent_folder(path_));
    } catch (...) {
      close();
      throw;
    }
  }
}

AppendFile::~AppendFile() { close(); }

AppendFile::AppendFile(AppendFile&& other) noexcept : path_(std::move(other.path_)), fd_(std::exchange(other.fd_, -1)) {}

AppendFile& AppendFile::operator=(AppendFile&& other) noexcept {
  if (this != &other) {
    close();
    path_ = std::move(other.path_);
    fd_ = std::exchange(other.fd_, -1);
  }
  return *this;
}

void AppendFile::append(std::string_view bytes, bool sync_now) {
  if (fd_ < 0) fail(path_, "append after close");
  write_all(fd_, bytes.data(), bytes.size(), path_, "append failed");
  if (sync_now) sync();
}

void AppendFile::sync() {
  if (fd_ < 0) fail(path_, "sync after close");
  sync_data(fd_, path_);
}

void AppendFile::close() {
  if (fd_ >= 0) io::close(fd_);
  fd_ = -1;
}

}  // namespace rdsf
