// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "label_cloud.h"

#include <cstring>
#include <stdexcept>
#include <string>

#include "floodplane/io/label_palette.h"

namespace floodplane::conversion {

std::vector<PointField> labelCloudFields() {
  const auto f32 = static_cast<std::uint8_t>(FieldType::float32);
  return {{"x", 0, f32, 1},
          {"y", 4, f32, 1},
          {"z", 8, f32, 1},
          {"rgb", 12, f32, 1},
          {"label", 16, static_cast<std::uint8_t>(FieldType::uint32), 1}};
}

float packedLabelColor(std::uint32_t label) {
  const auto rgb = io::labelColor(label);
  const std::uint32_t packed = (std::uint32_t{rgb[0]} << 16) | (std::uint32_t{rgb[1]} << 8) | std::uint32_t{rgb[2]};
  float value;
  std::memcpy(&value, &packed, sizeof value);
  return value;
}

void writeLabelCloud(const PointGrid& grid, const std::vector<std::uint32_t>& labels,
                     const std::vector<std::uint32_t>& plane_labels, std::uint8_t* out) {
  if (labels.size() != grid.size()) {
    throw std::invalid_argument("writeLabelCloud: " + std::to_string(labels.size()) + " labels for " +
                                std::to_string(grid.size()) + " points");
  }
  // Index 0 is "no plane"; index k the published label of plane k and its colour, worked out
  // once a plane rather than once a pixel.
  std::vector<std::uint32_t> published(plane_labels.size() + 1, 0);
  std::vector<float> colors(plane_labels.size() + 1, packedLabelColor(0));
  for (std::size_t k = 0; k < plane_labels.size(); ++k) {
    published[k + 1] = plane_labels[k];
    colors[k + 1] = packedLabelColor(plane_labels[k]);
  }
  for (std::size_t i = 0; i < grid.size(); ++i, out += kLabelCloudPointStep) {
    const std::uint32_t k = labels[i];
    if (k >= published.size()) {
      throw std::invalid_argument("writeLabelCloud: label " + std::to_string(k) + " but only " +
                                  std::to_string(plane_labels.size()) + " planes");
    }
    std::memcpy(out, grid.point(i), 3 * sizeof(float));
    std::memcpy(out + 12, &colors[k], sizeof(float));
    std::memcpy(out + 16, &published[k], sizeof(std::uint32_t));
  }
}

}  // namespace floodplane::conversion
