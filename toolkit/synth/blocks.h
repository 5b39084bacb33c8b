// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Polyhedral blocks of the kind in the SegComp structured-light images: boxes, wedges, roof
// and arch blocks whose top faces meet at shallow angles (10-30 degrees), chamfered boxes,
// many-sided prisms standing or lying, and cylinders. Sizes are for a block 1 m from a
// scanner (2-12 cm, faces down to 2 cm); `scale` enlarges them (blocks on a table in a room).

#include "synth/assembly.h"
#include "synth/random_source.h"

namespace floodplane::synth {

enum class BlockKind {
  box,
  wedge,           ///< a sloped block: a face rising at 10-30 degrees from the support
  roof,            ///< two roof faces at 10-30 degrees from the horizontal, meeting at a ridge
  arch,            ///< a top of 3-5 faces 2-5 cm wide, each turned 10-30 degrees from the last
  chamfered_box,   ///< a box with one top edge cut at 10-30 degrees from its top face
  standing_prism,  ///< an upright regular prism, 6-18 sides 2-5 cm wide
  lying_prism,     ///< a regular prism on one of its sides
  standing_cylinder,
  lying_cylinder,
};

/// Every kind, for picking one at random.
const std::vector<BlockKind>& allBlockKinds();

/// One block of `kind`, standing on z = 0 with its footprint centred on the origin.
Assembly makeBlock(BlockKind kind, double scale, RandomSource& random);

/// A prism whose cross-section `profile` ((y, z) points, counter-clockwise seen from +x) lies in
/// the plane x = -width / 2 and is swept along +x across `width`.
Prism profilePrism(const std::vector<Eigen::Vector2d>& profile, double width);

/// A prism standing on z = 0 with the (x, y) outline `outline` swept up by `height`.
Prism uprightPrism(const std::vector<Eigen::Vector2d>& outline, double height);

}  // namespace floodplane::synth
