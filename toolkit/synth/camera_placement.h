// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Checking a generated camera pose: what a small preview render through the scene's camera
// shows, and how far the camera is from every surface. The scene generators draw poses until
// one meets their requirements, so no generated scene looks at nothing, is mostly empty or
// has a surface at the lens.

#include "synth/scene.h"

namespace floodplane::synth {

struct ViewRequirements {
  int preview_width = 80;  ///< the preview render's size (same field of view as the scene)
  int preview_height = 60;
  double min_coverage = 0.9;  ///< fraction of preview pixels that hit a surface
  int min_planes = 5;         ///< planes with at least min_plane_fraction of the pixels
  double min_plane_fraction = 0.005;
  double max_plane_fraction = 0.6;  ///< no plane may cover more of the pixels (a bare wall)
  double min_centre_depth = 0.5;    ///< the centre pixel must hit a surface this far ...
  double max_centre_depth = 6.0;    ///< ... and no farther (metres)
  double min_clearance = 0.5;       ///< no surface nearer to the camera centre (metres)
  double max_clearance = 6.0;       ///< the nearest surface no farther (metres)
};

struct ViewSummary {
  double coverage = 0.0;
  int planes = 0;              ///< planes with at least min_plane_fraction of the pixels
  double largest_plane = 0.0;  ///< the fraction of the pixels of the largest plane
  double centre_depth = 0.0;   ///< depth at the centre pixel; infinity for no hit
  double clearance = 0.0;      ///< distance from the camera centre to the nearest surface
  bool inside_solid = false;   ///< the camera centre is inside a solid
};

/// Renders the preview (exact sensor) and measures the camera's clearance. A camera inside a
/// solid is reported, not rendered.
ViewSummary summarizeView(const Scene& scene, const ViewRequirements& requirements);

bool meetsRequirements(const ViewSummary& summary, const ViewRequirements& requirements);

}  // namespace floodplane::synth
