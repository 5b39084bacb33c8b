// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "io/label_palette.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace floodplane::io {
namespace {

constexpr std::array<std::uint8_t, 3> kNoLabelColor{24, 24, 24};
constexpr double kInverseGoldenRatio = 0.6180339887498949;
constexpr std::array<double, 3> kSaturations{0.95, 0.6, 0.8};
constexpr std::array<double, 2> kValues{1.0, 0.8};

std::uint8_t toByte(double channel) { return static_cast<std::uint8_t>(std::lround(channel * 255.0)); }

// The standard hexcone HSV to RGB conversion; hue, saturation and value in [0, 1].
std::array<std::uint8_t, 3> hsvToRgb(double hue, double saturation, double value) {
  const double sector = hue * 6.0;
  const int index = static_cast<int>(sector) % 6;
  const double fraction = sector - std::floor(sector);
  const double p = value * (1.0 - saturation);
  const double q = value * (1.0 - saturation * fraction);
  const double t = value * (1.0 - saturation * (1.0 - fraction));
  switch (index) {
    case 0:
      return {toByte(value), toByte(t), toByte(p)};
    case 1:
      return {toByte(q), toByte(value), toByte(p)};
    case 2:
      return {toByte(p), toByte(value), toByte(t)};
    case 3:
      return {toByte(p), toByte(q), toByte(value)};
    case 4:
      return {toByte(t), toByte(p), toByte(value)};
    default:
      return {toByte(value), toByte(p), toByte(q)};
  }
}

}  // namespace

std::array<std::uint8_t, 3> labelColor(std::uint32_t label) {
  if (label == 0) {
    return kNoLabelColor;
  }
  const double turns = static_cast<double>(label) * kInverseGoldenRatio;
  const double hue = turns - std::floor(turns);
  return hsvToRgb(hue, kSaturations[label % kSaturations.size()], kValues[label % kValues.size()]);
}

RgbImage labelImage(const std::vector<std::uint32_t>& labels, std::size_t width, std::size_t height) {
  if (labels.size() != width * height) {
    throw std::invalid_argument("labelImage: " + std::to_string(labels.size()) + " labels for a " +
                                std::to_string(width) + "x" + std::to_string(height) + " image");
  }
  RgbImage image;
  image.width = width;
  image.height = height;
  image.pixels.reserve(labels.size() * 3);
  for (const std::uint32_t label : labels) {
    const auto color = labelColor(label);
    image.pixels.insert(image.pixels.end(), color.begin(), color.end());
  }
  return image;
}

}  // namespace floodplane::io
