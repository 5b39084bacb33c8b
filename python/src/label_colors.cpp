// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "label_colors.h"

#include <pybind11/numpy.h>

#include <array>
#include <cstdint>

#include "floodplane/io/label_palette.h"

namespace floodplane::python {
namespace {

namespace py = pybind11;

// The colour of each of `labels` (1-D uint32): (N, 3) uint8. floodplane.label_colors calls it
// once per distinct label.
py::array_t<std::uint8_t> colorTable(
    const py::array_t<std::uint32_t, py::array::c_style | py::array::forcecast>& labels) {
  const auto count = static_cast<py::ssize_t>(labels.size());
  py::array_t<std::uint8_t> colors({count, py::ssize_t{3}});
  std::uint8_t* out = colors.mutable_data();
  const std::uint32_t* label = labels.data();
  for (py::ssize_t i = 0; i < count; ++i, out += 3) {
    const std::array<std::uint8_t, 3> rgb = io::labelColor(label[i]);
    out[0] = rgb[0];
    out[1] = rgb[1];
    out[2] = rgb[2];
  }
  return colors;
}

}  // namespace

void bindLabelColors(py::module_& m) {
  m.def("_label_color_table", &colorTable, py::arg("labels"), "The colour of each label: (N, 3) uint8.");
}

}  // namespace floodplane::python
