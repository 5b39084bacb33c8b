// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "objects/surface_patches.h"
#include "util/union_find.h"

namespace floodplane {

/// LCCP's convexity test (Stein et al., "Object partitioning using local convexity", CVPR
/// 2014): two touching patches are parts of one convex surface when the line between their
/// centroids is convex with respect to their normals, (n_a - n_b) . (c_a - c_b) > 0 with the
/// normals towards the sensor, or when their normals are within `concavity_tolerance_rad` of
/// each other (a flat or gently curved surface under noise). False when either has no normal.
bool convexContact(const SurfacePatch& a, const SurfacePatch& b, double concavity_tolerance_rad);

/// Joins, in `objects` (reset to the patches' count), the patches of each contact that passes
/// convexContact; a patch with no normal (too few points to span a plane) joins the patch it
/// shares the most pixel pairs with.
void joinConvexPatches(const SurfacePatches& patches, double concavity_tolerance_rad, UnionFind& objects);

}  // namespace floodplane
