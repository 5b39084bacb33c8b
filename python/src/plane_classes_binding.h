// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// floodplane.describe_planes: the core's describePlanes over a Segmentation or a list of its
// Planes (floor, ceiling, wall, horizontal surface or other, and the height above the floor);
// floodplane.PlaneDescription: what it says of one plane.

#include <pybind11/pybind11.h>

namespace floodplane::python {

void bindPlaneClasses(pybind11::module_& module);

}  // namespace floodplane::python
