#include "comparison_image.h"

#include <cairo.h>

#include <algorithm>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "io/label_palette.h"

namespace pcd_compare {

namespace {

constexpr std::uint32_t kUnmatchedLabelOffset = 1000;
constexpr std::size_t kTitleHeight = 22;  // pixels of the strip above each panel
constexpr double kTitleFontSize = 15.0;   // pixels
constexpr double kTitleMargin = 4.0;      // pixels left of the text
constexpr std::size_t kPanelGap = 4;

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

}  // namespace pcd_compare
