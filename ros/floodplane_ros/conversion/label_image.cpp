// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "label_image.h"

#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "byte_order.h"

namespace floodplane::conversion {

bool labelImageIsBigEndian() { return hostIsBigEndian(); }

void writeLabelImage(const std::vector<std::uint32_t>& labels, const std::vector<std::uint32_t>& plane_labels,
                     std::uint8_t* out) {
  // Index 0 is "no plane"; index k the published label of plane k, checked once a plane.
  std::vector<std::int32_t> published(plane_labels.size() + 1, 0);
  for (std::size_t k = 0; k < plane_labels.size(); ++k) {
    if (plane_labels[k] > static_cast<std::uint32_t>(std::numeric_limits<std::int32_t>::max())) {
      throw std::invalid_argument("writeLabelImage: label " + std::to_string(plane_labels[k]) +
                                  " does not fit a 32SC1 pixel");
    }
    published[k + 1] = static_cast<std::int32_t>(plane_labels[k]);
  }
  for (std::size_t i = 0; i < labels.size(); ++i, out += kLabelImageBytesPerPixel) {
    const std::uint32_t k = labels[i];
    if (k >= published.size()) {
      throw std::invalid_argument("writeLabelImage: label " + std::to_string(k) + " but only " +
                                  std::to_string(plane_labels.size()) + " planes");
    }
    std::memcpy(out, &published[k], kLabelImageBytesPerPixel);
  }
}

}  // namespace floodplane::conversion
