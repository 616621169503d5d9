#include "gui/display.hpp"

#include <cstdlib>
#include <string>

#include "rdsf/core/error.hpp"

namespace rdsf::gui {

void require_display(const std::string& program_name, const std::string& hint) {
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  const char* platform = std::getenv("QT_QPA_PLATFORM");
  const bool offscreen = platform != nullptr && std::string(platform).find("offscreen") != std::string::npos;
  if ((display == nullptr || *display == '\0') && (wayland == nullptr || *wayland == '\0') && !offscreen) {
    throw Error(program_name + ": no display to open a window on (DISPLAY is not set); " + hint);
  }
}

}  // namespace rdsf::gui
