// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "camera_intrinsics.h"

#include <pybind11/numpy.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>

#include "errors.h"
#include "params_kwargs.h"
#include "point_arrays.h"

namespace floodplane::python {
namespace {

namespace py = pybind11;

const char* const kForms =
    "fx, fy, cx, cy (four numbers or one sequence of them), a 3 x 3 matrix K (or its 9 values), or an object "
    "with intrinsic_matrix (Open3D's PinholeCameraIntrinsic)";

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", value);
  return text;
}

// A real-valued numpy array of `value`; TypeError for anything else.
py::array_t<double> realArray(py::handle value, const std::string& where) {
  if (value.is_none() || py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value)) {
    raiseTypeError(where + " must be " + kForms + ", got " + typeName(value));
  }
  py::array array = py::array::ensure(value);
  if (!array) {
    PyErr_Clear();
    raiseTypeError(where + " must be " + kForms + ", got " + typeName(value));
  }
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    raiseTypeError(where + " must hold real numbers, got dtype " + std::string(py::str(array.dtype())));
  }
  auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!values) throw py::error_already_set();
  return values;
}

// K = [[fx, 0, cx], [0, fy, cy], [0, 0, 1]]; the back-projection has no skew term, so a K
// with one would give wrong points without a word.
Intrinsics fromMatrix(const py::array_t<double>& matrix, const std::string& where) {
  const auto k = matrix.unchecked<2>();
  const bool pinhole = k(0, 1) == 0.0 && k(1, 0) == 0.0 && k(2, 0) == 0.0 && k(2, 1) == 0.0 && k(2, 2) == 1.0;
  if (!pinhole) {
    std::string rows;
    for (py::ssize_t r = 0; r < 3; ++r) {
      rows += r ? ", [" : "[";
      for (py::ssize_t c = 0; c < 3; ++c) rows += (c ? ", " : "") + number(k(r, c));
      rows += "]";
    }
    raiseValueError(where + " must be a pinhole camera matrix [[fx, 0, cx], [0, fy, cy], [0, 0, 1]] (no skew), got [" +
                    rows + "]");
  }
  Intrinsics out;
  out.fx = k(0, 0);
  out.fy = k(1, 1);
  out.cx = k(0, 2);
  out.cy = k(1, 2);
  return out;
}

// Open3D's width and height, or nothing when the object has none (or -1, its "unset").
std::optional<int> imageExtent(py::handle object, const char* name, const std::string& where) {
  if (!py::hasattr(object, name)) return std::nullopt;
  const py::object value = object.attr(name);
  if (value.is_none()) return std::nullopt;
  const long long extent = toInteger(value, where + "." + name, LLONG_MIN, LLONG_MAX);
  if (extent <= 0) return std::nullopt;
  if (extent > INT_MAX) raiseValueError(where + "." + name + " is too large: " + std::to_string(extent));
  return static_cast<int>(extent);
}

}  // namespace

io::DepthCamera Intrinsics::camera(double depth_scale, const std::string& function) const {
  const io::DepthCamera out{fx, fy, cx, cy, depth_scale};
  const std::string problem = out.problem();
  if (!problem.empty()) raiseValueError(function + ": " + problem);
  return out;
}

void Intrinsics::checkImageSize(long long image_width, long long image_height, const std::string& function) const {
  if (!width || !height) return;
  if (*width != image_width || *height != image_height) {
    raiseValueError(function + ": the intrinsics are for a " + std::to_string(*width) + " x " +
                    std::to_string(*height) + " image, the depth image is " + std::to_string(image_width) + " x " +
                    std::to_string(image_height) + " (width x height)");
  }
}

Intrinsics intrinsicsFrom(py::handle intrinsics, py::handle fy, py::handle cx, py::handle cy,
                          const std::string& function) {
  const int loose = !fy.is_none() + !cx.is_none() + !cy.is_none();
  if (loose == 0) return intrinsicsFrom(intrinsics, function);
  if (loose != 3) {
    raiseTypeError(function + ": give the intrinsics as fx, fy, cx, cy (all four), or as one argument: " + kForms);
  }
  Intrinsics out;
  out.fx = toDouble(intrinsics, function + ": fx");
  out.fy = toDouble(fy, function + ": fy");
  out.cx = toDouble(cx, function + ": cx");
  out.cy = toDouble(cy, function + ": cy");
  return out;
}

Intrinsics intrinsicsFrom(py::handle intrinsics, const std::string& function) {
  const std::string where = function + ": intrinsics";
  if (!intrinsics.is_none() && py::hasattr(intrinsics, "intrinsic_matrix")) {
    const py::array_t<double> matrix = realArray(intrinsics.attr("intrinsic_matrix"), where + ".intrinsic_matrix");
    if (matrix.ndim() != 2 || matrix.shape(0) != 3 || matrix.shape(1) != 3) {
      raiseValueError(where + ".intrinsic_matrix must have shape (3, 3), got " + shapeText(matrix));
    }
    Intrinsics out = fromMatrix(matrix, where + ".intrinsic_matrix");
    out.width = imageExtent(intrinsics, "width", where);
    out.height = imageExtent(intrinsics, "height", where);
    if (!out.width || !out.height) out.width = out.height = std::nullopt;
    return out;
  }
  const py::array_t<double> values = realArray(intrinsics, where);
  if (values.ndim() == 0) {
    raiseTypeError(where + " must be " + kForms + ", got the single number " + number(values.at()));
  }
  if (values.ndim() == 2 && values.shape(0) == 3 && values.shape(1) == 3) return fromMatrix(values, where);
  if (values.ndim() != 1) {
    raiseValueError(where + " must be (fx, fy, cx, cy) or a 3 x 3 matrix K, got shape " + shapeText(values));
  }
  // K's nine values row by row: ROS's CameraInfo.k (K in ROS 1).
  if (values.shape(0) == 9) {
    py::array_t<double> matrix({py::ssize_t{3}, py::ssize_t{3}});
    std::copy_n(values.data(), 9, matrix.mutable_data());
    return fromMatrix(matrix, where);
  }
  if (values.shape(0) != 4) {
    raiseValueError(where + " must be (fx, fy, cx, cy) or the 9 values of K, got " + std::to_string(values.shape(0)) +
                    " values");
  }
  Intrinsics out;
  out.fx = values.at(0);
  out.fy = values.at(1);
  out.cx = values.at(2);
  out.cy = values.at(3);
  return out;
}

}  // namespace floodplane::python
