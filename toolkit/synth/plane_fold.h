// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Folding ground-truth planes into one: the faces of one continuous flat surface become one
// plane, in a frame (renderer.cpp: faces that touch in the image) and over a sequence
// (sequence_labels.cpp: faces that touched in any frame).

#include <cstdint>

#include "synth/rendered_frame.h"

namespace floodplane::synth {

/// Folds every plane whose `root(id)` is another plane into that one: its `merged_into` names
/// the root, its pixel count moves there and its pixels take the root's label. `root` maps a
/// label to the smallest id of its group (0 to 0). Returns whether any plane was folded; the
/// labels are rewritten only then.
template <typename Root>
bool foldPlanes(RenderedFrame& frame, Root&& root) {
  bool folded = false;
  for (GroundTruthPlane& plane : frame.planes) {
    const std::uint32_t group = root(plane.id);
    if (group == plane.id) continue;
    plane.merged_into = group;
    frame.planes[group - 1].pixel_count += plane.pixel_count;
    plane.pixel_count = 0;
    folded = true;
  }
  if (!folded) return false;
  for (std::uint32_t& label : frame.labels) label = root(label);
  return true;
}

}  // namespace floodplane::synth
