// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Colours for label images: every plane label a bright colour well separated from the labels
// numbered near it, "no plane" (label 0) near-black and pixels without a point (no depth: a
// hole) white, so that a label image tells the three apart; and the labels blended over a
// frame's own colours.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "floodplane/io/rgb_image.h"

namespace floodplane::io {

/// The colour of label 0, "no plane": a finite point on no plane.
inline constexpr std::array<std::uint8_t, 3> kNoPlaneColor{24, 24, 24};
/// The colour of a pixel without a finite point (the sensor saw nothing): white, which no
/// plane's colour comes near (every plane colour has a channel of at most 102).
inline constexpr std::array<std::uint8_t, 3> kHoleColor{255, 255, 255};

/// The colour of `label`. Label 0 is kNoPlaneColor. Label k > 0 takes the hue k / phi (mod 1),
/// the golden-ratio step that keeps any run of consecutive labels far apart on the colour
/// wheel, with saturation cycling over three levels and value over two so that labels whose
/// hues come close again differ in brightness or saturation. Deterministic: the same label
/// always has the same colour.
std::array<std::uint8_t, 3> labelColor(std::uint32_t label);

/// Colours a row-major label grid: labelColor of each pixel's label, kHoleColor where
/// `has_point` is 0 (whatever the label). Throws std::invalid_argument if `labels` or
/// `has_point` does not hold width * height entries.
RgbImage labelImage(const std::vector<std::uint32_t>& labels, const std::vector<std::uint8_t>& has_point,
                    std::size_t width, std::size_t height);

/// The labels over `colours`, the frame's own picture on the same grid: each pixel of a plane
/// half its labelColor and half its own colour, pixels on no plane their own colour, so the
/// planes stand out on the scene as the camera saw it; holes kHoleColor as in labelImage (a
/// sensor's colour where it measured no depth is often a fill value). Throws
/// std::invalid_argument if `labels` or `has_point` does not hold a value per pixel of
/// `colours`.
RgbImage overlayImage(const std::vector<std::uint32_t>& labels, const std::vector<std::uint8_t>& has_point,
                      const RgbImage& colours);

}  // namespace floodplane::io
