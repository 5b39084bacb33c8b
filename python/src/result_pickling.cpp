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

// How one field goes into a state and comes back: numbers, flags and Python objects as they
// are, vectors and matrices as tuples of their coefficients, the structs a state holds as their
// own states (a plane's fit without its format number, as a Segmentation holds it).
template <typename T>
py::object fieldState(const T& value) {
  if constexpr (std::is_base_of_v<py::handle, T>) {
    return py::reinterpret_borrow<py::object>(value);
  } else {
    return py::cast(value);
  }
}
py::object fieldState(const Eigen::Vector3d& v) { return vectorState(v); }
py::object fieldState(const Eigen::Matrix3d& m) { return matrixState(m); }
py::object fieldState(const PlaneFit& fit);
py::object fieldState(const NoiseModel& noise) { return noiseState(noise); }
py::object fieldState(const PhaseTimes& phases) { return phasesState(phases); }
py::object fieldState(const SegmentationStats& stats) { return statsState(stats); }

template <typename T>
void readField(StateReader& reader, T& field) {
  field = reader.next<T>();
}
void readField(StateReader& reader, Eigen::Vector3d& v) { v = reader.vector(); }
void readField(StateReader& reader, Eigen::Matrix3d& m) { m = reader.matrix(); }
void readField(StateReader& reader, PlaneFit& fit);
void readField(StateReader& reader, NoiseModel& noise) { noise = noiseFromState(reader.next<py::tuple>()); }
void readField(StateReader& reader, PhaseTimes& phases) { phases = phasesFromState(reader.next<py::tuple>()); }
void readField(StateReader& reader, SegmentationStats& stats) { stats = statsFromState(reader.next<py::tuple>()); }

// Each type's fields are listed once, by a function that hands them to a visitor in their
// order (const when they are written, not when they are read); these turn that one list into
// both directions.
template <typename T, typename Fields>
py::tuple fieldsState(const T& value, Fields fields) {
  return fields(value, [](const auto&... field) { return py::make_tuple(fieldState(field)...); });
}

template <typename T, typename Fields>
std::size_t fieldCount(T& value, Fields fields) {
  return fields(value, [](auto&... field) { return sizeof...(field); });
}

template <typename T, typename Fields>
void readFields(StateReader& reader, T& value, Fields fields) {
  fields(value, [&reader](auto&... field) {
    (readField(reader, field), ...);  // left to right: the fields' order
    return 0;
  });
}

template <typename T, typename Fields>
py::tuple plainState(const T& value, Fields fields) {
  return withFormat(fieldsState(value, fields));
}

template <typename T, typename Fields>
T plainFromState(const py::tuple& state, const char* type, Fields fields) {
  T value;
  StateReader reader(state, type, fieldCount(value, fields));
  readFields(reader, value, fields);
  return value;
}

const auto fitFields = [](auto& f, auto&& visit) {
  return visit(f.centroid, f.normal, f.offset, f.covariance, f.eigenvalues, f.mean_squared_error, f.curvature, f.valid);
};
const auto noiseFields = [](auto& n, auto&& visit) {
  return visit(n.sigma_constant, n.sigma_quadratic, n.step_constant, n.step_quadratic, n.patches, n.estimated);
};
const auto phasesFields = [](auto& t, auto&& visit) {
  return visit(t.preparation, t.seed_selection, t.flood_fill, t.relabelling, t.merging, t.region_output,
               t.pcl_conversion);
};
const auto statsFields = [](auto& s, auto&& visit) {
  return visit(s.seed_candidates, s.seeds, s.pixels_taken_over, s.segments, s.merges, s.head_start);
};
// A Segmentation holds its planes' states without the format number.
const auto segmentedPlaneFields = [](auto& p, auto&& visit) { return visit(p.fit, p.inlier_count, p.first_pixel); };
// Python's Plane: a SegmentedPlane and its label.
const auto planeFields = [](auto& p, auto&& visit) {
  return visit(p.plane.fit, p.plane.inlier_count, p.plane.first_pixel, p.label);
};
// An ObjectSegmentation holds its objects' states without the format number.
const auto objectFields = [](auto& o, auto&& visit) {
  return visit(o.id, o.pixel_count, o.centroid, o.min, o.max, o.support);
};
// An ObjectSegmentation's fields: its labels (an array), supports and objects (lists), checked
// against each other and the segmentation's size once read.
struct ObjectsFields {
  py::object labels;
  std::vector<std::uint32_t> supports;
  py::list objects;
};
const auto objectsFields = [](auto& o, auto&& visit) { return visit(o.labels, o.supports, o.objects); };
const auto trackFields = [](auto& t, auto&& visit) {
  return visit(t.id, t.first_frame, t.last_frame, t.frames_seen, t.plane, t.inlier_count, t.normal, t.offset,
               t.centroid, t.smoothed_normal, t.smoothed_offset, t.best_inlier_count, t.best_normal, t.best_offset,
               t.best_centroid);
};

py::object fieldState(const PlaneFit& fit) { return fieldsState(fit, fitFields); }
void readField(StateReader& reader, PlaneFit& fit) {
  fit = plainFromState<PlaneFit>(withFormat(reader.next<py::tuple>()), "Plane", fitFields);
}

// A Segmentation's fields: its label image and planes stand in the state as `labels` (an
// array) and `planes` (a list of their states), which are checked against each other once read.
struct SegmentationFields {
  int width = 0;
  int height = 0;
  py::object labels;
  py::list planes;
  NoiseModel noise;
  PhaseTimes phases;
  SegmentationStats stats;
  double ms = 0.0;
};
const auto segmentationFields = [](auto& s, auto&& visit) {
  return visit(s.width, s.height, s.labels, s.planes, s.noise, s.phases, s.stats, s.ms);
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

py::tuple planeState(const PlaneResult& plane) { return plainState(plane, planeFields); }
PlaneResult planeFromState(const py::tuple& state) { return plainFromState<PlaneResult>(state, "Plane", planeFields); }

py::tuple segmentationState(const SegmentationResult& result) {
  const Segmentation& s = *result.segmentation;
  SegmentationFields fields{s.width, s.height, arrayCopy(s.labels, {s.height, s.width}), py::list(), s.noise, s.phases,
                            s.stats, result.ms};
  for (const SegmentedPlane& plane : s.planes) fields.planes.append(fieldsState(plane, segmentedPlaneFields));
  return plainState(fields, segmentationFields);
}

SegmentationResult segmentationFromState(const py::tuple& state) {
  const auto fields = plainFromState<SegmentationFields>(state, "Segmentation", segmentationFields);
  const std::string where = "cannot unpickle floodplane.Segmentation: ";
  if (fields.width < 0 || fields.height < 0) raiseValueError(where + "fields 1 and 2 must be a width and height >= 0");
  auto s = std::make_shared<Segmentation>();
  s->width = fields.width;
  s->height = fields.height;
  s->labels = unsignedGrid(fields.labels, s->height, s->width, fields.planes.size(), where + "labels");
  const std::size_t pixels = s->labels.size();
  for (const py::handle plane : fields.planes) {
    if (!py::isinstance<py::tuple>(plane)) raiseValueError(where + "a plane's state must be a tuple");
    const py::tuple plane_state = withFormat(py::reinterpret_borrow<py::tuple>(plane));
    SegmentedPlane& added = s->planes.emplace_back();
    StateReader reader(plane_state, "Segmentation.planes", fieldCount(added, segmentedPlaneFields));
    readFields(reader, added, segmentedPlaneFields);
    const std::size_t label = s->planes.size();
    // boundary() starts its walk at the first pixel, which must carry the plane's label.
    if (added.first_pixel >= pixels || s->labels[added.first_pixel] != label) {
      raiseValueError(where + "plane " + std::to_string(label) + "'s first pixel does not carry its label");
    }
  }
  s->noise = fields.noise;
  s->phases = fields.phases;
  s->stats = fields.stats;
  SegmentationResult result;
  result.segmentation = std::move(s);
  result.ms = fields.ms;
  return result;
}

py::tuple objectsState(const ObjectSegmentation& objects) {
  ObjectsFields fields{arrayCopy(objects.labels, {objects.height, objects.width}), objects.supports, py::list()};
  for (const SegmentedObject& object : objects.objects) fields.objects.append(fieldsState(object, objectFields));
  return plainState(fields, objectsFields);
}

ObjectSegmentation objectsFromState(const py::tuple& state, int width, int height) {
  const auto fields = plainFromState<ObjectsFields>(state, "Segmentation.objects", objectsFields);
  const std::string where = "cannot unpickle floodplane.Segmentation: ";
  ObjectSegmentation out;
  out.width = width;
  out.height = height;
  out.labels = unsignedGrid(fields.labels, height, width, fields.objects.size(), where + "object labels");
  out.supports = fields.supports;
  for (const py::handle object : fields.objects) {
    if (!py::isinstance<py::tuple>(object)) raiseValueError(where + "an object's state must be a tuple");
    SegmentedObject& added = out.objects.emplace_back();
    StateReader reader(withFormat(py::reinterpret_borrow<py::tuple>(object)), "Segmentation.objects",
                       fieldCount(added, objectFields));
    readFields(reader, added, objectFields);
    if (added.id != out.objects.size()) raiseValueError(where + "the objects' ids must be 1, 2, ... in order");
  }
  return out;
}

py::tuple trackState(const PlaneTrack& track) { return plainState(track, trackFields); }
PlaneTrack trackFromState(const py::tuple& state) { return plainFromState<PlaneTrack>(state, "Track", trackFields); }

}  // namespace floodplane::python
