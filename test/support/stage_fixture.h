// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the stage tests share (refinement, occlusion merging, region output, plane merging):
// the paper's fixed thresholds on exact data, labels drawn as string art, one string per row
// ('.' no plane, a digit the plane's number), and the planes of such a labelling on a pinhole
// grid as region output hands them over, each with the sums, first pixel and flood criterion
// of its labelled pixels.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "floodplane/params.h"
#include "models/plane_candidates.h"
#include "models/tolerances.h"
#include "support/pinhole_grid.h"

namespace floodplane::test {

/// A depth of no return, for the grids' depth functions.
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// The angle between neighbouring rays of a PinholeGrid, as the stages take it [rad].
inline constexpr float kPinholePitch = static_cast<float>(1.0 / kPinholeFocal);

/// The paper's fixed thresholds (sigma_plane 1 cm, sigma_plane-merge 3 cm), for exact data (no
/// depth noise).
inline Params exactParams() {
  Params params;
  params.distance_threshold = 0.01;
  params.merge_distance = 0.03;
  params.depth_noise_coefficient = 0.0;
  return params;
}

/// A label per pixel, row by row, from string art: '.' is 0, a digit its number.
inline std::vector<std::uint32_t> labelsFromArt(const std::vector<std::string>& art) {
  std::vector<std::uint32_t> labels;
  for (const std::string& row : art)
    for (const char c : row) labels.push_back(c == '.' ? 0u : static_cast<std::uint32_t>(c - '0'));
  return labels;
}

/// The planes of `labels` on `grid`, with `labels` as their image: plane k (1..K) has the sums
/// and the first pixel of the pixels labelled k, and the criterion of its fit under
/// `tolerances`. K is the largest label.
inline PlaneCandidates planesOfLabels(const PinholeGrid& grid, const std::vector<std::uint32_t>& labels,
                                      const Tolerances& tolerances) {
  PlaneCandidates planes;
  planes.list().resize(labels.empty() ? 0u : *std::max_element(labels.begin(), labels.end()));
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const std::uint32_t k = labels[i];
    if (k == 0) continue;
    PlaneCandidate& plane = planes[k];
    plane.sums.add(grid.point(i));
    plane.first_pixel = std::min(plane.first_pixel, i);
  }
  for (PlaneCandidate& plane : planes.list())
    plane.criterion = planeCriterion(plane.sums.fit(), tolerances, kPinholePitch);
  std::copy(labels.begin(), labels.end(), planes.newImage(grid.width, grid.height));
  return planes;
}

}  // namespace floodplane::test
