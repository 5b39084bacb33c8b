// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "comparison_image.h"

#include <cairo.h>

#include <algorithm>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "floodplane/io/label_palette.h"
#include "view/plane_view.h"

namespace pcd_compare {

namespace {

constexpr std::uint32_t kUnmatchedLabelOffset = 1000;
constexpr std::size_t kTitleHeight = 22;  // pixels of the strip above each panel
constexpr double kTitleFontSize = 15.0;   // pixels
constexpr double kTitleMargin = 4.0;      // pixels left of the text
constexpr std::size_t kPanelGap = 4;

// Images of one size side by side, each with its title in a strip above. Throws
// std::invalid_argument if there are none or their sizes differ.
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
  floodplane::io::RgbImage image;
  image.width = images.size() * width + (images.size() - 1) * kPanelGap;
  image.height = kTitleHeight + height;
  image.pixels.assign(image.width * image.height * 3, 255);  // white
  // The titles: black text drawn by cairo as coverage (an A8 image surface: grey-scale
  // antialiasing, no colour fringes, no X display), each clipped to its panel's width.
  const std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> strip(
      cairo_image_surface_create(CAIRO_FORMAT_A8, static_cast<int>(image.width), kTitleHeight), cairo_surface_destroy);
  const std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cairo(cairo_create(strip.get()), cairo_destroy);
  cairo_select_font_face(cairo.get(), "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cairo.get(), kTitleFontSize);
  cairo_font_extents_t font;
  cairo_font_extents(cairo.get(), &font);
  for (std::size_t k = 0; k < images.size(); ++k) {
    const std::size_t left = k * (width + kPanelGap);
    for (std::size_t y = 0; y < height; ++y) {
      std::copy_n(images[k].second.pixels.begin() + static_cast<std::ptrdiff_t>(y * width * 3), width * 3,
                  image.pixels.begin() + static_cast<std::ptrdiff_t>(((kTitleHeight + y) * image.width + left) * 3));
    }
    cairo_reset_clip(cairo.get());
    cairo_rectangle(cairo.get(), static_cast<double>(left), 0.0, static_cast<double>(width), kTitleHeight);
    cairo_clip(cairo.get());
    // The baseline that centres the font's ascent and descent in the strip.
    cairo_move_to(cairo.get(), static_cast<double>(left) + kTitleMargin,
                  (kTitleHeight + font.ascent - font.descent) / 2.0);
    cairo_show_text(cairo.get(), images[k].first.c_str());
  }
  cairo_surface_flush(strip.get());
  if (cairo_status(cairo.get()) != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string("titledImages: cairo: ") + cairo_status_to_string(cairo_status(cairo.get())));
  }
  const unsigned char* coverage = cairo_image_surface_get_data(strip.get());
  const auto stride = static_cast<std::size_t>(cairo_image_surface_get_stride(strip.get()));
  for (std::size_t y = 0; y < kTitleHeight; ++y) {
    for (std::size_t x = 0; x < image.width; ++x) {
      std::fill_n(image.pixels.begin() + static_cast<std::ptrdiff_t>((y * image.width + x) * 3), 3,
                  static_cast<std::uint8_t>(255 - coverage[y * stride + x]));
    }
  }
  return image;
}

// Labels that give `predicted` colours comparable with the ground truth's. Separate
// segmentations number their planes arbitrarily, so coloured by their own labels the same
// wall would get a different colour in every panel. Instead each predicted segment takes
// the label of the ground-truth plane it overlaps most (over valid pixels), and segments on
// no plane keep their own label, shifted past any plausible ground-truth label so that they
// do not borrow a plane's colour. Label 0 stays 0.
std::vector<std::uint32_t> coloursMatchedToGroundTruth(const std::vector<std::uint32_t>& predicted,
                                                       const std::vector<std::uint32_t>& ground_truth,
                                                       const std::vector<std::uint8_t>& valid) {
  // overlap[p][g] = pixels of segment p on plane g.
  std::map<std::uint32_t, std::map<std::uint32_t, std::size_t>> overlap;
  for (std::size_t i = 0; i < predicted.size(); ++i) {
    if (predicted[i] != 0 && ground_truth[i] != 0 && valid[i] != 0) {
      ++overlap[predicted[i]][ground_truth[i]];
    }
  }
  std::map<std::uint32_t, std::uint32_t> colour_of = {{0, 0}};
  for (const auto& [segment, planes] : overlap) {
    const auto best = std::max_element(planes.begin(), planes.end(),
                                       [](const auto& a, const auto& b) { return a.second < b.second; });
    colour_of[segment] = best->first;
  }
  std::vector<std::uint32_t> colours(predicted.size());
  for (std::size_t i = 0; i < predicted.size(); ++i) {
    const auto found = colour_of.find(predicted[i]);
    colours[i] = found != colour_of.end() ? found->second : predicted[i] + kUnmatchedLabelOffset;
  }
  return colours;
}

}  // namespace

floodplane::io::RgbImage comparisonImage(const InputCloud& input, const std::vector<LabelledPanel>& panels,
                                         std::size_t min_points, bool in_3d) {
  const Cloud& cloud = *input.cloud;
  std::vector<std::pair<std::string, floodplane::io::RgbImage>> images;
  // `segments` (a method's own labels, one segment each) coloured as `colours` says.
  const auto add = [&](const std::string& title, const std::vector<std::uint32_t>& colours,
                       const std::vector<std::uint32_t>& segments) {
    if (!in_3d) {
      images.emplace_back(title, floodplane::io::labelImage(colours, input.valid, cloud.width, cloud.height));
      return;
    }
    floodplane::view::PlaneScene scene;
    scene.cloud = input.cloud;
    scene.colour_labels = colours;
    scene.planes = floodplane::view::planeMarkersFromLabels(cloud, segments, colours, min_points);
    scene.show_plane_text = false;  // segment numbers differ between methods and mean nothing here
    images.emplace_back(title,
                        floodplane::view::renderImage(scene, floodplane::view::CameraView::oblique,
                                                      static_cast<int>(cloud.width), static_cast<int>(cloud.height)));
  };
  if (input.ground_truth) {
    // Pixels without a point are holes (no plane in 3-D), as they are in the predictions.
    std::vector<std::uint32_t> shown = *input.ground_truth;
    for (std::size_t i = 0; i < shown.size(); ++i) shown[i] = input.valid[i] != 0 ? shown[i] : 0;
    add("ground truth", shown, shown);
  }
  for (const auto& [title, labels] : panels) {
    add(title, input.ground_truth ? coloursMatchedToGroundTruth(labels, *input.ground_truth, input.valid) : labels,
        labels);
  }
  return titledImages(images);
}

}  // namespace pcd_compare
