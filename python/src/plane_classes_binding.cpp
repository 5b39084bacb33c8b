// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "plane_classes_binding.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "decimal_text.h"
#include "errors.h"
#include "floodplane/plane_classes.h"
#include "params_kwargs.h"
#include "point_arrays.h"
#include "segmentation_result.h"

namespace floodplane::python {
namespace {

namespace py = pybind11;

constexpr const char* kFunction = "describe_planes";

// The planes of a Segmentation, or of a sequence of Plane objects.
std::vector<SegmentedPlane> planesFrom(py::handle planes) {
  const std::string wanted = "a floodplane.Segmentation or a list of its Plane objects";
  if (py::isinstance<SegmentationResult>(planes)) return planes.cast<const SegmentationResult&>().segmentation->planes;
  // An array is a sequence too, but never of planes: most likely the frame's points.
  if (py::isinstance<py::str>(planes) || py::isinstance<py::bytes>(planes) || py::isinstance<py::array>(planes) ||
      !py::isinstance<py::sequence>(planes))
    raiseTypeError(std::string(kFunction) + ": planes must be " + wanted + ", got " + typeName(planes));
  std::vector<SegmentedPlane> result;
  std::size_t index = 0;
  for (const py::handle item : planes.cast<py::sequence>()) {
    if (!py::isinstance<PlaneResult>(item)) {
      raiseTypeError(std::string(kFunction) + ": planes[" + std::to_string(index) +
                     "] must be a floodplane.Plane, got " + typeName(item));
    }
    result.push_back(item.cast<const PlaneResult&>().plane);
    ++index;
  }
  return result;
}

// Three real numbers, from anything numpy.asarray makes an array of them.
Eigen::Vector3d upFrom(py::handle up) {
  const std::string where = std::string(kFunction) + ": up";
  const std::string wanted = "three numbers x, y, z (the up direction in the planes' frame)";
  const py::array array = arrayFrom(up, where, wanted);
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    raiseTypeError(where + " must be " + wanted + ", got dtype " + std::string(py::str(array.dtype())));
  if (array.ndim() != 1 || array.shape(0) != 3)
    raiseValueError(where + " must have shape (3,), got " + shapeText(array));
  const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!values) throw py::error_already_set();
  return {values.at(0), values.at(1), values.at(2)};
}

// The options are keywords of their own (as PlaneClassOptions names them), taken as any
// object so that toDouble refuses bool and text with the option's name.
std::vector<PlaneDescription> describe(py::handle planes, py::handle up, py::handle horizontal_tolerance_rad,
                                       py::handle vertical_tolerance_rad, py::handle min_floor_area_m2,
                                       py::handle floor_height_tolerance_m, py::handle min_ceiling_area_m2,
                                       py::handle min_ceiling_height_m) {
  const std::vector<SegmentedPlane> segmented = planesFrom(planes);
  const Eigen::Vector3d direction = upFrom(up);
  const std::string where = std::string(kFunction) + ": ";
  PlaneClassOptions chosen;
  chosen.horizontal_tolerance_rad = toDouble(horizontal_tolerance_rad, where + "horizontal_tolerance_rad");
  chosen.vertical_tolerance_rad = toDouble(vertical_tolerance_rad, where + "vertical_tolerance_rad");
  chosen.min_floor_area_m2 = toDouble(min_floor_area_m2, where + "min_floor_area_m2");
  chosen.floor_height_tolerance_m = toDouble(floor_height_tolerance_m, where + "floor_height_tolerance_m");
  chosen.min_ceiling_area_m2 = toDouble(min_ceiling_area_m2, where + "min_ceiling_area_m2");
  chosen.min_ceiling_height_m = toDouble(min_ceiling_height_m, where + "min_ceiling_height_m");
  try {
    return describePlanes(segmented, direction, chosen);
  } catch (const std::invalid_argument& error) {
    std::string what = error.what();
    const std::string prefix = "floodplane::describePlanes: ";
    if (what.compare(0, prefix.size(), prefix) == 0) what = what.substr(prefix.size());
    raiseValueError(std::string(kFunction) + ": " + what);
  }
}

py::tuple descriptionState(const PlaneDescription& d) {
  return py::make_tuple(static_cast<int>(d.plane_class), d.height_above_floor);
}

PlaneDescription descriptionFromState(const py::tuple& state) {
  if (state.size() != 2) throw std::runtime_error("PlaneDescription: a pickle of another version");
  PlaneDescription d;
  d.plane_class = static_cast<PlaneClass>(state[0].cast<int>());
  d.height_above_floor = state[1].cast<double>();
  return d;
}

}  // namespace

void bindPlaneClasses(py::module_& m) {
  py::class_<PlaneDescription>(m, "PlaneDescription", "What describe_planes says of one plane.")
      .def_property_readonly(
          "plane_class", [](const PlaneDescription& d) { return std::string(planeClassName(d.plane_class)); },
          "'floor', 'ceiling', 'wall', 'horizontal_surface' or 'other'")
      .def_readonly("height_above_floor", &PlaneDescription::height_above_floor,
                    "along up from the floor's plane to the plane's centroid [m]; nan when no floor was found")
      .def("__eq__",
           [](const PlaneDescription& a, const PlaneDescription& b) {
             const bool both_nan = std::isnan(a.height_above_floor) && std::isnan(b.height_above_floor);
             return a.plane_class == b.plane_class && (both_nan || a.height_above_floor == b.height_above_floor);
           })
      .def(py::pickle(&descriptionState, &descriptionFromState))
      .def("__repr__", [](const PlaneDescription& d) {
        return std::string("PlaneDescription(plane_class='") + planeClassName(d.plane_class) +
               "', height_above_floor=" + (std::isnan(d.height_above_floor) ? "nan" : fixed(d.height_above_floor, 3)) +
               ")";
      });
  const PlaneClassOptions defaults;
  m.def("describe_planes", &describe, py::arg("planes"), py::arg("up"), py::kw_only(),
        py::arg("horizontal_tolerance_rad") = defaults.horizontal_tolerance_rad,
        py::arg("vertical_tolerance_rad") = defaults.vertical_tolerance_rad,
        py::arg("min_floor_area_m2") = defaults.min_floor_area_m2,
        py::arg("floor_height_tolerance_m") = defaults.floor_height_tolerance_m,
        py::arg("min_ceiling_area_m2") = defaults.min_ceiling_area_m2,
        py::arg("min_ceiling_height_m") = defaults.min_ceiling_height_m,
        "What each plane is, one PlaneDescription per plane in the order "
        "of `planes` (a Segmentation, or a list of its Plane objects), by the up direction `up` (three numbers "
        "against gravity in the planes' frame, the camera's: (0, -1, 0) for a level camera with y down; any "
        "length): 'floor' (the lowest large up-facing horizontal plane, and its pieces at its height), 'ceiling' "
        "(a large down-facing one high above the floor), 'wall' (any vertical plane), 'horizontal_surface' "
        "(another up-facing horizontal plane: tables, shelves, treads) or 'other' (inclined), with the height "
        "above the floor [m] (nan without a floor). The options are floodplane::PlaneClassOptions' fields: "
        "the angles [rad] within which a normal is horizontal and vertical, the smallest floor and ceiling "
        "[m^2], how far from the floor's plane a horizontal plane is floor too [m], how high a ceiling is at "
        "least [m]. Raises TypeError for planes, up or an option of the wrong type, ValueError for an up that is zero, "
        "not finite or not three numbers and an option out "
        "of range.");
}

}  // namespace floodplane::python
