// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The result of one segmentation as Python sees it: a copy of the core's Segmentation (which
// the Segmenter overwrites on its next call), its labels as a read-only numpy view, its planes
// as objects.

#include <pybind11/pybind11.h>

#include <memory>

#include "floodplane/object_segmentation.h"
#include "floodplane/segmenter.h"

namespace floodplane::python {

struct SegmentationResult {
  std::shared_ptr<const Segmentation> segmentation;
  double ms = 0.0;  ///< wall time of the core's segment call
  /// The objects on the planes, when asked for (segment(..., objects=True)); null otherwise.
  std::shared_ptr<const ObjectSegmentation> objects;
};

/// One plane: the core's SegmentedPlane and its label (its index + 1).
struct PlaneResult {
  SegmentedPlane plane;
  std::uint32_t label = 0;
};

/// Registers Segmentation, Plane, Object, NoiseModel, PhaseTimes and SegmentationStats.
void bindSegmentationResult(pybind11::module_& module);

}  // namespace floodplane::python
