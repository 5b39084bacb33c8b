// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The results as pickle states (tuples of plain numbers and one label array), so that they
// cross process boundaries: Dask, multiprocessing, a file. Each state starts with a format
// number; a state of another format, or one whose parts do not fit together (labels of
// another size, a plane's first pixel outside the image), raises ValueError instead of
// making a result that the methods would read out of bounds.

#include <pybind11/pybind11.h>

#include "floodplane/plane_tracker.h"
#include "floodplane/segmenter.h"
#include "segmentation_result.h"

namespace floodplane::python {

pybind11::tuple noiseState(const NoiseModel& noise);
NoiseModel noiseFromState(const pybind11::tuple& state);

pybind11::tuple phasesState(const PhaseTimes& phases);
PhaseTimes phasesFromState(const pybind11::tuple& state);

pybind11::tuple statsState(const SegmentationStats& stats);
SegmentationStats statsFromState(const pybind11::tuple& state);

pybind11::tuple planeState(const PlaneResult& plane);
PlaneResult planeFromState(const pybind11::tuple& state);

pybind11::tuple segmentationState(const SegmentationResult& result);
SegmentationResult segmentationFromState(const pybind11::tuple& state);

/// The objects of a segmentation: (format, labels (H, W), supports, objects as tuples of id,
/// pixels, centroid, min, max, support). objectsFromState checks the labels against the
/// segmentation's size and the ids against the objects.
pybind11::tuple objectsState(const ObjectSegmentation& objects);
ObjectSegmentation objectsFromState(const pybind11::tuple& state, int width, int height);

pybind11::tuple trackState(const PlaneTrack& track);
PlaneTrack trackFromState(const pybind11::tuple& state);

}  // namespace floodplane::python
