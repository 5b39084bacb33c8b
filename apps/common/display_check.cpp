#include "common/display_check.h"

// Xlib's macros (None, Bool, Status, ...) clash with VTK's and PCL's names: Xlib stays in
// this file.
#include <X11/Xlib.h>

#include <cstdlib>

namespace floodplane::view {
namespace {

constexpr const char* kHint =
    "; VTK here draws through X11 only: on a machine without a screen run under xvfb-run -a "
    "(Debian package xvfb)";

}  // namespace

std::optional<std::string> renderingUnavailableReason() {
  const char* name = std::getenv("DISPLAY");
  if (name == nullptr || *name == '\0') return std::string("no X display (DISPLAY is not set)") + kHint;
  Display* display = XOpenDisplay(nullptr);
  if (display == nullptr) return "cannot open the X display '" + std::string(name) + "'" + kHint;
  int opcode = 0, first_event = 0, first_error = 0;
  const bool has_glx = XQueryExtension(display, "GLX", &opcode, &first_event, &first_error) != 0;
  XCloseDisplay(display);
  if (!has_glx) return "the X display '" + std::string(name) + "' has no OpenGL (GLX extension)" + kHint;
  return std::nullopt;
}

}  // namespace floodplane::view
