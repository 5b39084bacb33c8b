// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/sequence_labels.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "synth/plane_fold.h"

namespace floodplane::synth {

std::uint32_t SequenceSurfaces::root(std::uint32_t id) const {
  if (id >= parent_.size()) return id;
  while (parent_[id] != id) id = parent_[id];
  return id;
}

void SequenceSurfaces::add(const RenderedFrame& frame) {
  if (parent_.size() < frame.planes.size() + 1) {
    const auto old_size = static_cast<std::uint32_t>(parent_.size());
    parent_.resize(frame.planes.size() + 1);
    for (std::uint32_t id = old_size; id < parent_.size(); ++id) parent_[id] = id;
  }
  for (const GroundTruthPlane& plane : frame.planes) {
    if (plane.merged_into == 0) continue;
    const std::uint32_t a = root(plane.id);
    const std::uint32_t b = root(plane.merged_into);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }
}

bool SequenceSurfaces::changes(const RenderedFrame& frame) const {
  return std::any_of(frame.planes.begin(), frame.planes.end(), [&](const GroundTruthPlane& plane) {
    const std::uint32_t label = plane.merged_into == 0 ? plane.id : plane.merged_into;
    return root(label) != label;
  });
}

void SequenceSurfaces::relabel(RenderedFrame& frame) const {
  if (!parent_.empty() && frame.planes.size() + 1 != parent_.size()) {
    throw std::invalid_argument("SequenceSurfaces::relabel: the frame has " + std::to_string(frame.planes.size()) +
                                " planes, the sequence " + std::to_string(parent_.size() - 1));
  }
  foldPlanes(frame, [this](std::uint32_t id) { return root(id); });
}

}  // namespace floodplane::synth
