// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cmath>
#include <cstddef>

/// \file
/// floodplane::PointGrid, the organized points the core reads in place.

namespace floodplane {

/// A read-only view of an organized cloud: width x height points, row-major, whose x y z are
/// three consecutive floats every `stride` floats, in metres, with the sensor at the origin.
/// A pcl::PointCloud<PointXYZ...> is such a grid in place (x y z lead every PCL point type),
/// so the core reads the caller's memory without a copy. Points whose coordinates are not
/// finite are holes (no return).
struct PointGrid {
  const float* data = nullptr;  ///< x of the first point (the top left pixel); not owned
  std::size_t stride = 3;       ///< floats from one point to the next (PCL's point types: 4 or more)
  int width = 0;                ///< points per row
  int height = 0;               ///< rows

  /// \return the number of points, width x height
  std::size_t size() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
  /// The x y z of one point.
  /// \param index row-major, v * width + u
  /// \return its x; y and z follow
  const float* point(std::size_t index) const { return data + index * stride; }
  /// Whether a point has finite x, y and z (a return, not a hole).
  /// \param index row-major, v * width + u
  /// \return false for a hole
  bool isFinite(std::size_t index) const {
    const float* p = point(index);
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
  }
};

}  // namespace floodplane
