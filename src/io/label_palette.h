// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Colours for label images: label 0 (no plane) near-black, every other label a bright colour
// well separated from the labels numbered near it.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "io/rgb_image.h"

namespace floodplane::io {

/// The colour of `label`. Label 0 is near-black. Label k > 0 takes the hue k / phi (mod 1),
/// the golden-ratio step that keeps any run of consecutive labels far apart on the colour
/// wheel, with saturation cycling over three levels and value over two so that labels whose
/// hues come close again differ in brightness or saturation. Deterministic: the same label
/// always has the same colour.
std::array<std::uint8_t, 3> labelColor(std::uint32_t label);

/// Colours a row-major label grid. Throws std::invalid_argument if `labels` does not hold
/// width * height entries.
RgbImage labelImage(const std::vector<std::uint32_t>& labels, std::size_t width, std::size_t height);

}  // namespace floodplane::io
