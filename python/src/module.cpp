// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The compiled part of the floodplane package (imported as floodplane._floodplane; the
// package's __init__.py is the public face).

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "file_functions.h"
#include "floodplane/version.h"
#include "label_colors.h"
#include "params_kwargs.h"
#include "plane_classes_binding.h"
#include "segmentation_result.h"
#include "segmenter_binding.h"
#include "tracker_binding.h"

PYBIND11_MODULE(_floodplane, m) {
  m.doc() = "Plane segmentation of organized point clouds by seeded flood fill (compiled core).";
  m.attr("__version__") = FLOODPLANE_VERSION_STRING;
  m.attr("PARAMETER_NAMES") = pybind11::tuple(pybind11::cast(floodplane::python::parameterNames()));
  floodplane::python::bindSegmentationResult(m);
  floodplane::python::bindSegmenter(m);
  floodplane::python::bindTracker(m);
  floodplane::python::bindPlaneClasses(m);
  floodplane::python::bindFileFunctions(m);
  floodplane::python::bindLabelColors(m);
}
