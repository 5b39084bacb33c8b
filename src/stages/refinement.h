// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "floodplane/point_grid.h"
#include "stages/hole_filling.h"
#include "stages/plane_candidates.h"

namespace floodplane {

/// Refinement, the counterpart of OMPS's (segmentAndRefine): grows each plane into adjacent
/// unlabelled pixels that fit it, breadth first, with the flood's test (Eqs. 1-3) under the
/// plane's own thresholds. These are pixels a flood could not reach through noise, and pixels
/// of segments too small to report. An unlabelled pixel next to several planes goes to the one
/// it fits best. The planes' sums and first pixels follow.
///
/// With `renumber_first`, the labels are first renumbered by `planes.remap()` in the same pass,
/// one row ahead of the scan (which reads the rows above and below the pixel it looks at).
/// `queue` is scratch space.
/// Pixels `holes` filled in are never labelled.
void refinePlanes(const PointGrid& full, const HoleFilling& holes, std::vector<std::uint32_t>& labels,
                  PlaneCandidates& planes, bool renumber_first, std::vector<std::size_t>& queue);

}  // namespace floodplane
