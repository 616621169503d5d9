#pragma once
// A text file that appears under its final name only when complete and on disk: written to
// "<path>.partial" through the I/O layer of core/durable_io, flushed as it goes (so a killed program leaves
// everything but the last line behind, under .partial), and by commit() fdatasync'ed, renamed into place
// and its folder fsync'ed (durable across a power cut). Refuses to replace an existing file unless asked to.
#include <memory>
#include <ostream>
#include <string>

namespace rdsf {

class AtomicTextFile {
 public:
  /// Opens "<path>.partial". Throws Error when `path` exists and `overwrite` is false, or when the file
  /// cannot be created.
  AtomicTextFile(std::string path, bool overwrite);
  ~AtomicTextFile();  // without commit(), the .partial file stays for inspection
  AtomicTextFile(const AtomicTextFile&) = delete;
  AtomicTextFile& operator=(const AtomicTextFile&) = delete;

  std::ostream& stream();
  /// Hands what was written to the operating system; throws Error naming the file and the cause when a
  /// write failed (disk full, I/O error).
  void flush();
  /// Flushes, fdatasyncs, closes, renames into place and fsyncs the folder; throws Error on any failure
  /// (the final name is then untouched).
  void commit();
  const std::string& path() const { return path_; }

 private:
  class Buffer;
  std::string path_;
  std::string partial_;
  std::unique_ptr<Buffer> buffer_;
  std::unique_ptr<std::ostream> out_;
  bool committed_ = false;
};

}  // namespace rdsf
