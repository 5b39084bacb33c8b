// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "result_pickling.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "errors.h"
#include "point_arrays.h"

namespace floodplane::python {
namespace {

namespace py = pybind11;

// Raised by a state this build cannot read; bump when a state's layout changes.
constexpr int kStateFormat = 1;

// Reads a state's fields in order, checking its type name, format and length first.
class StateReader {
 public:
  StateReader(const py::tuple& state, const char* type, std::size_t fields) : state_(state), type_(type) {
    if (state.size() != fields + 1 || !py::isinstance<py::int_>(state[0]) || state[0].cast<int>() != kStateFormat) {
      raiseValueError(std::string("cannot unpickle floodplane.") + type + ": not a state of format " +
                      std::to_string(kStateFormat) + " with " + std::to_string(fields) +
                      " fields (pickled by another floodplane version?)");
    }
  }
  template <typename T>
  T next() {
    try {
      return state_[index_++].template cast<T>();
    } catch (const py::cast_error&) {
      raiseValueError(std::string("cannot unpickle floodplane.") + type_ + ": field " + std::to_string(index_ - 1) +
                      " has the wrong type");
    }
  }
  Eigen::Vector3d vector() {
    const auto values = next<std::vector<double>>();
    if (values.size() != 3) fail("a vector of 3 numbers");
    return {values[0], values[1], values[2]};
  }
  Eigen::Matrix3d matrix() {
    const auto values = next<std::vector<double>>();
    if (values.size() != 9) fail("a 3 x 3 matrix of 9 numbers");
    Eigen::Matrix3d m;
    for (int i = 0; i < 9; ++i) m(i / 3, i % 3) = values[static_cast<std::size_t>(i)];
    return m;
  }
  py::handle raw() { return state_[index_++]; }
  [[noreturn]] void fail(const std::string& wanted) const {
    raiseValueError(std::string("cannot unpickle floodplane.") + type_ + ": field " + std::to_string(index_ - 1) +
                    " must be " + wanted);
  }

 private:
  py::tuple state_;
  const char* type_;
  std::size_t index_ = 1;
};

// `fields` behind the format number: a nested state (a plane's fit, a Segmentation's plane)
// read with a StateReader of its own.
py::tuple withFormat(const py::tuple& fields) {
  py::tuple out(fields.size() + 1);
  out[0] = kStateFormat;
  for (std::size_t i = 0; i < fields.size(); ++i) out[i + 1] = fields[i];
  return out;
}

py::tuple vectorState(const Eigen::Vector3d& v) { return py::make_tuple(v.x(), v.y(), v.z()); }

py::tuple matrixState(const Eigen::Matrix3d& m) {
  py::tuple out(9);
  for (int i = 0; i < 9; ++i) out[static_cast<std::size_t>(i)] = m(i / 3, i % 3);
  return out;
}

py::tuple fitState(const PlaneFit& f) {
  return py::make_tuple(vectorState(f.centroid), vectorState(f.normal), f.offset, matrixState(f.covariance),
                        vectorState(f.eigenvalues), f.mean_squared_error, f.curvature, f.valid);
}

// The fields of a SegmentedPlane, without the format number, so that a Segmentation's state
// holds its planes' as they are.
py::tuple segmentedPlaneFields(const SegmentedPlane& plane) {
  return py::make_tuple(fitState(plane.fit), plane.inlier_count, plane.first_pixel);
}

SegmentedPlane segmentedPlaneFrom(StateReader& reader) {
  SegmentedPlane plane;
  const auto fit = reader.next<py::tuple>();
  StateReader fields(withFormat(fit), "Plane", 8);
  plane.fit.centroid = fields.vector();
  plane.fit.normal = fields.vector();
  plane.fit.offset = fields.next<double>();
  plane.fit.covariance = fields.matrix();
  plane.fit.eigenvalues = fields.vector();
  plane.fit.mean_squared_error = fields.next<double>();
  plane.fit.curvature = fields.next<double>();
  plane.fit.valid = fields.next<bool>();
  plane.inlier_count = reader.next<std::uint32_t>();
  plane.first_pixel = reader.next<std::size_t>();
  return plane;
}

// The plain structs' states: each struct's fields are listed once (its `fields` function
// hands them to a visitor in their order), for both ways.
template <typename T, typename Fields>
py::tuple plainState(T value, Fields fields) {
  return fields(value, [](auto&... field) { return py::make_tuple(kStateFormat, field...); });
}

template <typename T, typename Fields>
T plainFromState(const py::tuple& state, const char* type, Fields fields) {
  T value;
  StateReader reader(state, type, fields(value, [](auto&... field) { return sizeof...(field); }));
  fields(value, [&reader](auto&... field) {
    ((field = reader.next<std::decay_t<decltype(field)>>()), ...);  // left to right: the fields' order
    return 0;
  });
  return value;
}

const auto noiseFields = [](NoiseModel& n, auto&& visit) {
  return visit(n.sigma_constant, n.sigma_quadratic, n.step_constant, n.step_quadratic, n.patches, n.estimated);
};
const auto phasesFields = [](PhaseTimes& t, auto&& visit) {
  return visit(t.preparation, t.seed_selection, t.flood_fill, t.relabelling, t.merging, t.region_output,
               t.pcl_conversion);
};
const auto statsFields = [](SegmentationStats& s, auto&& visit) {
  return visit(s.seed_candidates, s.seeds, s.pixels_taken_over, s.segments, s.merges, s.head_start);
};

}  // namespace

py::tuple noiseState(const NoiseModel& noise) { return plainState(noise, noiseFields); }
NoiseModel noiseFromState(const py::tuple& state) {
  return plainFromState<NoiseModel>(state, "NoiseModel", noiseFields);
}

py::tuple phasesState(const PhaseTimes& phases) { return plainState(phases, phasesFields); }
PhaseTimes phasesFromState(const py::tuple& state) {
  return plainFromState<PhaseTimes>(state, "PhaseTimes", phasesFields);
}

py::tuple statsState(const SegmentationStats& stats) { return plainState(stats, statsFields); }
SegmentationStats statsFromState(const py::tuple& state) {
  return plainFromState<SegmentationStats>(state, "SegmentationStats", statsFields);
}

py::tuple planeState(const PlaneResult& plane) {
  const py::tuple fields = segmentedPlaneFields(plane.plane);
  return py::make_tuple(kStateFormat, fields[0], fields[1], fields[2], plane.label);
}

PlaneResult planeFromState(const py::tuple& state) {
  StateReader reader(state, "Plane", 4);
  PlaneResult plane;
  plane.plane = segmentedPlaneFrom(reader);
  plane.label = reader.next<std::uint32_t>();
  return plane;
}

py::tuple segmentationState(const SegmentationResult& result) {
  const Segmentation& s = *result.segmentation;
  py::list planes;
  for (const SegmentedPlane& plane : s.planes) planes.append(segmentedPlaneFields(plane));
  return py::make_tuple(kStateFormat, s.width, s.height, arrayCopy(s.labels, {s.height, s.width}), planes,
                        noiseState(s.noise), phasesState(s.phases), statsState(s.stats), result.ms);
}

SegmentationResult segmentationFromState(const py::tuple& state) {
  StateReader reader(state, "Segmentation", 8);
  auto s = std::make_shared<Segmentation>();
  s->width = reader.next<int>();
  s->height = reader.next<int>();
  if (s->width < 0 || s->height < 0) reader.fail("a width and height >= 0");
  const py::handle labels = reader.raw();
  const auto planes = reader.next<py::list>();
  s->labels =
      unsignedGrid(labels, s->height, s->width, planes.size(), "cannot unpickle floodplane.Segmentation: labels");
  const std::size_t pixels = s->labels.size();
  for (const py::handle plane : planes) {
    if (!py::isinstance<py::tuple>(plane)) {
      raiseValueError("cannot unpickle floodplane.Segmentation: a plane's state must be a tuple");
    }
    StateReader fields(withFormat(py::reinterpret_borrow<py::tuple>(plane)), "Segmentation.planes", 3);
    s->planes.push_back(segmentedPlaneFrom(fields));
    const std::size_t label = s->planes.size();
    // boundary() starts its walk at the first pixel, which must carry the plane's label.
    if (s->planes.back().first_pixel >= pixels || s->labels[s->planes.back().first_pixel] != label) {
      raiseValueError("cannot unpickle floodplane.Segmentation: plane " + std::to_string(label) +
                      "'s first pixel does not carry its label");
    }
  }
  s->noise = noiseFromState(reader.next<py::tuple>());
  s->phases = phasesFromState(reader.next<py::tuple>());
  s->stats = statsFromState(reader.next<py::tuple>());
  SegmentationResult result;
  result.segmentation = std::move(s);
  result.ms = reader.next<double>();
  return result;
}

py::tuple trackState(const PlaneTrack& t) {
  return py::make_tuple(kStateFormat, t.id, t.first_frame, t.last_frame, t.frames_seen, t.plane, t.inlier_count,
                        vectorState(t.normal), t.offset, vectorState(t.centroid), vectorState(t.smoothed_normal),
                        t.smoothed_offset, t.best_inlier_count, vectorState(t.best_normal), t.best_offset,
                        vectorState(t.best_centroid));
}

PlaneTrack trackFromState(const py::tuple& state) {
  StateReader reader(state, "Track", 15);
  PlaneTrack t;
  t.id = reader.next<std::uint32_t>();
  t.first_frame = reader.next<std::size_t>();
  t.last_frame = reader.next<std::size_t>();
  t.frames_seen = reader.next<std::size_t>();
  t.plane = reader.next<int>();
  t.inlier_count = reader.next<std::uint32_t>();
  t.normal = reader.vector();
  t.offset = reader.next<double>();
  t.centroid = reader.vector();
  t.smoothed_normal = reader.vector();
  t.smoothed_offset = reader.next<double>();
  t.best_inlier_count = reader.next<std::uint32_t>();
  t.best_normal = reader.vector();
  t.best_offset = reader.next<double>();
  t.best_centroid = reader.vector();
  return t;
}

}  // namespace floodplane::python
