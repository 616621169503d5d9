#pragma once
// rdsf-record's work: record depth (and registered colour) from a live OpenNI2 device into an .oni file
// with OpenNI2's own recorder, lossless, showing progress, until N frames or Ctrl-C.
#include <cstdint>
#include <string>

namespace rdsf::recorder {

struct RecordOptions {
  std::string out;                 ///< the .oni file to write
  std::string device = "openni";   ///< "openni" (first device), a device URI, or "rdsf-png://<folder>"
  std::int64_t frames = 0;         ///< stop after this many frames of every recorded stream (counted by the
                                   ///< device's frame index; a live device may add the frame that arrives
                                   ///< while the recorder stops); 0: until Ctrl-C
  bool colour = false;             ///< record the colour stream too (registered to depth when supported)
  bool depth = true;               ///< record the depth stream (off only to make test files)
  bool force = false;              ///< replace an existing --out file
  int timeout_ms = 2000;           ///< longest wait for a frame before the device counts as gone
};

/// Checks the options together, before anything is opened, in this order: --frames >= 0, --timeout-ms >= 1
/// (cli::UsageError, exit 2), --out ending in .oni (rdsf::Error, exit 1), not --no-depth without --colour
/// (cli::UsageError). Call once, before run_record.
void check_options(const RecordOptions& options);

/// Records; returns the exit code. Throws rdsf::Error (one line) on a bad device or file. The file is
/// written under a temporary name and renamed when the recorder has finished it, also after Ctrl-C or a
/// device that stops sending: what was recorded then stays playable.
int run_record(const RecordOptions& options);

}  // namespace rdsf::recorder
