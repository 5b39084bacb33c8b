// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The side-by-side picture of one scene, ground truth | ransac | omps | floodplane: as label
// images (--png) or rendered in 3-D from the oblique camera of view/plane_view.h (--png3d).

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "floodplane/io/rgb_image.h"
#include "input_cloud.h"

namespace pcd_compare {

/// A panel's title and a method's labels (row-major, 0 = no plane).
using LabelledPanel = std::pair<std::string, std::vector<std::uint32_t>>;

/// The ground truth, when `input` has it, then `panels`, side by side, each as large as the
/// cloud's grid with its title in a strip above (drawn by cairo in a sans font). Segments are
/// coloured by the ground-truth plane they overlap most (floodplane::io::labelColor), pixels
/// without a point white (floodplane::io::labelImage). In 3-D
/// (`in_3d`) the segments of at least `min_points` points get an arrow along their
/// least-squares normal. Throws std::invalid_argument if there is no panel, std::runtime_error
/// if cairo cannot draw the titles or, in 3-D, when nothing can be rendered here (no X
/// display: run under xvfb-run).
floodplane::io::RgbImage comparisonImage(const InputCloud& input, const std::vector<LabelledPanel>& panels,
                                         std::size_t min_points, bool in_3d);

}  // namespace pcd_compare
