// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace floodplane {

/// Traces the outer boundary of the region labelled `label` that contains pixel `start`,
/// which must be the region's first pixel in raster order (top row, leftmost), and appends
/// its pixels in order to `contour` (clockwise on screen, y pointing down; 8-connected; a
/// pixel on a one-pixel-wide neck appears twice). This is Moore-neighbour tracing with
/// Jacob's stopping criterion; its cost is the boundary's length, not the region's area.
void traceRegionBoundary(const std::uint32_t* labels, int width, int height, std::uint32_t label, std::size_t start,
                         std::vector<int>& contour);

}  // namespace floodplane
