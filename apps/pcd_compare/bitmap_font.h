#pragma once
// A tiny built-in 5x7 bitmap font for panel titles, so the app needs no font library.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/rgb_image.h"

namespace pcd_compare {

constexpr std::size_t kGlyphWidth = 5;
constexpr std::size_t kGlyphHeight = 7;
constexpr std::size_t kGlyphAdvance = kGlyphWidth + 1;  // one column of spacing

/// Width in pixels of `text` drawn at `scale`.
std::size_t textWidth(const std::string& text, std::size_t scale);

/// Draws `text` with its top-left corner at (x, y), each font pixel a scale x scale block.
/// The font has capitals, digits and - _ . , : / ( ) | % + = ?; lower-case letters are drawn
/// as capitals and other characters as '?'. Pixels outside the image are clipped.
void drawText(floodplane::io::RgbImage& image, std::size_t x, std::size_t y, const std::string& text, std::size_t scale,
              std::array<std::uint8_t, 3> colour);

}  // namespace pcd_compare
