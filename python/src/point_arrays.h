// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// numpy arrays in and out: an (H, W, 3) array as the core's PointGrid (in place when its
// memory already has the grid's layout), depth images as points, labels as uint32.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>
#include <vector>

#include "floodplane/point_grid.h"
#include "io/depth_camera.h"

namespace floodplane::python {

/// A PointGrid over a numpy array, and the array it reads (the caller's, or a float32 copy),
/// which must outlive the grid's use.
struct GridArray {
  pybind11::array array;
  PointGrid grid;
  bool copied = false;  ///< whether `array` is a converted copy of the caller's
};

/// `points` as a grid. Read in place when it is float32 in native byte order with x y z
/// adjacent and the points of a row evenly spaced, rows following each other (C order, or a
/// view such as cloud[..., :3] of a wider array); otherwise converted to a C-ordered float32
/// copy. Raises TypeError for anything but a float32 or float64 array, ValueError for a shape
/// other than (H, W, 3) with H >= 2 (an image grid) and W >= 1. `where` names the argument.
GridArray gridFromArray(pybind11::handle points, const std::string& where);

/// A C-ordered array of `shape` holding a copy of `values`.
template <typename T>
pybind11::array_t<T> arrayCopy(const std::vector<T>& values, std::vector<pybind11::ssize_t> shape);

/// A depth image (H, W) of any integer dtype as an (H, W, 3) float32 array of points
/// (io::backProjectPixel: zero is no return, NaN). Raises TypeError for a non-integer array,
/// ValueError for another shape or a negative depth.
pybind11::array_t<float> pointsFromDepth(pybind11::handle depth, const io::DepthCamera& camera,
                                         const std::string& where);

/// An integer array of `shape` (H, W) as uint32 values, row-major (labels, depth units up to
/// `max_value`). Raises TypeError for a non-integer array, ValueError for another shape or a
/// value outside [0, max_value].
std::vector<std::uint32_t> unsignedGrid(pybind11::handle values, pybind11::ssize_t height, pybind11::ssize_t width,
                                        std::uint64_t max_value, const std::string& where);

/// The shape of a numpy array as text, "(480, 640, 3)".
std::string shapeText(const pybind11::array& array);

}  // namespace floodplane::python
