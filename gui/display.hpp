#pragma once
// The programs' window helpers (highgui lives here and in the programs, never in src/).
#include <string>

namespace rdsf::gui {

/// Throws rdsf::Error with a clear message (and `hint`) when no display is available, instead of letting
/// Qt abort the process.
void require_display(const std::string& program_name, const std::string& hint);

}  // namespace rdsf::gui
