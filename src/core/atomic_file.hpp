#pragma once
// A text file that appears under its final name only when complete: written to "<path>.partial", flushed
// as it goes (so a killed program leaves everything but the last line behind, under .partial), renamed
// into place by commit(). Refuses to replace an existing file unless asked to.
#include <fstream>
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

  std::ofstream& stream() { return out_; }
  /// Flushes to the operating system; throws Error when a write failed.
  void flush();
  /// Flushes, closes and renames into place.
  void commit();
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::string partial_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace rdsf
