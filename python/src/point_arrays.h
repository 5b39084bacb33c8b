// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// numpy arrays in and out: an (H, W, 3) array as the core's PointGrid (in place when its
// memory already has the grid's layout, points at (0, 0, 0) made holes in a copy), depth
// images of integer units or of real numbers as points, labels as uint32.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>
#include <vector>

#include "floodplane/io/depth_camera.h"
#include "floodplane/point_grid.h"

namespace floodplane::python {

/// A PointGrid over a numpy array, and the array it reads (the caller's, or a float32 copy),
/// which must outlive the grid's use.
struct GridArray {
  pybind11::array array;
  PointGrid grid;
  bool copied = false;  ///< whether `array` is a converted copy of the caller's
};

/// `value` as numpy.asarray makes it an array (lists and tuples of numbers, arrays of any
/// dtype). Raises TypeError for None and text ("<where> must be <wanted>, got str") and for
/// what numpy takes for no array, ValueError with numpy's reason for what it cannot make an
/// array of (a ragged list).
pybind11::array arrayFrom(pybind11::handle value, const std::string& where, const std::string& wanted);

/// `points`, anything numpy.asarray makes an array of real numbers of (an array of any float
/// or integer dtype, nested lists or tuples of numbers), as a grid. Read in place when it is
/// float32 in native byte order with x y z adjacent and the points of a row evenly spaced,
/// rows following each other (C order, or a view such as cloud[..., :3] of a wider array);
/// otherwise converted to a C-ordered float32 copy. With `zero_is_hole`, points at exactly
/// (0, 0, 0), the "no depth" of Open3D, RealSense and many ROS drivers, become NaN (no return,
/// as the core knows holes) in a copy; the caller's array is never written. Raises TypeError
/// for None, text and arrays of other dtypes (bool, complex, strings, objects), ValueError for
/// what numpy cannot make an array of (a ragged list) and for a shape other than (H, W, 3)
/// with H >= 2 (an image grid) and W >= 1. `where` names the argument.
GridArray gridFromArray(pybind11::handle points, const std::string& where, bool zero_is_hole = false);

/// A C-ordered array of `shape` holding a copy of `values`.
template <typename T>
pybind11::array_t<T> arrayCopy(const std::vector<T>& values, std::vector<pybind11::ssize_t> shape);

/// A depth image: (H, W) values, of an integer dtype (sensor units: Kinect and RealSense
/// millimetres, ROS 16UC1) or a real one (Open3D's float images, ROS 32FC1: metres).
struct DepthArray {
  pybind11::array array;  ///< (H, W); an (H, W, 1) input seen without its last axis
  bool real = false;      ///< a floating-point dtype
};

/// `depth`, anything numpy.asarray makes an array of integers or floats of, as a DepthArray.
/// Raises TypeError for an array neither integer nor real (bool, complex) or no array,
/// ValueError for what numpy cannot make an array of and for a shape other than (H, W) or
/// (H, W, 1).
DepthArray depthArrayFrom(pybind11::handle depth, const std::string& where);

/// The units per metre of a depth image when not given: 1 (metres) for real depths, 1000
/// (millimetres) for integer ones.
double defaultDepthScale(const DepthArray& depth);

/// The depth image as an (H, W, 3) float32 array of points (io::backProjectPixel). No return,
/// NaN, where the depth is 0, and for real depths also where it is NaN or infinite. Raises
/// ValueError for a negative depth.
pybind11::array_t<float> pointsFromDepth(const DepthArray& depth, const io::DepthCamera& camera,
                                         const std::string& where);

/// An integer array of `shape` (H, W) as uint32 values, row-major (labels, depth units up to
/// `max_value`). Raises TypeError for a non-integer array, ValueError for another shape or a
/// value outside [0, max_value].
std::vector<std::uint32_t> unsignedGrid(pybind11::handle values, pybind11::ssize_t height, pybind11::ssize_t width,
                                        std::uint64_t max_value, const std::string& where);

/// The shape of a numpy array as text, "(480, 640, 3)".
std::string shapeText(const pybind11::array& array);

}  // namespace floodplane::python
