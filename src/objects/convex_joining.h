// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>

#include "objects/surface_patches.h"
#include "util/union_find.h"

namespace floodplane {

/// LCCP's convexity test (Stein et al., "Object partitioning using local convexity", CVPR
/// 2014): two touching patches are parts of one convex surface when the line between their
/// centroids is convex with respect to their normals, (n_a - n_b) . (c_a - c_b) > 0 with the
/// normals towards the sensor, and does not run along the line where their planes meet (LCCP's
/// sanity criterion). Normals within `concavity_tolerance_rad` of each other are one surface
/// (flat or gently curved, under noise) when the line between the centroids runs along it
/// within that angle, not two parallel surfaces at a step. False when either has no normal.
bool convexContact(const SurfacePatch& a, const SurfacePatch& b, double concavity_tolerance_rad);

/// Joins, in `objects` (reset to the patches' count): the touching patches of one plane; two
/// patches on
/// no plane whose contact passes convexContact; two planes, or a plane and a patch on none,
/// when more of the pixel pairs where they touch are in convex contacts than in concave ones
/// (the test is local, patch by patch, along their border). A patch with no normal (too few
/// points to span a plane, or a strip too narrow) joins the patch it shares the most pixel
/// pairs with; the patches with normals around such a patch (a strip along a crease the
/// planes left out) are judged as touching across it (one patch wide: judging across longer
/// chains pits far patches against each other).
void joinConvexPatches(const SurfacePatches& patches, double concavity_tolerance_rad, UnionFind& objects);

/// Joins each group of `objects` smaller than `min_pixels` (a fringe the convexity test cut
/// off: an edge's mixed pixels, a handle's end) to the group of at least `min_pixels` it
/// shares the most pixel pairs with, whatever their convexity; one that touches none stays.
void absorbFragments(const SurfacePatches& patches, std::uint32_t min_pixels, UnionFind& objects);

}  // namespace floodplane
