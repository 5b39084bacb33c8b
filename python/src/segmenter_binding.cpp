// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "segmenter_binding.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>

#include "camera_intrinsics.h"
#include "errors.h"
#include "file_segmentation.h"
#include "floodplane/io/output_rule.h"
#include "floodplane/object_segmentation.h"
#include "floodplane/segmenter.h"
#include "params/params_table.h"
#include "params_kwargs.h"
#include "point_arrays.h"
#include "segmentation_result.h"

namespace floodplane::python {
namespace {

namespace py = pybind11;

// The core's Segmenter is one-thread-at-a-time; the GIL is released while it works, so two
// Python threads sharing one Segmenter take turns on this mutex instead.
struct SharedSegmenter {
  explicit SharedSegmenter(const Params& params) : core(params) {}
  Segmenter core;
  std::mutex mutex;
};

SegmentationResult segmentArray(SharedSegmenter& self, py::handle points, bool refine, bool measure_phases,
                                bool head_start, bool zero_is_hole, bool objects) {
  const GridArray input = gridFromArray(points, "Segmenter.segment: points", zero_is_hole);
  auto copy = std::make_shared<Segmentation>();
  SegmentationResult result;
  {
    py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(self.mutex);
    Segmenter::Options options;
    options.refine = refine;
    options.measure_phases = measure_phases;
    options.head_start = head_start;
    const auto start = std::chrono::steady_clock::now();
    const Segmentation& segmentation = self.core.segment(input.grid, options);
    const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
    result.ms = elapsed.count();
    *copy = segmentation;  // the next call overwrites the core's result
    if (objects) result.objects = std::make_shared<ObjectSegmentation>(segmentObjects(input.grid, segmentation));
  }
  result.segmentation = std::move(copy);
  return result;
}

py::dict segmentFileSummary(SharedSegmenter& self, const std::filesystem::path& input_file,
                            const std::filesystem::path& output_file, py::handle intrinsics, double depth_scale,
                            const std::optional<std::filesystem::path>& objects_file) {
  const std::string input = input_file.string();
  const std::string output = output_file.string();
  const std::string objects_output = objects_file ? objects_file->string() : std::string();
  const std::string function = "Segmenter.segment_file";
  // An output over the input or over the other output, however spelled: refused before any
  // work, by the rule pcd_segment applies.
  if (const std::optional<std::string> collision = floodplane::io::outputCollision({output, objects_output}, {input})) {
    throw py::value_error(function + ": " + *collision + "; nothing written");
  }
  std::optional<DepthInput> depth;
  if (!intrinsics.is_none()) {
    const Intrinsics pinhole = intrinsicsFrom(intrinsics, function);
    depth = DepthInput{pinhole.camera(depth_scale, function), pinhole.width, pinhole.height};
  }
  FileSummary summary;
  std::string read_error;
  std::string write_error;
  {
    py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(self.mutex);
    try {
      summary = segmentFile(self.core, input, output, depth, objects_output);
    } catch (const OutputFileError& error) {
      write_error = error.what();
    } catch (const InputFileError& error) {
      read_error = error.what();
    }
  }
  if (!write_error.empty()) raiseFileError(FileAccess::write, function, "output", output, write_error);
  if (!read_error.empty()) raiseFileError(FileAccess::read, function, "input", input, read_error);
  py::dict out;
  out["width"] = summary.width;
  out["height"] = summary.height;
  out["planes"] = summary.planes;
  out["ms"] = summary.ms;
  if (summary.objects) out["objects"] = *summary.objects;
  return out;
}

std::string segmenterRepr(const SharedSegmenter& self) {
  std::string text = "Segmenter(";
  bool first = true;
  for (const auto& [name, value] : paramsToDict(self.core.params())) {
    text += (first ? "" : ", ") + std::string(py::str(name)) + "=" + std::string(py::repr(value));
    first = false;
  }
  return text + ")";
}

}  // namespace

// " distance_threshold" and so on: the keywords in Segmenter's docstring.
#define FLOODPLANE_KEYWORD(field, kind, flag, setter, help) " " #field

void bindSegmenter(py::module_& m) {
  py::class_<SharedSegmenter>(
      m, "Segmenter",
      "Plane segmentation of organized point clouds by seeded flood fill. The keywords are "
      "the fields of floodplane::Params; None (the default of the lengths) derives a "
      "value from the frame's noise. Keeps its buffers between calls: reuse one for a "
      "sequence of frames. Thread-safe (calls on one Segmenter take turns; use one per "
      "thread to run in parallel); the GIL is released while it segments. Pickles as its parameters: a "
      "copy starts cold (new buffers, no head start).")
      .def(py::init([](const py::kwargs& keywords) {
             return std::make_unique<SharedSegmenter>(paramsFromKeywords(keywords, "Segmenter"));
           }),
           "Segmenter(**params), the keywords:" FLOODPLANE_PARAMETERS(FLOODPLANE_KEYWORD))
      .def_property_readonly(
          "params", [](const SharedSegmenter& self) { return paramsToDict(self.core.params()); },
          "every parameter as a dict (None: derived from the frame)")
      .def("segment", &segmentArray, py::arg("points"), py::kw_only(), py::arg("refine") = true,
           py::arg("measure_phases") = false, py::arg("head_start") = false, py::arg("zero_is_hole") = true,
           py::arg("objects") = false,
           "Segments `points`, (H, W, 3) x y z in metres with the camera at the origin (NaN: no return): anything "
           "numpy.asarray makes an array of real numbers of (any float or integer dtype, nested lists or tuples). "
           "Read in place when float32 with x y z adjacent, converted to float32 otherwise. `zero_is_hole` "
           "takes points at exactly (0, 0, 0), the \"no depth\" of Open3D, RealSense and many ROS drivers, for "
           "no return as NaN is (in a copy; the array is not changed); False segments them as points. `refine` "
           "grows the planes into unlabelled pixels that fit them (as pcd_segment); `measure_phases` fills the "
           "result's phases; `head_start` continues from the last frame this Segmenter segmented (a stream from "
           "one sensor): its noise model is taken again instead of measured (anew every 30 frames); a cold start "
           "on the first frame, after a size change or a failed call. Returns a Segmentation. A frame with no "
           "finite point (all NaN; all (0, 0, 0) with zero_is_hole) or fewer than three is a valid frame with no "
           "planes: a Segmentation whose planes are [] and labels all 0, not an error (as pcd_segment and the ROS "
           "node); tiny frames (2 x 2) are segmented like any other. `objects` also finds the objects standing on the "
           "planes (floodplane::segmentObjects, as pcd_segment --objects): the result's object_labels and objects "
           "(None without). Raises for what is not a frame: a shape "
           "other than (H, W, 3) with H >= 2 and W >= 1 (ValueError), values that are not numbers (TypeError).")
      .def("segment_file", &segmentFileSummary, py::arg("input"), py::arg("output"), py::kw_only(),
           py::arg("intrinsics") = py::none(), py::arg("depth_scale") = 1000.0, py::arg("objects_output") = py::none(),
           "Segments the file `input` and writes its labelled cloud to `output` as pcd_segment does (the same "
           "bytes). `input` is a PCD file, or a 16-bit depth PNG with intrinsics ((fx, fy, cx, cy), a 3 x 3 K "
           "or Open3D's PinholeCameraIntrinsic, whose width and height must be the image's) and depth_scale "
           "(units per metre). With `objects_output`, also the objects standing on the planes to that file, as "
           "pcd_segment --objects writes them (x y z label: object ids 1..K, 0 none). Returns {'width', 'height', "
           "'planes', 'ms'} and, with objects_output, 'objects' (how many). Raises OSError for a file that cannot "
           "be read or written.")
      .def(py::pickle([](const SharedSegmenter& self) { return paramsToDict(self.core.params()); },
                      [](const py::dict& params) {
                        return std::make_unique<SharedSegmenter>(paramsFromKeywords(params, "Segmenter"));
                      }))
      .def("__repr__", &segmenterRepr);
}

}  // namespace floodplane::python
