#pragma once
// The comparison in 3-D (--png3d): the panels of comparisonImage, each rendered from the
// oblique camera of common/plane_view.h with an arrow per segment's normal.

#include <cstddef>
#include <vector>

#include "comparison_image.h"
#include "io/rgb_image.h"
#include "method.h"

namespace pcd_compare {

/// The panels side by side, each rendered as large as the cloud's grid with its title above;
/// segments (Panel::segment_labels, or the colour labels) of at least `min_points` points
/// get an arrow along their least-squares normal. Throws std::runtime_error when nothing can
/// be rendered here (no X display: run under xvfb-run).
floodplane::io::RgbImage comparisonImage3d(const std::vector<Panel>& panels, const Cloud::ConstPtr& cloud,
                                           std::size_t min_points);

}  // namespace pcd_compare
