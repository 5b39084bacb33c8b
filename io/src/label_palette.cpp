// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/io/label_palette.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace floodplane::io {
namespace {

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

void checkGrid(const char* function, std::size_t labels, std::size_t has_point, std::size_t width, std::size_t height) {
  if (labels != width * height || has_point != width * height) {
    throw std::invalid_argument(std::string(function) + ": " + std::to_string(labels) + " labels and " +
                                std::to_string(has_point) + " point flags for a " + std::to_string(width) + "x" +
                                std::to_string(height) + " image");
  }
}

}  // namespace

std::array<std::uint8_t, 3> labelColor(std::uint32_t label) {
  if (label == 0) {
    return kNoPlaneColor;
  }
  const double turns = static_cast<double>(label) * kInverseGoldenRatio;
  const double hue = turns - std::floor(turns);
  return hsvToRgb(hue, kSaturations[label % kSaturations.size()], kValues[label % kValues.size()]);
}

RgbImage labelImage(const std::vector<std::uint32_t>& labels, const std::vector<std::uint8_t>& has_point,
                    std::size_t width, std::size_t height) {
  checkGrid("labelImage", labels.size(), has_point.size(), width, height);
  RgbImage image;
  image.width = width;
  image.height = height;
  image.pixels.reserve(labels.size() * 3);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const auto color = has_point[i] != 0 ? labelColor(labels[i]) : kHoleColor;
    image.pixels.insert(image.pixels.end(), color.begin(), color.end());
  }
  return image;
}

RgbImage overlayImage(const std::vector<std::uint32_t>& labels, const std::vector<std::uint8_t>& has_point,
                      const RgbImage& colours) {
  checkGrid("overlayImage", labels.size(), has_point.size(), colours.width, colours.height);
  if (colours.pixels.size() != labels.size() * 3) {
    throw std::invalid_argument("overlayImage: " + std::to_string(colours.pixels.size()) + " colour bytes for " +
                                std::to_string(labels.size()) + " pixels");
  }
  RgbImage image = colours;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (has_point[i] == 0) {
      std::copy(kHoleColor.begin(), kHoleColor.end(), image.pixels.begin() + static_cast<std::ptrdiff_t>(i * 3));
      continue;
    }
    if (labels[i] == 0) continue;
    const auto color = labelColor(labels[i]);
    for (std::size_t c = 0; c < 3; ++c) {
      std::uint8_t& pixel = image.pixels[i * 3 + c];
      pixel = static_cast<std::uint8_t>((pixel + color[c] + 1) / 2);
    }
  }
  return image;
}

}  // namespace floodplane::io
