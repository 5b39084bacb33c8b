// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The module's file functions (PCD and depth PNG in and out) and the depth back-projection.

#include <pybind11/pybind11.h>

namespace floodplane::python {

void bindFileFunctions(pybind11::module_& module);

}  // namespace floodplane::python
