// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "point_arrays.h"

#include <climits>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "errors.h"

namespace floodplane::python {
namespace {

namespace py = pybind11;

// Any array-like as a numpy array; TypeError for what numpy cannot take.
py::array asArray(py::handle value, const std::string& where, const std::string& wanted) {
  if (!py::isinstance<py::array>(value)) {
    if (value.is_none() || py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value)) {
      raiseTypeError(where + " must be " + wanted + ", got " + typeName(value));
    }
  }
  py::array array = py::array::ensure(value);
  if (!array) {
    PyErr_Clear();
    raiseTypeError(where + " must be " + wanted + ", got " + typeName(value));
  }
  return array;
}

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

template <typename T>
std::string positionText(T value, py::ssize_t row, py::ssize_t column) {
  return std::to_string(value) + " at row " + std::to_string(row) + ", column " + std::to_string(column);
}

}  // namespace

std::string shapeText(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) {
    text += (d ? ", " : "") + std::to_string(array.shape(d));
  }
  return text + (array.ndim() == 1 ? ",)" : ")");
}

GridArray gridFromArray(py::handle points, const std::string& where) {
  GridArray out;
  out.array = asArray(points, where, "a float32 or float64 array of shape (H, W, 3)");
  const char kind = out.array.dtype().kind();
  if (kind != 'f' || (out.array.itemsize() != 4 && out.array.itemsize() != 8)) {
    raiseTypeError(where + " must be a float32 or float64 array, got dtype " + std::string(py::str(out.array.dtype())));
  }
  checkGridShape(out.array, where);
  if (!isNativeFloat32(out.array) || !hasGridLayout(out.array)) {
    out.array = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(out.array);
    if (!out.array) throw py::error_already_set();
    out.copied = true;
  }
  out.grid.data = static_cast<const float*>(out.array.data());
  out.grid.stride = static_cast<std::size_t>(out.array.strides(1)) / sizeof(float);
  out.grid.width = static_cast<int>(out.array.shape(1));
  out.grid.height = static_cast<int>(out.array.shape(0));
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

py::array_t<float> pointsFromDepth(py::handle depth, const io::DepthCamera& camera, const std::string& where) {
  const py::array array = asArray(depth, where, "an integer array of shape (H, W)");
  checkIntegerDtype(array, where);
  if (array.ndim() != 2) raiseValueError(where + " must have shape (H, W), got " + shapeText(array));
  if (array.shape(0) > INT_MAX || array.shape(1) > INT_MAX)
    raiseValueError(where + " is too large: " + shapeText(array));
  py::array_t<float> points({array.shape(0), array.shape(1), py::ssize_t{3}});
  float* xyz = points.mutable_data();
  forEachInteger(array, [&](auto value, py::ssize_t row, py::ssize_t column, py::ssize_t index) {
    if constexpr (std::is_signed_v<decltype(value)>) {
      if (value < 0) raiseValueError(where + " must not be negative, got " + positionText(value, row, column));
    }
    io::backProjectPixel(static_cast<int>(column), static_cast<int>(row), static_cast<double>(value), camera,
                         xyz + 3 * index);
  });
  return points;
}

std::vector<std::uint32_t> unsignedGrid(py::handle values, py::ssize_t height, py::ssize_t width,
                                        std::uint64_t max_value, const std::string& where) {
  const py::array array = asArray(values, where, "an integer array of shape (H, W)");
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
