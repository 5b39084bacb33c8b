// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Whether 3-D views can be drawn here. Debian 12's VTK 9.1 is built for X11 alone (no OSMesa,
// no EGL), so even its off-screen rendering needs an X display with OpenGL (GLX): a desktop's,
// or Xvfb's on a headless machine (xvfb-run). Without one VTK aborts the process, so the apps
// ask here first.

#include <optional>
#include <string>

namespace floodplane::view {

/// std::nullopt when an X display with the GLX extension can be opened; otherwise one line
/// saying what is missing and what to do (run under xvfb-run). The first connection that
/// passes stays open until the process ends, so that the X server does not reset (and refuse
/// connections) between the renderings of a batch. Not thread-safe.
std::optional<std::string> renderingUnavailableReason();

}  // namespace floodplane::view
