#pragma once
// Durable file writing in one place, used by every writer of the workbench (sample sets, the labeler's
// journal, model files, recordings, synthetic sets, reports), and the I/O layer under it that tests can
// make fail or record.
//
// Rules (what survives a power cut, not only a killed program):
//   - a file that appears under its final name is written to a temporary name, fdatasync'ed, renamed (or
//     hard-linked, when an existing name must never be replaced) and then its folder is fsync'ed, so the
//     name never points at data that is not on disk;
//   - a folder that is created is fsync'ed in its parent;
//   - an appended record is fdatasync'ed before the program moves on (before it reports it as saved);
//   - a file cut to a size is fdatasync'ed after the cut.
// Every failure throws rdsf::Error with one line "<file>: <what> : <strerror>" naming the file and cause.
//
// The I/O layer (namespace io): every system call that changes files goes through it. Tests and the
// programs' fault tests control it through the environment, read once at the first call:
//   RDSF_IO_FAULT="N:ERR[:short][:once]"  call number N (from 1) fails with ERR (ENOSPC, EIO or EDQUOT), and
//                                         every later call too (a full disk stays full) unless ":once"; with
//                                         ":short" a write at call N writes half its bytes first (the next
//                                         call then fails).
//   RDSF_IO_RECORD=FILE                   appends a record of every call (kind, path, offset, bytes) to FILE,
//                                         for the power-cut simulation in tests (tests/support/crash_replay).
//   RDSF_IO_COUNT=FILE                    writes the number of calls made to FILE at exit.
// Both can also be set in-process with io::set_fault().
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rdsf {

namespace io {

/// The kinds of call the layer counts (and can fail). Recorded with these names.
enum class Call { open, write, fdatasync, fsync, rename, link, unlink, mkdir, truncate, close, syncfs };
const char* call_name(Call call);

struct Fault {
  std::int64_t at_call = 0;  ///< the first failing call (1-based); 0: no fault
  int error = 0;             ///< errno given (ENOSPC, EIO, EDQUOT)
  bool short_write = false;  ///< a write at `at_call` writes half its bytes before the failures start
  bool once = false;         ///< only call `at_call` fails (a passing EIO), not every later one
};

/// Replaces the fault read from RDSF_IO_FAULT (in-process tests).
void set_fault(const Fault& fault);
/// The number of calls made so far.
std::int64_t calls_made();

// The calls: as POSIX (return -1 and set errno on failure), counted and maybe failed or recorded.
int open(const std::string& path, int flags, int mode = 0644);
long write(int fd, const void* data, std::size_t size);
int fdatasync(int fd);
int fsync(int fd);
int rename(const std::string& from, const std::string& to);
int link(const std::string& from, const std::string& to);
int unlink(const std::string& path);
int mkdir(const std::string& path, int mode = 0755);
int ftruncate(int fd, std::uint64_t size);
int close(int fd);
/// syncfs(2): everything written to the file system that holds `fd`, data and names, reaches the disk.
int syncfs(int fd);

}  // namespace io

/// "<strerror(errno)>", e.g. "No space left on device".
std::string errno_text(int error);

/// Writes all bytes (retrying short writes and EINTR); throws Error "<path>: <what>: <cause>".
void write_all(int fd, const void* data, std::size_t size, const std::string& path, const std::string& what);
/// fdatasync; throws Error naming `path`.
void sync_data(int fd, const std::string& path);
/// fsync of a folder, so that names created, renamed or removed in it are on disk.
void sync_folder(const std::string& dir);
/// syncfs of the file system that holds `dir`: every file and name written so far is on disk (one call for
/// a batch of files instead of one fdatasync each).
void sync_file_system(const std::string& dir);
/// The folder that holds `path` ("." for a bare name).
std::string parent_folder(const std::string& path);

/// Creates `dir` and any missing parents, each fsync'ed in its parent; nothing when it exists.
void create_folders_durably(const std::string& dir);

/// Whether a write is flushed to disk before it returns, or by the caller later (one syncfs for a batch).
enum class Sync { now, later };
/// Creates (or truncates) `path`, writes `bytes`, fdatasyncs (Sync::now) and closes it; removes it on
/// failure. The name itself is not made durable (a temporary file: see write_file_durably).
void write_synced(const std::string& path, std::string_view bytes, Sync sync = Sync::now);
/// Creates `path`, which must not exist (Error "already exists": nothing is overwritten), writes `bytes`
/// and closes it, syncing neither: the caller makes the file and its name durable later (sync_file or
/// sync_file_system, then sync_folder). No temporary name and no rename (half the cost of a small file on
/// ext4): a failed write removes the file, but a killed process can leave it partial under its own name,
/// so callers publish it only after it is complete (a sample set's row comes after its crops, and a crop
/// without a row is removed when the set is opened).
void write_new_file_unsynced(const std::string& path, std::string_view bytes);

enum class Replace { allowed, never };
/// Writes `bytes` to `path` durably (temporary "<path>.tmp", fdatasync, rename or link, folder fsync).
/// With Replace::never an existing `path` is left alone and Error "already exists" thrown. The temporary
/// file is removed on failure when possible.
void write_file_durably(const std::string& path, std::string_view bytes, Replace replace = Replace::allowed);
void write_file_durably(const std::string& path, const std::vector<unsigned char>& bytes,
                        Replace replace = Replace::allowed);
/// fdatasync of the file named `path` (written earlier, closed since).
void sync_file(const std::string& path);
/// Moves a finished file `from` to `to` (same folder or file system) durably: fdatasync of `from`, rename,
/// fsync of the folder(s). For files written by someone else (the OpenNI recorder).
void rename_durably(const std::string& from, const std::string& to);
/// Hard-links `from` to `to` (never replacing; returns false when `to` exists), then fsyncs the folder.
bool link_durably(const std::string& from, const std::string& to);
/// Removes `path` (nothing when absent); throws Error on other failures. The folder is fsync'ed by
/// sync_folder() when the caller needs the removal to be durable.
void remove_file(const std::string& path);
/// Cuts `path` to `size` bytes and fdatasyncs it.
void cut_file_durably(const std::string& path, std::uint64_t size);

/// A file open for durable appends (O_APPEND): each append() is one write, synced unless asked not to.
class AppendFile {
 public:
  AppendFile() = default;
  /// Opens (creating it when `create`, fsync'ing the folder when it was created); throws Error.
  AppendFile(std::string path, bool create);
  ~AppendFile();
  AppendFile(AppendFile&& other) noexcept;
  AppendFile& operator=(AppendFile&& other) noexcept;
  AppendFile(const AppendFile&) = delete;
  AppendFile& operator=(const AppendFile&) = delete;

  bool is_open() const { return fd_ >= 0; }
  const std::string& path() const { return path_; }
  /// Appends the bytes in one write (retried when short) and fdatasyncs unless `sync` is false.
  void append(std::string_view bytes, bool sync = true);
  void sync();
  void close();

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace rdsf
