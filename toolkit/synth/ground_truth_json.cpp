// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/ground_truth_json.h"

#include <nlohmann/json.hpp>

namespace floodplane::synth {

Eigen::Vector3d cameraUp(const RenderedFrame& frame) {
  return frame.world_from_camera.conjugate() * Eigen::Vector3d::UnitZ();
}

std::string groundTruthJson(const RenderedFrame& frame) {
  using nlohmann::ordered_json;  // keeps keys in the order written, for human readers
  ordered_json document;
  document["scene"] = frame.scene_name;
  document["description"] = frame.scene_description;
  document["sensor"] = sensorModelName(frame.sensor);
  if (frame.sensor != SensorModel::none) {
    document["seed"] = frame.seed;
  }
  // Only when some quirk is on, so that the files of plain renders stay as they were.
  if (frame.quirks.any()) {
    const SensorQuirks& quirks = frame.quirks;
    ordered_json section = ordered_json::object();
    if (quirks.range_bits > 0) {
      section["quantize_bits"] = quirks.range_bits;
      section["range_code_window"] = {quirks.range_code_near, quirks.range_code_far};
    }
    if (quirks.warp_amplitude > 0.0) {
      section["warp_mm"] = quirks.warp_amplitude * 1000.0;
      section["warp_seed"] = quirks.warp_seed;
    }
    if (quirks.speckle) section["speckle"] = true;
    if (quirks.bend_curvature != 0.0) {
      section["bend_per_m"] = quirks.bend_curvature;
      section["bend_reference_depth"] = quirks.bend_reference_depth;
    }
    document["sensor_quirks"] = std::move(section);
  }
  document["camera"] = {{"width", frame.intrinsics.width}, {"height", frame.intrinsics.height},
                        {"fx", frame.intrinsics.fx},       {"fy", frame.intrinsics.fy},
                        {"cx", frame.intrinsics.cx},       {"cy", frame.intrinsics.cy}};
  const Eigen::Vector3d up = cameraUp(frame);
  document["up"] = {up.x(), up.y(), up.z()};
  document["plane_equation"] =
      "n . P + d = 0 in the camera frame (x right, y down, z forward, metres); "
      "n has unit length and points towards the camera";
  ordered_json planes = ordered_json::array();
  for (const GroundTruthPlane& plane : frame.planes) {
    planes.push_back({{"id", plane.id},
                      {"primitive", plane.primitive},
                      {"face", plane.face},
                      {"normal", {plane.normal.x(), plane.normal.y(), plane.normal.z()}},
                      {"d", plane.d},
                      {"pixels", plane.pixel_count},
                      {"faces_camera", plane.faces_camera},
                      {"merged_into", plane.merged_into}});
  }
  document["planes"] = std::move(planes);
  // A scene named after a file whose name is not UTF-8: replaced as floodplane/io/json_text.h says.
  return document.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace floodplane::synth
