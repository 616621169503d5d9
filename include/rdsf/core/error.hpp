#pragma once
// The project's one error type. Everything the library throws for bad input is an rdsf::Error whose
// message is a single line that names the file (or device) and the problem, e.g.
//   "frames/0001.depth.png: 8-bit image given as depth (expected 16-bit single-channel PNG in millimetres)".
// Programs catch it at the top of main(), print it and exit non-zero.
#include <stdexcept>
#include <string>

namespace rdsf {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A file or folder the caller asked to write already holds something that is only replaced when the
/// caller says so (the programs' --force). Library messages name no command-line option: the programs
/// add how to replace it (cli::run).
class AlreadyExists : public Error {
 public:
  using Error::Error;
};

/// Throws Error("<where>: <what>").
[[noreturn]] void fail(const std::string& where, const std::string& what);

}  // namespace rdsf
