#include "core/atomic_file.hpp"

#include <filesystem>

#include "core/error.hpp"

namespace rdsf {

AtomicTextFile::AtomicTextFile(std::string path, bool overwrite)
    : path_(std::move(path)), partial_(path_ + ".partial") {
  std::error_code ec;
  if (!overwrite && std::filesystem::exists(path_, ec)) {
    fail(path_, "already exists (pass --force to replace it)");
  }
  out_.open(partial_, std::ios::out | std::ios::trunc);
  if (!out_) fail(partial_, "cannot be created");
}

AtomicTextFile::~AtomicTextFile() = default;

void AtomicTextFile::flush() {
  out_.flush();
  if (!out_) fail(partial_, "write failed (disk full?)");
}

void AtomicTextFile::commit() {
  if (committed_) return;
  flush();
  out_.close();
  std::error_code ec;
  std::filesystem::rename(partial_, path_, ec);
  if (ec) fail(path_, "cannot rename " + partial_ + " into place: " + ec.message());
  committed_ = true;
}

}  // namespace rdsf
