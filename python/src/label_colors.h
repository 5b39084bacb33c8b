// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The label colours of pcd_segment's PNG files (io::labelColor), for Python's pictures and
// the Open3D bridge, so that a plane has one colour wherever it is shown.

#include <pybind11/pybind11.h>

namespace floodplane::python {

void bindLabelColors(pybind11::module_& module);

}  // namespace floodplane::python
