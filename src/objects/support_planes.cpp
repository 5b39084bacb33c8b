// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "objects/support_planes.h"

#include <algorithm>
#include <cmath>

namespace floodplane {

double coveredArea(const PlaneFit& fit) {
  const double product = std::max(0.0, fit.eigenvalues[1]) * std::max(0.0, fit.eigenvalues[2]);
  return 12.0 * std::sqrt(product);
}

Supports findSupports(const std::vector<SegmentedPlane>& planes, const ObjectOptions& options) {
  Supports supports;
  supports.is_support.assign(planes.size() + 1, false);
  // planes are largest first (by pixels); the area decides, so that a near box face with many
  // pixels is no support while a far table with fewer is.
  for (std::size_t k = 0; k < planes.size(); ++k) {
    const PlaneFit& fit = planes[k].fit;
    if (!fit.valid || !fit.normal.allFinite() || coveredArea(fit) < options.min_support_area_m2) continue;
    SupportSurface surface;
    surface.label = static_cast<std::uint32_t>(k + 1);
    surface.normal = fit.normal.normalized();
    surface.offset = -surface.normal.dot(fit.centroid);
    supports.surfaces.push_back(surface);
    supports.is_support[k + 1] = true;
  }
  const double cos_piece = std::cos(options.support_piece_angle_rad);
  for (std::size_t k = 0; k < planes.size(); ++k) {
    if (supports.is_support[k + 1]) continue;
    const PlaneFit& fit = planes[k].fit;
    if (!fit.valid || !fit.normal.allFinite() || !fit.centroid.allFinite()) continue;
    for (const SupportSurface& surface : supports.surfaces) {
      if (fit.normal.normalized().dot(surface.normal) >= cos_piece &&
          std::abs(surface.height(fit.centroid)) <= options.support_piece_distance_m) {
        supports.is_support[k + 1] = true;
        break;
      }
    }
  }
  return supports;
}

}  // namespace floodplane
