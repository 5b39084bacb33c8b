// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "file_functions.h"

#include <pybind11/numpy.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>

#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "camera_intrinsics.h"
#include "errors.h"
#include "floodplane/io/depth_png.h"
#include "floodplane/io/input_frame.h"
#include "floodplane/io/pcd_file.h"
#include "floodplane/io/pcd_input.h"
#include "params_kwargs.h"
#include "point_arrays.h"

namespace floodplane::python {
namespace {

namespace py = pybind11;

// Runs `read` without the GIL; a std::runtime_error becomes OSError naming `path`.
template <typename Read>
auto readFile(const std::string& function, const std::string& path, Read&& read) -> decltype(read()) {
  std::optional<decltype(read())> value;
  std::string error;
  {
    py::gil_scoped_release release;
    try {
      value = read();
    } catch (const std::runtime_error& e) {
      error = e.what();
    }
  }
  if (!value) raiseFileError(FileAccess::read, function, "path", path, error);
  return std::move(*value);
}

// Runs `write` without the GIL; a std::runtime_error becomes OSError naming `path`.
template <typename Write>
void writeFile(const std::string& function, const std::string& path, Write&& write) {
  std::string error;
  {
    py::gil_scoped_release release;
    try {
      write();
    } catch (const std::runtime_error& e) {
      error = e.what();
    }
  }
  if (!error.empty()) raiseFileError(FileAccess::write, function, "path", path, error);
}

py::object readPcd(const std::filesystem::path& file, bool colors) {
  const std::string path = file.string();
  const io::InputFrame frame = readFile("read_pcd", path, [&] { return io::readPcdFrame(path); });
  const auto& cloud = frame.xyz;
  const py::ssize_t height = cloud.height;
  const py::ssize_t width = cloud.width;
  py::array_t<float> points({height, width, py::ssize_t{3}});
  float* out = points.mutable_data();
  for (const pcl::PointXYZ& p : cloud) {
    *out++ = p.x;
    *out++ = p.y;
    *out++ = p.z;
  }
  if (!colors) return std::move(points);
  if (!frame.xyzrgb) return py::make_tuple(points, py::none());
  py::array_t<std::uint8_t> rgb({height, width, py::ssize_t{3}});
  std::uint8_t* channel = rgb.mutable_data();
  for (const pcl::PointXYZRGB& p : *frame.xyzrgb) {
    *channel++ = p.r;
    *channel++ = p.g;
    *channel++ = p.b;
  }
  return py::make_tuple(points, rgb);
}

py::array_t<std::uint32_t> readLabelsPcd(const std::filesystem::path& file) {
  const std::string path = file.string();
  const io::InputFrame frame = readFile("read_labels_pcd", path, [&] { return io::readPcdFrame(path); });
  if (!frame.labels) {
    raiseFileError(FileAccess::read, "read_labels_pcd", "path", path, "the file has no uint32 label field");
  }
  return arrayCopy(*frame.labels, {py::ssize_t{frame.xyz.height}, py::ssize_t{frame.xyz.width}});
}

void writeLabelsPcd(const std::filesystem::path& file, py::handle points, py::handle labels, bool ascii) {
  const std::string path = file.string();
  const GridArray grid = gridFromArray(points, "write_labels_pcd: points");
  const std::vector<std::uint32_t> values = unsignedGrid(
      labels, grid.grid.height, grid.grid.width, std::numeric_limits<std::uint32_t>::max(), "write_labels_pcd: labels");
  pcl::PointCloud<pcl::PointXYZL> cloud(static_cast<std::uint32_t>(grid.grid.width),
                                        static_cast<std::uint32_t>(grid.grid.height));
  bool dense = true;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const float* p = grid.grid.point(i);
    cloud[i].x = p[0];
    cloud[i].y = p[1];
    cloud[i].z = p[2];
    cloud[i].label = values[i];
    dense = dense && grid.grid.isFinite(i);
  }
  cloud.is_dense = dense;
  const io::PcdEncoding encoding = ascii ? io::PcdEncoding::ascii : io::PcdEncoding::binary_compressed;
  writeFile("write_labels_pcd", path, [&] { io::savePcd(path, cloud, encoding); });
}

py::array_t<std::uint16_t> readDepthPng(const std::filesystem::path& file) {
  const std::string path = file.string();
  const io::DepthImage image = readFile("read_depth_png", path, [&] { return io::readDepthPng(path); });
  return arrayCopy(image.depth, {py::ssize_t{image.height}, py::ssize_t{image.width}});
}

void writeDepthPng(const std::filesystem::path& file, py::handle depth) {
  const std::string path = file.string();
  const py::array array = arrayFrom(depth, "write_depth_png: depth", "an integer array of shape (H, W)");
  if (array.ndim() != 2 || array.shape(0) < 1 || array.shape(1) < 1) {
    raiseValueError("write_depth_png: depth must have shape (H, W) with H, W >= 1, got " + shapeText(array));
  }
  const std::vector<std::uint32_t> values = unsignedGrid(
      array, array.shape(0), array.shape(1), std::numeric_limits<std::uint16_t>::max(), "write_depth_png: depth");
  io::DepthImage image;
  image.width = static_cast<int>(array.shape(1));
  image.height = static_cast<int>(array.shape(0));
  image.depth.assign(values.begin(), values.end());
  try {
    writeFile("write_depth_png", path, [&] { io::writeDepthPng(path, image); });
  } catch (const std::invalid_argument& e) {
    raiseValueError(std::string("write_depth_png: ") + e.what());
  }
}

py::array_t<float> depthToPoints(py::handle depth, py::handle intrinsics, py::handle fy, py::handle cx, py::handle cy,
                                 py::handle depth_scale) {
  const std::string function = "depth_to_points";
  const DepthArray image = depthArrayFrom(depth, function + ": depth");
  const Intrinsics pinhole = intrinsicsFrom(intrinsics, fy, cx, cy, function);
  pinhole.checkImageSize(image.array.shape(1), image.array.shape(0), function);
  const double scale =
      depth_scale.is_none() ? defaultDepthScale(image) : toDouble(depth_scale, function + ": depth_scale");
  const io::DepthCamera camera = pinhole.camera(scale, function);
  return pointsFromDepth(image, camera, function + ": depth");
}

// fx, fy, cx, cy of any form of intrinsics, for what must travel as plain numbers
// (floodplane.distributed's tasks).
py::tuple pinholeTuple(py::handle intrinsics, const std::string& function) {
  const Intrinsics pinhole = intrinsicsFrom(intrinsics, function);
  return py::make_tuple(pinhole.fx, pinhole.fy, pinhole.cx, pinhole.cy);
}

}  // namespace

void bindFileFunctions(py::module_& m) {
  m.def("read_pcd", &readPcd, py::arg("path"), py::kw_only(), py::arg("colors") = false,
        "Reads an organized PCD file (x y z as float or double): float32 (H, W, 3) in the file's coordinates, "
        "NaN where there is no return. With colors=True, a pair (points, colors): colors uint8 (H, W, 3), R G B "
        "of the file's rgb or rgba field, or None when it has none. segment() takes the sensor to be at the "
        "origin; a file whose VIEWPOINT puts it elsewhere (rare for camera frames) needs that translation "
        "subtracted first, or segment_file(), which applies it as pcd_segment does. Raises OSError "
        "(FileNotFoundError) for a file that cannot be read as an organized cloud.");
  m.def("read_labels_pcd", &readLabelsPcd, py::arg("path"),
        "Reads the uint32 label field of an organized PCD file (pcd_segment's and write_labels_pcd's outputs, "
        "pcd_synth's ground truth): uint32 (H, W). Raises OSError when there is none.");
  m.def("write_labels_pcd", &writeLabelsPcd, py::arg("path"), py::arg("points"), py::arg("labels"), py::kw_only(),
        py::arg("ascii") = false,
        "Writes points (H, W, 3) and labels (H, W) as an organized PCD file with fields x y z label (binary "
        "compressed, or text with ascii=True), atomically: a failed write leaves no partial file.");
  m.def("read_depth_png", &readDepthPng, py::arg("path"),
        "Reads a 16-bit greyscale PNG depth image: uint16 (H, W) in the camera's units. Raises OSError for a "
        "broken file or a PNG that is not a depth image (8-bit, colour, alpha).");
  m.def("write_depth_png", &writeDepthPng, py::arg("path"), py::arg("depth"),
        "Writes depth (H, W), integers in [0, 65535], as a 16-bit greyscale PNG, atomically.");
  m.def("depth_to_points", &depthToPoints, py::arg("depth"), py::arg("intrinsics"), py::arg("fy") = py::none(),
        py::arg("cx") = py::none(), py::arg("cy") = py::none(), py::arg("depth_scale") = py::none(),
        "depth_to_points(depth, fx, fy, cx, cy, depth_scale=None) or depth_to_points(depth, intrinsics, "
        "depth_scale=None): back-projects a depth image through a pinhole camera: float32 (H, W, 3). depth is "
        "(H, W) or (H, W, 1), of integer units (Kinect, RealSense, ROS 16UC1: millimetres) or floating point "
        "(Open3D's depth images, ROS 32FC1: metres); depth_scale is units per metre, by default 1000 for "
        "integers and 1 for floats. A depth of 0 (and a NaN or infinite one) is no return: NaN. intrinsics: "
        "fx, fy, cx, cy [pixels], a sequence of those four, a 3 x 3 matrix K (or its 9 values row by row, as "
        "ROS's CameraInfo.k), or an object with "
        "intrinsic_matrix such as Open3D's PinholeCameraIntrinsic (whose width and height must then be the "
        "image's). The same points as pcd_segment gives a depth PNG.");
  m.def("_pinhole", &pinholeTuple, py::arg("intrinsics"), py::arg("function"),
        "(fx, fy, cx, cy) of any form of intrinsics; `function` names the caller in messages.");
}

}  // namespace floodplane::python
