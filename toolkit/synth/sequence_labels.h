// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// One surface, one ground-truth id over a sequence of frames. The renderer gives coplanar faces
// that touch in a frame's image the label of the smallest id among them (one continuous flat
// surface is one plane; see mergeTouchingCoplanarFaces in renderer.cpp), but whether they touch
// in the image depends on the view: a shelf board's front flush with the side panels' fronts
// may be hidden behind a box in one frame and not in the next. Over a sequence, faces merged in
// any frame are one surface in every frame, so its id does not change with the view.

#include <cstdint>
#include <vector>

#include "synth/rendered_frame.h"

namespace floodplane::synth {

class SequenceSurfaces {
 public:
  /// Records the merges of a rendered frame of the sequence (its planes' merged_into).
  void add(const RenderedFrame& frame);

  /// Whether relabel() would change `frame`: some label it carries is merged into a smaller id
  /// by the frames added so far.
  bool changes(const RenderedFrame& frame) const;

  /// Gives every face merged with others in any frame added so far the smallest id of its
  /// group: the labels, the planes' merged_into and their pixel counts (moved to the group's
  /// plane). Throws std::invalid_argument for a frame of another scene (other plane count).
  void relabel(RenderedFrame& frame) const;

 private:
  std::uint32_t root(std::uint32_t id) const;

  std::vector<std::uint32_t> parent_;  // union-find over plane ids; index 0 is label 0
};

}  // namespace floodplane::synth
