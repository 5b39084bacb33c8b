// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// floodplane.Tracker: the core's PlaneTracker over Segmentation results, giving planes ids that
// persist from frame to frame; floodplane.Track: one of its tracks.

#include <pybind11/pybind11.h>

namespace floodplane::python {

void bindTracker(pybind11::module_& module);

}  // namespace floodplane::python
