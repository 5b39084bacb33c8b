// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "file_segmentation.h"

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "floodplane/io/atomic_file.h"
#include "floodplane/io/input_frame.h"
#include "floodplane/io/labelled_cloud.h"
#include "floodplane/io/pcd_file.h"
#include "floodplane/object_segmentation.h"

namespace floodplane::python {
namespace {

// The points as the core wants them: in place when the sensor is at the origin (PointXYZ is
// x y z and a padding float), otherwise shifted there, as the PCL class does.
PointGrid sensorFrameGrid(const pcl::PointCloud<pcl::PointXYZ>& cloud, std::vector<float>& shifted) {
  PointGrid grid;
  grid.width = static_cast<int>(cloud.width);
  grid.height = static_cast<int>(cloud.height);
  const Eigen::Vector3f origin = cloud.sensor_origin_.head<3>();
  if (origin.isZero(0.0f)) {
    grid.data = &cloud[0].x;
    grid.stride = sizeof(pcl::PointXYZ) / sizeof(float);
    return grid;
  }
  shifted.resize(cloud.size() * 3);
  float* out = shifted.data();
  for (const pcl::PointXYZ& p : cloud) {
    *out++ = p.x - origin.x();
    *out++ = p.y - origin.y();
    *out++ = p.z - origin.z();
  }
  grid.data = shifted.data();
  grid.stride = 3;
  return grid;
}

}  // namespace

FileSummary segmentFile(Segmenter& segmenter, const std::string& input, const std::string& output,
                        const std::optional<DepthInput>& depth, const std::string& objects_output) {
  std::optional<io::DepthCamera> camera;
  if (depth) camera = depth->camera;
  if (camera && !camera->problem().empty()) throw std::invalid_argument(camera->problem());
  io::InputFrame frame;
  try {
    frame = io::loadInputFrame(input, camera);
  } catch (const std::runtime_error& error) {
    throw InputFileError(error.what());
  }
  if (depth && depth->width && depth->height && io::isDepthImagePath(input) &&
      (frame.xyz.width != static_cast<std::uint32_t>(*depth->width) ||
       frame.xyz.height != static_cast<std::uint32_t>(*depth->height))) {
    throw InputFileError("the depth image is " + std::to_string(frame.xyz.width) + " x " +
                         std::to_string(frame.xyz.height) + ", the intrinsics are for " +
                         std::to_string(*depth->width) + " x " + std::to_string(*depth->height) + " (width x height)");
  }
  std::vector<float> shifted;
  const PointGrid grid = sensorFrameGrid(frame.xyz, shifted);
  Segmenter::Options options;
  options.refine = true;  // pcd_segment's segmentAndRefine
  const auto start = std::chrono::steady_clock::now();
  const Segmentation& result = segmenter.segment(grid, options);
  const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
  std::optional<ObjectSegmentation> objects;
  if (!objects_output.empty()) objects = segmentObjects(grid, result);
  try {
    // Both files or neither, as pcd_segment writes an input's outputs.
    io::AtomicFileGroup files;
    if (frame.xyzrgb) {
      files.add(output, io::encodePcd(io::labelledCloud<pcl::PointXYZRGBL>(*frame.xyzrgb, result.labels)));
    } else {
      files.add(output, io::encodePcd(io::labelledCloud<pcl::PointXYZL>(frame.xyz, result.labels)));
    }
    if (objects)
      files.add(objects_output, io::encodePcd(io::labelledCloud<pcl::PointXYZL>(frame.xyz, objects->labels)));
    files.commit();
  } catch (const std::runtime_error& error) {
    throw OutputFileError(error.what());
  }
  FileSummary summary{result.width, result.height, result.planes.size(), elapsed.count(), std::nullopt};
  if (objects) summary.objects = objects->objects.size();
  return summary;
}

}  // namespace floodplane::python
