// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "tracker_binding.h"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "decimal_text.h"
#include "errors.h"
#include "floodplane/plane_tracker.h"
#include "params_kwargs.h"
#include "point_arrays.h"
#include "result_pickling.h"
#include "segmentation_result.h"

namespace floodplane::python {
namespace {

namespace py = pybind11;

// The core's tracker and the size of the last frame it took (which relabel() needs).
struct Tracker {
  PlaneTracker core;
  py::ssize_t width = 0;
  py::ssize_t height = 0;
};

// One option: its name, how a Python value is stored into the Options, and read back.
struct Option {
  const char* name;
  std::function<void(PlaneTracker::Options&, py::handle, const std::string&)> set;
  std::function<py::object(const PlaneTracker::Options&)> get;
};

const std::vector<Option>& options() {
  const auto number = [](const char* name, double PlaneTracker::Options::*member) {
    return Option{
        name,
        [member](PlaneTracker::Options& o, py::handle v, const std::string& where) { o.*member = toDouble(v, where); },
        [member](const PlaneTracker::Options& o) { return py::cast(o.*member); }};
  };
  static const std::vector<Option> table = {
      number("max_normal_angle", &PlaneTracker::Options::max_normal_angle),
      number("max_offset_difference", &PlaneTracker::Options::max_offset_difference),
      Option{"max_lost_frames",
             [](PlaneTracker::Options& o, py::handle v, const std::string& where) {
               o.max_lost_frames = static_cast<int>(
                   toInteger(v, where, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
             },
             [](const PlaneTracker::Options& o) { return py::cast(o.max_lost_frames); }},
      number("smoothing", &PlaneTracker::Options::smoothing),
      number("overlap_max_rotation", &PlaneTracker::Options::overlap_max_rotation),
      number("overlap_max_translation", &PlaneTracker::Options::overlap_max_translation),
  };
  return table;
}

std::string optionNames() {
  std::string list;
  for (const Option& option : options()) list += (list.empty() ? "" : ", ") + std::string(option.name);
  return list;
}

// The core's message without its "floodplane::PlaneTracker::...: " prefix, after `function`'s.
std::string coreProblem(const std::string& function, const std::invalid_argument& error) {
  std::string what = error.what();
  const std::string prefix = "floodplane::PlaneTracker::";
  if (what.compare(0, prefix.size(), prefix) == 0) {
    const std::size_t colon = what.find(": ");
    if (colon != std::string::npos) what = what.substr(colon + 2);
  }
  return function + ": " + what;
}

PlaneTracker::Options optionsFromKeywords(const py::kwargs& keywords) {
  PlaneTracker::Options result;
  for (const auto& [key, value] : keywords) {
    const std::string name = py::str(key);
    const Option* option = nullptr;
    for (const Option& candidate : options())
      if (name == candidate.name) option = &candidate;
    if (!option) {
      raiseTypeError("Tracker() got an unexpected keyword argument '" + name + "' (the options are " + optionNames() +
                     ")");
    }
    option->set(result, value, "Tracker: " + name);
  }
  return result;
}

std::unique_ptr<Tracker> makeTracker(const py::kwargs& keywords) {
  auto tracker = std::make_unique<Tracker>();
  try {
    tracker->core.setOptions(optionsFromKeywords(keywords));
  } catch (const std::invalid_argument& error) {
    raiseValueError(coreProblem("Tracker", error));
  }
  return tracker;
}

// A 4 x 4 motion from any array-like of real numbers.
Eigen::Matrix4d motionFrom(py::handle motion, const std::string& where) {
  const std::string wanted = "a 4 x 4 array of numbers (a rigid transform) or None";
  if (py::isinstance<py::str>(motion) || py::isinstance<py::bytes>(motion))
    raiseTypeError(where + " must be " + wanted + ", got " + typeName(motion));
  py::array array = py::array::ensure(motion);
  if (!array) {
    PyErr_Clear();
    raiseTypeError(where + " must be " + wanted + ", got " + typeName(motion));
  }
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    raiseTypeError(where + " must be " + wanted + ", got dtype " + std::string(py::str(array.dtype())));
  if (array.ndim() != 2 || array.shape(0) != 4 || array.shape(1) != 4)
    raiseValueError(where + " must have shape (4, 4), got " + shapeText(array));
  const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
  if (!values) throw py::error_already_set();
  Eigen::Matrix4d matrix;
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column) matrix(row, column) = values.at(row, column);
  return matrix;
}

std::vector<std::uint32_t> update(Tracker& self, py::handle result, py::handle motion) {
  const std::string function = "Tracker.update";
  if (!py::isinstance<SegmentationResult>(result)) {
    raiseTypeError(function + ": result must be a floodplane.Segmentation (what Segmenter.segment returns), got " +
                   typeName(result));
  }
  const Segmentation& segmentation = *result.cast<const SegmentationResult&>().segmentation;
  try {
    if (motion.is_none()) {
      self.core.update(segmentation);
    } else {
      self.core.update(segmentation, motionFrom(motion, function + ": motion"));
    }
  } catch (const std::invalid_argument& error) {
    raiseValueError(coreProblem(function, error));
  }
  self.width = segmentation.width;
  self.height = segmentation.height;
  return self.core.trackIds();
}

py::array_t<std::uint32_t> relabel(const Tracker& self, py::handle labels) {
  const std::string function = "Tracker.relabel";
  if (self.core.frameCount() == 0) raiseValueError(function + ": no frame yet: call update() first");
  const std::vector<std::uint32_t> values =
      unsignedGrid(labels, self.height, self.width, self.core.trackIds().size(), function + ": labels");
  std::vector<std::uint32_t> track_labels;
  self.core.relabel(values, track_labels);
  return arrayCopy(track_labels, {self.height, self.width});
}

std::optional<PlaneTrack> trackWithId(const Tracker& self, py::handle id) {
  const auto value =
      static_cast<std::uint32_t>(toInteger(id, "Tracker.track: id", 0, std::numeric_limits<std::uint32_t>::max()));
  const PlaneTrack* track = self.core.track(value);
  if (!track) return std::nullopt;
  return *track;
}

std::string vectorText(const Eigen::Vector3d& v) {
  return "[" + fixed(v.x(), 4) + ", " + fixed(v.y(), 4) + ", " + fixed(v.z(), 4) + "]";
}

void bindTrack(py::module_& m) {
  py::class_<PlaneTrack>(m, "Track",
                         "One surface followed over frames: its plane n . p + d = 0 in the camera frame of the last "
                         "frame given to Tracker.update (as measured there when seen, otherwise as last measured, "
                         "moved by the motions given since).")
      .def_readonly("id", &PlaneTrack::id, "1, 2, ... in order of appearance; never reused before reset()")
      .def_readonly("first_frame", &PlaneTrack::first_frame, "index of the frame it was first seen in (0: the first)")
      .def_readonly("last_frame", &PlaneTrack::last_frame, "index of the frame it was last seen in")
      .def_readonly("frames_seen", &PlaneTrack::frames_seen, "frames it was seen in (not necessarily consecutive)")
      .def_readonly("plane", &PlaneTrack::plane, "its index in the last frame's planes; -1 when not seen in it")
      .def_readonly("inliers", &PlaneTrack::inlier_count, "pixels when last seen")
      .def_property_readonly(
          "normal", [](const PlaneTrack& t) -> Eigen::Vector3d { return t.normal; }, "unit normal n (3,)")
      .def_readonly("offset", &PlaneTrack::offset, "offset d [m]")
      .def_property_readonly(
          "centroid", [](const PlaneTrack& t) -> Eigen::Vector3d { return t.centroid; },
          "mean of its inliers when last seen (3,) [m]")
      .def_property_readonly(
          "smoothed_normal", [](const PlaneTrack& t) -> Eigen::Vector3d { return t.smoothed_normal; },
          "exponentially smoothed unit normal (3,)")
      .def_readonly("smoothed_offset", &PlaneTrack::smoothed_offset, "exponentially smoothed offset d [m]")
      .def_readonly("best_inliers", &PlaneTrack::best_inlier_count,
                    "pixels in the frame where it had the most (since the last update without a motion, which "
                    "makes the newest the best): where best_normal, best_offset and best_centroid were "
                    "measured (moved like the others since)")
      .def_property_readonly(
          "best_normal", [](const PlaneTrack& t) -> Eigen::Vector3d { return t.best_normal; },
          "unit normal where it had the most inliers (3,)")
      .def_readonly("best_offset", &PlaneTrack::best_offset, "offset d where it had the most inliers [m]")
      .def_property_readonly(
          "best_centroid", [](const PlaneTrack& t) -> Eigen::Vector3d { return t.best_centroid; },
          "mean of its inliers where it had the most (3,) [m]")
      .def(py::pickle(&trackState, &trackFromState))
      .def("__repr__", [](const PlaneTrack& t) {
        return "Track(id=" + std::to_string(t.id) + ", first_frame=" + std::to_string(t.first_frame) +
               ", last_frame=" + std::to_string(t.last_frame) + ", frames_seen=" + std::to_string(t.frames_seen) +
               ", normal=" + vectorText(t.normal) + ", offset=" + fixed(t.offset, 4) + ")";
      });
}

}  // namespace

void bindTracker(py::module_& m) {
  bindTrack(m);
  py::class_<Tracker>(m, "Tracker",
                      "Gives the planes of a stream of segmentations ids that persist over frames "
                      "(floodplane::PlaneTracker): a plane keeps its id while its surface stays in view and gets it "
                      "back when it returns within max_lost_frames frames; new surfaces get new ids. Feed it each "
                      "frame's Segmentation in order. Not thread-safe: one Tracker per stream.")
      .def(py::init(&makeTracker),
           "Tracker(**options): max_normal_angle [rad] and max_offset_difference [m] (the largest turn of a "
           "plane's normal, and the largest distance between two planes, by their offsets or at their "
           "centroids, that still match), max_lost_frames, smoothing (weight of the newest "
           "measurement in the smoothed parameters, (0, 1]), overlap_max_rotation [rad] and "
           "overlap_max_translation [m] (the largest motion for which the label images are compared).")
      .def_property_readonly(
          "options",
          [](const Tracker& self) {
            py::dict dict;
            for (const Option& option : options()) dict[option.name] = option.get(self.core.options());
            return dict;
          },
          "every option as a dict")
      .def("update", &update, py::arg("result"), py::arg("motion") = py::none(),
           "Takes the next frame's Segmentation, with the camera's motion since the previous frame when known: "
           "the pose of the current camera in the previous camera's frame (4 x 4 rigid transform, metres), so that "
           "a point p of this frame is motion @ p in the previous one. Returns the track id of each plane "
           "(ids[k] for result.planes[k]; ids >= 1).")
      .def("relabel", &relabel, py::arg("labels"),
           "The last frame's label image (its result.labels) with track ids in place of plane labels (0 stays 0): "
           "a new uint32 (H, W) array.")
      .def_property_readonly(
          "tracks", [](const Tracker& self) { return self.core.tracks(); },
          "the tracks seen in the last frame and the lost ones still kept, by increasing id (list of Track)")
      .def_property_readonly(
          "track_ids", [](const Tracker& self) { return self.core.trackIds(); },
          "the last frame's track id per plane, as update returned them")
      .def("track", &trackWithId, py::arg("id"), "The Track with this id, or None when there is none.")
      .def_property_readonly(
          "frame_count", [](const Tracker& self) { return self.core.frameCount(); },
          "frames taken since construction or reset()")
      .def(
          "reset",
          [](Tracker& self) {
            self.core.reset();
            self.width = self.height = 0;
          },
          "Forgets every track and the previous frame; ids start again at 1. Keeps the options.")
      .def("__repr__", [](const Tracker& self) {
        return "<floodplane.Tracker " + std::to_string(self.core.frameCount()) + " frames, " +
               std::to_string(self.core.tracks().size()) + " tracks>";
      });
}

}  // namespace floodplane::python
