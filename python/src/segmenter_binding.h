// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// floodplane.Segmenter: the core's Segmenter (its buffers kept between calls), segmenting
// numpy arrays and files without holding the GIL.

#include <pybind11/pybind11.h>

namespace floodplane::python {

void bindSegmenter(pybind11::module_& module);

}  // namespace floodplane::python
