// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "floodplane/point_grid.h"
#include "frame/hole_filling.h"
#include "models/plane_candidates.h"

namespace floodplane {

/// Refinement, the counterpart of OMPS's (segmentAndRefine): grows each plane into adjacent
/// unlabelled pixels that fit it, breadth first, with the flood's test (Eqs. 1-3) under the
/// plane's own thresholds. These are pixels a flood could not reach through noise, and pixels
/// of segments too small to report. An unlabelled pixel next to several planes goes to the one
/// it fits best. The planes' sums and first pixels follow.
///
/// The labels are the planes' image (`planes` on `full`), in whatever numbers it was written.
/// `queue` is scratch space. Pixels `holes` filled in are never labelled.
void refinePlanes(const PointGrid& full, const HoleFilling& holes, PlaneCandidates& planes,
                  std::vector<std::size_t>& queue);

}  // namespace floodplane
