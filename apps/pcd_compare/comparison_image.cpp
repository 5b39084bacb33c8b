#include "comparison_image.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "bitmap_font.h"
#include "io/label_palette.h"

namespace pcd_compare {

namespace {

constexpr std::uint32_t kUnmatchedLabelOffset = 1000;
constexpr std::size_t kTitleScale = 2;
constexpr std::size_t kTitleMargin = 4;
constexpr std::size_t kPanelGap = 4;
constexpr std::array<std::uint8_t, 3> kBackground = {255, 255, 255};
constexpr std::array<std::uint8_t, 3> kTitleColour = {0, 0, 0};

}  // namespace

std::vector<std::uint32_t> coloursMatchedToGroundTruth(const std::vector<std::uint32_t>& predicted,
                                                       const std::vector<std::uint32_t>& ground_truth,
                                                       const std::vector<std::uint8_t>& valid) {
  if (ground_truth.empty()) {
    return predicted;
  }
  // overlap[p][g] = pixels of segment p on plane g.
  std::map<std::uint32_t, std::map<std::uint32_t, std::size_t>> overlap;
  for (std::size_t i = 0; i < predicted.size(); ++i) {
    if (predicted[i] != 0 && ground_truth[i] != 0 && valid[i] != 0) {
      ++overlap[predicted[i]][ground_truth[i]];
    }
  }
  std::map<std::uint32_t, std::uint32_t> colour_of;
  for (const auto& [segment, planes] : overlap) {
    const auto best = std::max_element(planes.begin(), planes.end(),
                                       [](const auto& a, const auto& b) { return a.second < b.second; });
    colour_of[segment] = best->first;
  }
  std::vector<std::uint32_t> colours(predicted.size(), 0);
  for (std::size_t i = 0; i < predicted.size(); ++i) {
    if (predicted[i] == 0) {
      continue;
    }
    const auto found = colour_of.find(predicted[i]);
    colours[i] = found != colour_of.end() ? found->second : predicted[i] + kUnmatchedLabelOffset;
  }
  return colours;
}

floodplane::io::RgbImage comparisonImage(const std::vector<Panel>& panels, std::size_t width, std::size_t height) {
  if (panels.empty()) {
    throw std::invalid_argument("comparisonImage: no panels");
  }
  std::vector<std::pair<std::string, floodplane::io::RgbImage>> images;
  for (const Panel& panel : panels) {
    images.emplace_back(panel.title, floodplane::io::labelImage(panel.colour_labels, width, height));
  }
  return titledImages(images);
}

floodplane::io::RgbImage titledImages(const std::vector<std::pair<std::string, floodplane::io::RgbImage>>& images) {
  if (images.empty()) {
    throw std::invalid_argument("titledImages: no images");
  }
  const std::size_t width = images.front().second.width;
  const std::size_t height = images.front().second.height;
  for (const auto& [title, panel] : images) {
    if (panel.width != width || panel.height != height || panel.pixels.size() != width * height * 3) {
      throw std::invalid_argument("titledImages: the image of '" + title + "' is not " + std::to_string(width) + "x" +
                                  std::to_string(height));
    }
  }
  const std::size_t strip = kGlyphHeight * kTitleScale + 2 * kTitleMargin;
  floodplane::io::RgbImage image;
  image.width = images.size() * width + (images.size() - 1) * kPanelGap;
  image.height = strip + height;
  image.pixels.resize(image.width * image.height * 3);
  for (std::size_t i = 0; i < image.pixels.size(); i += 3) {
    std::copy(kBackground.begin(), kBackground.end(), image.pixels.begin() + static_cast<std::ptrdiff_t>(i));
  }
  for (std::size_t k = 0; k < images.size(); ++k) {
    const std::size_t left = k * (width + kPanelGap);
    const floodplane::io::RgbImage& panel = images[k].second;
    for (std::size_t y = 0; y < height; ++y) {
      std::copy_n(panel.pixels.begin() + static_cast<std::ptrdiff_t>(y * width * 3), width * 3,
                  image.pixels.begin() + static_cast<std::ptrdiff_t>(((strip + y) * image.width + left) * 3));
    }
    // Titles too long for the panel are cut at the panel's edge by drawing into a copy
    // limited to the panel's width.
    floodplane::io::RgbImage title;
    title.width = width;
    title.height = strip;
    title.pixels.resize(width * strip * 3);
    for (std::size_t i = 0; i < title.pixels.size(); i += 3) {
      std::copy(kBackground.begin(), kBackground.end(), title.pixels.begin() + static_cast<std::ptrdiff_t>(i));
    }
    drawText(title, kTitleMargin, kTitleMargin, images[k].first, kTitleScale, kTitleColour);
    for (std::size_t y = 0; y < strip; ++y) {
      std::copy_n(title.pixels.begin() + static_cast<std::ptrdiff_t>(y * width * 3), width * 3,
                  image.pixels.begin() + static_cast<std::ptrdiff_t>((y * image.width + left) * 3));
    }
  }
  return image;
}

}  // namespace pcd_compare
