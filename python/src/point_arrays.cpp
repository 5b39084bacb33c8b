// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "point_arrays.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <type_traits>

#include "errors.h"

namespace floodplane::python {
namespace {

namespace py = pybind11;

bool isNativeFloat32(const py::array& array) { return array.dtype().equal(py::dtype::of<float>()); }

// Whether the core can read `array`, float32 (H, W, 3), where it lies: coordinates adjacent,
// points a whole number of floats apart, rows one after the other, aligned.
bool hasGridLayout(const py::array& array) {
  const py::ssize_t f = static_cast<py::ssize_t>(sizeof(float));
  const py::ssize_t point_step = array.strides(1);
  const auto address = reinterpret_cast<std::uintptr_t>(array.data());
  return array.strides(2) == f && point_step >= 3 * f && point_step % f == 0 &&
         array.strides(0) == point_step * array.shape(1) && address % alignof(float) == 0;
}

void checkGridShape(const py::array& array, const std::string& where) {
  if (array.ndim() != 3 || array.shape(2) != 3) {
    raiseValueError(where + " must have shape (H, W, 3), got " + shapeText(array));
  }
  if (array.shape(0) < 2 || array.shape(1) < 1) {
    raiseValueError(where + " must be an image grid of H >= 2 rows and W >= 1 columns, got " + shapeText(array));
  }
  if (array.shape(0) > INT_MAX || array.shape(1) > INT_MAX || array.shape(0) * array.shape(1) > INT_MAX) {
    raiseValueError(where + " has too many points: " + shapeText(array));
  }
}

void checkIntegerDtype(const py::array& array, const std::string& where) {
  const char kind = array.dtype().kind();
  if (kind != 'u' && kind != 'i') {
    raiseTypeError(where + " must be an integer array, got dtype " + std::string(py::str(array.dtype())));
  }
}

// Calls `visit(value, index)` for every element of a 2-D integer array (row-major index),
// whatever its integer dtype, strides and byte order.
template <typename Visit>
void forEachInteger(const py::array& array, Visit&& visit) {
  const py::array native = array.dtype().attr("isnative").cast<bool>()
                               ? array
                               : py::array(array.attr("astype")(array.dtype().attr("newbyteorder")("=")));
  const auto run = [&](auto tag) {
    using T = decltype(tag);
    const auto view = native.unchecked<T, 2>();
    py::ssize_t index = 0;
    for (py::ssize_t r = 0; r < view.shape(0); ++r) {
      for (py::ssize_t c = 0; c < view.shape(1); ++c, ++index) visit(view(r, c), r, c, index);
    }
  };
  const char kind = native.dtype().kind();
  switch (native.itemsize() * (kind == 'u' ? 1 : -1)) {
    case 1:
      return run(std::uint8_t{});
    case 2:
      return run(std::uint16_t{});
    case 4:
      return run(std::uint32_t{});
    case 8:
      return run(std::uint64_t{});
    case -1:
      return run(std::int8_t{});
    case -2:
      return run(std::int16_t{});
    case -4:
      return run(std::int32_t{});
    case -8:
      return run(std::int64_t{});
    default:
      raiseTypeError("unsupported integer dtype " + std::string(py::str(native.dtype())));
  }
}

// Calls `visit(value, row, column, index)` for every element of a 2-D floating-point array,
// float32 and float64 as they are, other widths (float16, long double) as float64.
template <typename Visit>
void forEachReal(const py::array& array, Visit&& visit) {
  const bool native = array.dtype().attr("isnative").cast<bool>();
  const std::size_t size = static_cast<std::size_t>(array.itemsize());
  const auto run = [&](auto tag) {
    using T = decltype(tag);
    const py::array values = native && size == sizeof(T) ? array : py::array(array.attr("astype")(py::dtype::of<T>()));
    const auto view = values.unchecked<T, 2>();
    py::ssize_t index = 0;
    for (py::ssize_t r = 0; r < view.shape(0); ++r) {
      for (py::ssize_t c = 0; c < view.shape(1); ++c, ++index) visit(view(r, c), r, c, index);
    }
  };
  if (size == sizeof(float)) return run(float{});
  return run(double{});
}

template <typename T>
std::string positionText(T value, py::ssize_t row, py::ssize_t column) {
  std::string text;
  if constexpr (std::is_floating_point_v<T>) {
    char number[32];
    std::snprintf(number, sizeof(number), "%g", static_cast<double>(value));
    text = number;
  } else {
    text = std::to_string(value);
  }
  return text + " at row " + std::to_string(row) + ", column " + std::to_string(column);
}

// Whether the point is exactly (0, 0, 0) (-0.0 too), the "no depth" of Open3D and RealSense.
bool isZeroPoint(const float* p) { return p[0] == 0.0f && p[1] == 0.0f && p[2] == 0.0f; }

// Points at (0, 0, 0) become NaN: in `grid`'s own copy when it has one, otherwise in a new
// copy, made only when there is such a point (a frame without any is read in place still).
void makeZeroPointsHoles(GridArray& grid) {
  const std::size_t count = static_cast<std::size_t>(grid.grid.width) * static_cast<std::size_t>(grid.grid.height);
  std::size_t first = 0;
  while (first < count && !isZeroPoint(grid.grid.point(first))) ++first;
  if (first == count) return;
  if (!grid.copied) {
    py::array_t<float> copy({grid.array.shape(0), grid.array.shape(1), py::ssize_t{3}});
    float* out = copy.mutable_data();
    for (std::size_t i = 0; i < count; ++i, out += 3) std::copy_n(grid.grid.point(i), 3, out);
    grid.array = copy;
    grid.copied = true;
    grid.grid.data = copy.data();
    grid.grid.stride = 3;
  }
  float* data = static_cast<float*>(grid.array.mutable_data());
  const std::size_t stride = grid.grid.stride;
  for (std::size_t i = first; i < count; ++i) {
    float* p = data + i * stride;
    if (isZeroPoint(p)) p[0] = p[1] = p[2] = std::numeric_limits<float>::quiet_NaN();
  }
}

}  // namespace

std::string shapeText(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) {
    text += (d ? ", " : "") + std::to_string(array.shape(d));
  }
  return text + (array.ndim() == 1 ? ",)" : ")");
}

py::array arrayFrom(py::handle value, const std::string& where, const std::string& wanted) {
  if (value.is_none() || py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value)) {
    raiseTypeError(where + " must be " + wanted + ", got " + typeName(value));
  }
  if (py::isinstance<py::array>(value)) return py::reinterpret_borrow<py::array>(value);
  try {
    return py::module_::import("numpy").attr("asarray")(value);
  } catch (py::error_already_set& numpy_error) {
    const std::string reason = py::str(numpy_error.value());
    const std::string message = where + " must be " + wanted + "; numpy cannot make an array of this " +
                                typeName(value) + (reason.empty() ? "" : ": " + reason);
    if (numpy_error.matches(PyExc_ValueError)) raiseValueError(message);
    raiseTypeError(message);
  }
}

GridArray gridFromArray(py::handle points, const std::string& where, bool zero_is_hole) {
  GridArray out;
  out.array = arrayFrom(points, where, "an array of shape (H, W, 3)");
  const char kind = out.array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    raiseTypeError(where + " must hold real numbers (floats or integers), got dtype " +
                   std::string(py::str(out.array.dtype())));
  }
  checkGridShape(out.array, where);
  if (!isNativeFloat32(out.array) || !hasGridLayout(out.array)) {
    // astype copies always (ensure() would hand back an unaligned C-ordered array itself).
    out.array = py::array(out.array.attr("astype")("float32", py::arg("order") = "C"));
    out.copied = true;
  }
  out.grid.data = static_cast<const float*>(out.array.data());
  out.grid.stride = static_cast<std::size_t>(out.array.strides(1)) / sizeof(float);
  out.grid.width = static_cast<int>(out.array.shape(1));
  out.grid.height = static_cast<int>(out.array.shape(0));
  if (zero_is_hole) makeZeroPointsHoles(out);
  return out;
}

template <typename T>
py::array_t<T> arrayCopy(const std::vector<T>& values, std::vector<py::ssize_t> shape) {
  py::array_t<T> array(shape);
  std::copy(values.begin(), values.end(), array.mutable_data());
  return array;
}
template py::array_t<float> arrayCopy(const std::vector<float>&, std::vector<py::ssize_t>);
template py::array_t<std::uint16_t> arrayCopy(const std::vector<std::uint16_t>&, std::vector<py::ssize_t>);
template py::array_t<std::uint32_t> arrayCopy(const std::vector<std::uint32_t>&, std::vector<py::ssize_t>);

DepthArray depthArrayFrom(py::handle depth, const std::string& where) {
  DepthArray out;
  out.array = arrayFrom(depth, where, "an array of shape (H, W)");
  const char kind = out.array.dtype().kind();
  if (kind != 'u' && kind != 'i' && kind != 'f') {
    raiseTypeError(where + " must be an integer or floating-point array, got dtype " +
                   std::string(py::str(out.array.dtype())));
  }
  out.real = kind == 'f';
  if (out.array.ndim() == 3 && out.array.shape(2) == 1) out.array = py::array(out.array.attr("squeeze")(2));
  if (out.array.ndim() != 2)
    raiseValueError(where + " must have shape (H, W) or (H, W, 1), got " + shapeText(out.array));
  if (out.array.shape(0) > INT_MAX || out.array.shape(1) > INT_MAX)
    raiseValueError(where + " is too large: " + shapeText(out.array));
  return out;
}

double defaultDepthScale(const DepthArray& depth) { return depth.real ? 1.0 : 1000.0; }

py::array_t<float> pointsFromDepth(const DepthArray& depth, const io::DepthCamera& camera, const std::string& where) {
  const py::array& array = depth.array;
  py::array_t<float> points({array.shape(0), array.shape(1), py::ssize_t{3}});
  float* xyz = points.mutable_data();
  const auto project = [&](double units, py::ssize_t row, py::ssize_t column, py::ssize_t index) {
    io::backProjectPixel(static_cast<int>(column), static_cast<int>(row), units, camera, xyz + 3 * index);
  };
  if (depth.real) {
    forEachReal(array, [&](auto value, py::ssize_t row, py::ssize_t column, py::ssize_t index) {
      // NaN and infinity are "no reading" in Open3D's and ROS's float images, as 0 is.
      const double units = std::isfinite(value) ? static_cast<double>(value) : 0.0;
      if (units < 0.0) raiseValueError(where + " must not be negative, got " + positionText(value, row, column));
      project(units, row, column, index);
    });
    return points;
  }
  forEachInteger(array, [&](auto value, py::ssize_t row, py::ssize_t column, py::ssize_t index) {
    if constexpr (std::is_signed_v<decltype(value)>) {
      if (value < 0) raiseValueError(where + " must not be negative, got " + positionText(value, row, column));
    }
    project(static_cast<double>(value), row, column, index);
  });
  return points;
}

std::vector<std::uint32_t> unsignedGrid(py::handle values, py::ssize_t height, py::ssize_t width,
                                        std::uint64_t max_value, const std::string& where) {
  const py::array array = arrayFrom(values, where, "an integer array of shape (H, W)");
  checkIntegerDtype(array, where);
  if (array.ndim() != 2 || array.shape(0) != height || array.shape(1) != width) {
    raiseValueError(where + " must have shape (" + std::to_string(height) + ", " + std::to_string(width) + "), got " +
                    shapeText(array));
  }
  std::vector<std::uint32_t> out(static_cast<std::size_t>(height * width));
  forEachInteger(array, [&](auto value, py::ssize_t row, py::ssize_t column, py::ssize_t index) {
    bool fits = true;
    if constexpr (std::is_signed_v<decltype(value)>) fits = value >= 0;
    if (fits) fits = static_cast<std::uint64_t>(value) <= max_value;
    if (!fits) {
      raiseValueError(where + " must hold values in [0, " + std::to_string(max_value) + "], got " +
                      positionText(value, row, column));
    }
    out[static_cast<std::size_t>(index)] = static_cast<std::uint32_t>(value);
  });
  return out;
}

}  // namespace floodplane::python
