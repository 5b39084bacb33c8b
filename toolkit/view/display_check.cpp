// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "view/display_check.h"

// Xlib's macros (None, Bool, Status, ...) clash with VTK's and PCL's names: Xlib stays in
// this file.
#include <X11/Xlib.h>

#include <cstdlib>

namespace floodplane::view {
namespace {

constexpr const char* kHint =
    "; VTK here draws through X11 only: on a machine without a screen run under xvfb-run -a "
    "(Debian package xvfb)";

// The connection of the first successful check, kept open until the process ends. An X
// server resets when its last client disconnects, and refuses connections meanwhile: Xvfb
// under xvfb-run would do so between two renderings of a batch (each VTK window has a
// connection of its own), and the next one would fail, or VTK abort.
struct HeldDisplay {
  Display* display = nullptr;
  ~HeldDisplay() {
    if (display != nullptr) XCloseDisplay(display);
  }
};

}  // namespace

std::optional<std::string> renderingUnavailableReason() {
  static HeldDisplay held;
  if (held.display != nullptr) return std::nullopt;
  const char* name = std::getenv("DISPLAY");
  if (name == nullptr || *name == '\0') return std::string("no X display (DISPLAY is not set)") + kHint;
  Display* display = XOpenDisplay(nullptr);
  if (display == nullptr) return "cannot open the X display '" + std::string(name) + "'" + kHint;
  int opcode = 0, first_event = 0, first_error = 0;
  if (XQueryExtension(display, "GLX", &opcode, &first_event, &first_error) == 0) {
    XCloseDisplay(display);
    return "the X display '" + std::string(name) + "' has no OpenGL (GLX extension)" + kHint;
  }
  held.display = display;
  return std::nullopt;
}

}  // namespace floodplane::view
