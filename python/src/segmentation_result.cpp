// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "segmentation_result.h"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdio>
#include <string>
#include <vector>

#include "decimal_text.h"
#include "result_pickling.h"

namespace floodplane::python {
namespace {

namespace py = pybind11;

void bindNoiseModel(py::module_& m) {
  py::class_<NoiseModel>(m, "NoiseModel",
                         "The depth noise a segmentation assumed: sigma(r) = sigma_constant + sigma_quadratic r^2 "
                         "along a viewing ray at range r [m], and the depth step of quantized sensors, step(r) = "
                         "step_constant + step_quadratic r^2 (0 where there is none).")
      .def_readonly("sigma_constant", &NoiseModel::sigma_constant, "sigma_0 [m]")
      .def_readonly("sigma_quadratic", &NoiseModel::sigma_quadratic, "c [1/m]")
      .def_readonly("step_constant", &NoiseModel::step_constant, "q_0 [m]")
      .def_readonly("step_quadratic", &NoiseModel::step_quadratic, "q_2 [1/m]")
      .def_readonly("patches", &NoiseModel::patches, "flat 5 x 5 patches the estimate rests on")
      .def_readonly("estimated", &NoiseModel::estimated, "True: measured on the frame; False: from the parameters")
      .def("sigma", &NoiseModel::sigma, py::arg("range"), "The noise standard deviation [m] at `range` metres.")
      .def("step", &NoiseModel::step, py::arg("range"), "The depth step [m] at `range` metres.")
      .def(py::pickle(&noiseState, &noiseFromState))
      .def("__repr__", [](const NoiseModel& n) {
        return "NoiseModel(sigma_constant=" + std::to_string(n.sigma_constant) +
               ", sigma_quadratic=" + std::to_string(n.sigma_quadratic) +
               ", step_constant=" + std::to_string(n.step_constant) +
               ", step_quadratic=" + std::to_string(n.step_quadratic) + ", patches=" + std::to_string(n.patches) +
               ", estimated=" + (n.estimated ? "True" : "False") + ")";
      });
}

void bindPhaseTimes(py::module_& m) {
  py::class_<PhaseTimes>(m, "PhaseTimes",
                         "Milliseconds spent in each phase of one segmentation; zeros unless segment() was called "
                         "with measure_phases=True.")
      .def_readonly("preparation", &PhaseTimes::preparation)
      .def_readonly("seed_selection", &PhaseTimes::seed_selection)
      .def_readonly("flood_fill", &PhaseTimes::flood_fill)
      .def_readonly("relabelling", &PhaseTimes::relabelling)
      .def_readonly("merging", &PhaseTimes::merging)
      .def_readonly("region_output", &PhaseTimes::region_output)
      .def_readonly("pcl_conversion", &PhaseTimes::pcl_conversion)
      .def_property_readonly("total", &PhaseTimes::total)
      .def(py::pickle(&phasesState, &phasesFromState))
      .def("__repr__", [](const PhaseTimes& t) {
        return "PhaseTimes(preparation=" + fixed(t.preparation, 3) + ", seed_selection=" + fixed(t.seed_selection, 3) +
               ", flood_fill=" + fixed(t.flood_fill, 3) + ", relabelling=" + fixed(t.relabelling, 3) +
               ", merging=" + fixed(t.merging, 3) + ", region_output=" + fixed(t.region_output, 3) +
               ", pcl_conversion=" + fixed(t.pcl_conversion, 3) + ")";
      });
}

void bindStats(py::module_& m) {
  py::class_<SegmentationStats>(m, "SegmentationStats", "What happened inside one segmentation.")
      .def_readonly("seed_candidates", &SegmentationStats::seed_candidates, "unclaimed pixels tested as seeds")
      .def_readonly("seeds", &SegmentationStats::seeds, "candidates that passed the seed tests (one flood each)")
      .def_readonly("pixels_taken_over", &SegmentationStats::pixels_taken_over, "pixels reassigned by Eq. 4")
      .def_readonly("segments", &SegmentationStats::segments, "segments after relabelling")
      .def_readonly("merges", &SegmentationStats::merges, "merges by Eq. 9")
      .def_readonly("head_start", &SegmentationStats::head_start,
                    "the noise model was the previous frame's (Segmenter.segment(head_start=True)), not measured")
      .def(py::pickle(&statsState, &statsFromState))
      .def("__repr__", [](const SegmentationStats& s) {
        return "SegmentationStats(seed_candidates=" + std::to_string(s.seed_candidates) +
               ", seeds=" + std::to_string(s.seeds) + ", pixels_taken_over=" + std::to_string(s.pixels_taken_over) +
               ", segments=" + std::to_string(s.segments) + ", merges=" + std::to_string(s.merges) + ")";
      });
}

void bindPlane(py::module_& m) {
  py::class_<PlaneResult>(m, "Plane",
                          "One plane n . p + d = 0 in the camera frame (n unit, towards the camera), fitted to its "
                          "inliers by least squares.")
      .def_readonly("label", &PlaneResult::label, "its label in Segmentation.labels (1 = the largest)")
      .def_property_readonly(
          "normal", [](const PlaneResult& p) -> Eigen::Vector3d { return p.plane.fit.normal; },
          "unit normal (3,), towards the camera")
      .def_property_readonly(
          "d", [](const PlaneResult& p) { return p.plane.fit.offset; }, "offset d [m]")
      .def_property_readonly(
          "centroid", [](const PlaneResult& p) -> Eigen::Vector3d { return p.plane.fit.centroid; },
          "mean of the inliers (3,) [m]")
      .def_property_readonly(
          "inliers", [](const PlaneResult& p) { return p.plane.inlier_count; },
          "number of pixels labelled with this plane (full resolution)")
      .def_property_readonly(
          "covariance", [](const PlaneResult& p) -> Eigen::Matrix3d { return p.plane.fit.covariance; },
          "population covariance of the inliers (3, 3) [m^2]")
      .def_property_readonly(
          "eigenvalues", [](const PlaneResult& p) -> Eigen::Vector3d { return p.plane.fit.eigenvalues; },
          "of the covariance, ascending (3,)")
      .def_property_readonly(
          "mean_squared_error", [](const PlaneResult& p) { return p.plane.fit.mean_squared_error; },
          "mean squared distance of the inliers to the plane [m^2]")
      .def_property_readonly(
          "curvature", [](const PlaneResult& p) { return p.plane.fit.curvature; },
          "lambda_0 / (lambda_0 + lambda_1 + lambda_2), as PCL")
      .def_property_readonly(
          "first_pixel", [](const PlaneResult& p) { return p.plane.first_pixel; },
          "its first pixel in raster order (row * W + column)")
      .def(py::pickle(&planeState, &planeFromState))
      .def("__repr__", [](const PlaneResult& p) {
        const PlaneFit& f = p.plane.fit;
        return "Plane(label=" + std::to_string(p.label) + ", normal=[" + fixed(f.normal.x(), 4) + ", " +
               fixed(f.normal.y(), 4) + ", " + fixed(f.normal.z(), 4) + "], d=" + fixed(f.offset, 4) +
               ", inliers=" + std::to_string(p.plane.inlier_count) + ")";
      });
}

void bindObject(py::module_& m) {
  py::class_<SegmentedObject>(m, "Object",
                              "One object standing on the planes (floodplane::segmentObjects), in the camera frame.")
      .def_readonly("id", &SegmentedObject::id, "its label in Segmentation.object_labels (1 = the largest)")
      .def_readonly("pixels", &SegmentedObject::pixel_count, "number of pixels labelled with it")
      .def_property_readonly(
          "centroid", [](const SegmentedObject& o) -> Eigen::Vector3d { return o.centroid; },
          "mean of its points (3,) [m]")
      .def_property_readonly(
          "min", [](const SegmentedObject& o) -> Eigen::Vector3d { return o.min; },
          "axis-aligned bounding box's lower corner (3,) [m]")
      .def_property_readonly(
          "max", [](const SegmentedObject& o) -> Eigen::Vector3d { return o.max; },
          "axis-aligned bounding box's upper corner (3,) [m]")
      .def_readonly("support", &SegmentedObject::support,
                    "the label of the plane it stands on (Segmentation.labels' numbering), 0 for none")
      .def("__repr__", [](const SegmentedObject& o) {
        return "Object(id=" + std::to_string(o.id) + ", pixels=" + std::to_string(o.pixel_count) + ", centroid=[" +
               fixed(o.centroid.x(), 4) + ", " + fixed(o.centroid.y(), 4) + ", " + fixed(o.centroid.z(), 4) +
               "], support=" + std::to_string(o.support) + ")";
      });
}

py::object objectLabelsView(const py::object& self) {
  const auto& result = self.cast<const SegmentationResult&>();
  if (!result.objects) return py::none();
  const ObjectSegmentation& o = *result.objects;
  py::array_t<std::uint32_t> labels({py::ssize_t{o.height}, py::ssize_t{o.width}}, o.labels.data(), self);
  labels.attr("setflags")(py::arg("write") = false);
  return std::move(labels);
}

py::object objectList(const SegmentationResult& result) {
  if (!result.objects) return py::none();
  return py::cast(result.objects->objects);
}

// The pickle state: the planes' state alone (the format without objects), or with objects a
// pair (the planes' state, the objects' state).
py::tuple resultState(const SegmentationResult& result) {
  if (!result.objects) return segmentationState(result);
  return py::make_tuple(segmentationState(result), objectsState(*result.objects));
}

SegmentationResult resultFromState(const py::tuple& state) {
  if (state.size() == 2 && py::isinstance<py::tuple>(state[0])) {
    SegmentationResult result = segmentationFromState(state[0].cast<py::tuple>());
    result.objects = std::make_shared<ObjectSegmentation>(
        objectsFromState(state[1].cast<py::tuple>(), result.segmentation->width, result.segmentation->height));
    return result;
  }
  return segmentationFromState(state);
}

py::object labelsView(const py::object& self) {
  const auto& result = self.cast<const SegmentationResult&>();
  const Segmentation& s = *result.segmentation;
  py::array_t<std::uint32_t> labels({py::ssize_t{s.height}, py::ssize_t{s.width}}, s.labels.data(), self);
  // A view of the result's own labels, which boundary() reads: not to be written through.
  labels.attr("setflags")(py::arg("write") = false);
  return std::move(labels);
}

std::vector<PlaneResult> planeList(const SegmentationResult& result) {
  std::vector<PlaneResult> planes;
  const auto& segmented = result.segmentation->planes;
  for (std::size_t k = 0; k < segmented.size(); ++k)
    planes.push_back({segmented[k], static_cast<std::uint32_t>(k + 1)});
  return planes;
}

py::array_t<int> boundary(const SegmentationResult& result, py::ssize_t plane) {
  const Segmentation& s = *result.segmentation;
  const auto count = static_cast<py::ssize_t>(s.planes.size());
  if (plane < 0 || plane >= count) {
    throw py::index_error("boundary: plane " + std::to_string(plane) + " out of range: the segmentation has " +
                          std::to_string(count) + " planes (0 .. " + std::to_string(count - 1) + ")");
  }
  std::vector<int> contour;
  s.boundary(static_cast<std::size_t>(plane), contour);
  py::array_t<int> out(static_cast<py::ssize_t>(contour.size()));
  std::copy(contour.begin(), contour.end(), out.mutable_data());
  return out;
}

}  // namespace

void bindSegmentationResult(py::module_& m) {
  bindNoiseModel(m);
  bindPhaseTimes(m);
  bindStats(m);
  bindPlane(m);
  bindObject(m);
  py::class_<SegmentationResult>(m, "Segmentation",
                                 "The planes found in one frame. Pickles (with its planes, labels, noise, stats), "
                                 "so that Dask and multiprocessing can move it.")
      .def_property_readonly("labels", &labelsView,
                             "uint32 (H, W), read-only: 0 no plane, k = planes[k - 1] (largest first)")
      .def_property_readonly("planes", &planeList, "the planes, largest first (list of Plane)")
      .def_property_readonly("width", [](const SegmentationResult& r) { return r.segmentation->width; })
      .def_property_readonly("height", [](const SegmentationResult& r) { return r.segmentation->height; })
      .def_property_readonly(
          "noise", [](const SegmentationResult& r) { return r.segmentation->noise; },
          "the depth noise the segmentation assumed (NoiseModel)")
      .def_property_readonly(
          "phases", [](const SegmentationResult& r) { return r.segmentation->phases; },
          "time per phase [ms] (PhaseTimes), with measure_phases=True")
      .def_property_readonly(
          "stats", [](const SegmentationResult& r) { return r.segmentation->stats; },
          "seeds, segments, merges (SegmentationStats)")
      .def_readonly("ms", &SegmentationResult::ms, "wall time of the segmentation itself [ms]")
      .def_property_readonly("object_labels", &objectLabelsView,
                             "uint32 (H, W), read-only: 0 no object, k = objects[k - 1] (largest first); None "
                             "unless segmented with objects=True")
      .def_property_readonly("objects", &objectList,
                             "the objects standing on the planes, largest first (list of Object); None unless "
                             "segmented with objects=True")
      .def("boundary", &boundary, py::arg("plane"),
           "The outer boundary of planes[plane]: pixel indices (row * W + column), clockwise on screen, "
           "8-connected, starting at the plane's first pixel.")
      .def(py::pickle(&resultState, &resultFromState))
      .def("__repr__", [](const SegmentationResult& r) {
        const Segmentation& s = *r.segmentation;
        return "<floodplane.Segmentation " + std::to_string(s.width) + "x" + std::to_string(s.height) + ", " +
               std::to_string(s.planes.size()) + (s.planes.size() == 1 ? " plane, " : " planes, ") + fixed(r.ms, 2) +
               " ms>";
      });
}

}  // namespace floodplane::python
