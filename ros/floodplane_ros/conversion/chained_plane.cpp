// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "chained_plane.h"

#include <limits>
#include <stdexcept>
#include <string>

namespace floodplane::conversion {

std::vector<std::int32_t> planeIndices(const Segmentation& segmentation, std::size_t plane) {
  if (plane >= segmentation.planes.size()) {
    throw std::invalid_argument("planeIndices: plane " + std::to_string(plane) + " of " +
                                std::to_string(segmentation.planes.size()));
  }
  if (segmentation.labels.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
    throw std::invalid_argument("planeIndices: " + std::to_string(segmentation.labels.size()) +
                                " pixels, more than int32 indices reach");
  }
  const auto label = static_cast<std::uint32_t>(plane + 1);
  std::vector<std::int32_t> indices;
  indices.reserve(segmentation.planes[plane].inlier_count);
  for (std::size_t i = 0; i < segmentation.labels.size(); ++i) {
    if (segmentation.labels[i] == label) indices.push_back(static_cast<std::int32_t>(i));
  }
  return indices;
}

ChainedPlane chainedPlane(const Segmentation& segmentation) {
  ChainedPlane chained;
  if (segmentation.planes.empty()) return chained;
  const std::size_t plane = 0;  // the largest
  chained.indices = planeIndices(segmentation, plane);
  const PlaneFit& fit = segmentation.planes[plane].fit;
  chained.coefficients = {static_cast<float>(fit.normal.x()), static_cast<float>(fit.normal.y()),
                          static_cast<float>(fit.normal.z()), static_cast<float>(fit.offset)};
  return chained;
}

}  // namespace floodplane::conversion
