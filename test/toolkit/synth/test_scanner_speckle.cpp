// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Speckle along the scanner's depth discontinuities and shadow edges (scanner_speckle.h): a box
// before a wall rendered with and without it. The band near the edges is worked out here from
// two other renders (the exact depths, and the projector's shadow in a scanner frame that loses
// nothing by chance); the speckle changes pixels only inside it, adds returns off every plane
// near their surface, and removes returns in short runs down the columns, at about the rates of
// its parameters. Then the band of the library on a hand-made picture, and determinism.

#include "synth/scanner_speckle.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "synth/renderer.h"

namespace {

using namespace floodplane::synth;

bool isNaN(const Eigen::Vector3f& point) { return std::isnan(point.z()); }

// A box hanging 0.2 m before a wall at 1 m, a little left of the centre: its shadow falls on
// the wall to its left.
Scene boxBeforeWall() {
  Scene scene;
  scene.name = "test";
  scene.source = "test scene";
  scene.intrinsics = scannerIntrinsics();
  const Eigen::Vector3d low(-0.05, -0.04, 0.75);
  const Eigen::Vector3d high(0.03, 0.05, 0.85);
  scene.primitives = {
      {"wall", Rectangle{Eigen::Vector3d(0, 0, 1.0), Eigen::Vector3d(10, 0, 0), Eigen::Vector3d(0, 10, 0)}},
      {"box", Box{(low + high) / 2, high - low, Eigen::Matrix3d::Identity()}}};
  return scene;
}

// The scanner with its projector's field wider than the camera's, so that every unlit pixel
// lies in a shadow.
ScannerParams wideField() {
  ScannerParams params;
  params.projector_half_width = 10.0;
  params.projector_half_height = 10.0;
  return params;
}

RenderedFrame render(const Scene& scene, SensorModel sensor, const ScannerParams& params, std::uint64_t seed = 1) {
  RenderSettings settings;
  settings.sensor = sensor;
  settings.seed = seed;
  settings.scanner = params;
  return renderScene(scene, settings);
}

// The band, worked out from renders: the exact depths (sensor none) and the shadow (a scanner
// frame that loses returns to shadows only). Two 4-neighbours meet at an edge when their depths
// differ by over 1 % or one is lit and the other in shadow; the band is the edges widened by
// 2 pixels.
std::vector<bool> bandFromRenders(const Scene& scene) {
  const RenderedFrame exact = render(scene, SensorModel::none, wideField());
  ScannerParams shadows_only = wideField();
  shadows_only.dropout_probability = 0.0;
  shadows_only.full_return_signal = -0.5;
  shadows_only.no_return_signal = -1.0;
  const RenderedFrame lit = render(scene, SensorModel::scanner, shadows_only);
  const int width = scene.intrinsics.width;
  const int height = scene.intrinsics.height;
  const auto index = [width](int u, int v) { return static_cast<std::size_t>(v) * width + u; };
  const auto edge = [&](std::size_t a, std::size_t b) {
    const double za = exact.points[a].z();
    const double zb = exact.points[b].z();
    return std::abs(za - zb) > 0.01 * std::min(za, zb) || isNaN(lit.points[a]) != isNaN(lit.points[b]);
  };
  std::vector<bool> at_edge(exact.points.size(), false);
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      if (u + 1 < width && edge(index(u, v), index(u + 1, v))) at_edge[index(u, v)] = at_edge[index(u + 1, v)] = true;
      if (v + 1 < height && edge(index(u, v), index(u, v + 1))) at_edge[index(u, v)] = at_edge[index(u, v + 1)] = true;
    }
  }
  std::vector<bool> band(at_edge.size(), false);
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      if (!at_edge[index(u, v)]) continue;
      for (int y = std::max(0, v - 2); y <= std::min(height - 1, v + 2); ++y) {
        for (int x = std::max(0, u - 2); x <= std::min(width - 1, u + 2); ++x) band[index(x, y)] = true;
      }
    }
  }
  return band;
}

TEST(ScannerSpeckle, ChangesPixelsOnlyNearEdgesAddingReturnsOffThePlanesAndLosingStripes) {
  const Scene scene = boxBeforeWall();
  ScannerParams params = wideField();
  const RenderedFrame plain = render(scene, SensorModel::scanner, params);
  params.speckle = true;
  const RenderedFrame speckled = render(scene, SensorModel::scanner, params);
  const RenderedFrame exact = render(scene, SensorModel::none, params);
  const std::vector<bool> band = bandFromRenders(scene);
  const auto width = static_cast<std::size_t>(scene.intrinsics.width);

  std::size_t band_returns = 0;
  std::size_t band_without_return = 0;
  std::size_t added = 0;
  std::size_t lost = 0;
  std::size_t lost_in_runs = 0;  // with a lost pixel above or below
  for (std::size_t i = 0; i < plain.points.size(); ++i) {
    const bool before = !isNaN(plain.points[i]);
    const bool after = !isNaN(speckled.points[i]);
    if (band[i]) ++(before ? band_returns : band_without_return);
    if (!band[i]) {
      // Outside the band the frame is the plain one, bit for bit.
      ASSERT_EQ(before, after) << "pixel " << i;
      if (before) {
        ASSERT_EQ(plain.points[i], speckled.points[i]) << "pixel " << i;
      }
      ASSERT_EQ(plain.labels[i], speckled.labels[i]) << "pixel " << i;
      continue;
    }
    if (before && after) {
      ASSERT_EQ(plain.points[i], speckled.points[i]) << "pixel " << i;  // returns kept are untouched
    } else if (!before && after) {
      ++added;
      // Off every plane, near the surface the ray hits: within 2 cm (z / 1 m)^2 and a step.
      EXPECT_EQ(speckled.labels[i], 0U) << "pixel " << i;
      const double z = exact.points[i].z();
      EXPECT_LE(std::abs(speckled.points[i].z() - z), 0.02 * z * z + 0.0013 * z * z) << "pixel " << i;
    } else if (before && !after) {
      ++lost;
      EXPECT_EQ(speckled.labels[i], 0U);
      const bool above = i >= width && !isNaN(plain.points[i - width]) && isNaN(speckled.points[i - width]);
      const bool below =
          i + width < plain.points.size() && !isNaN(plain.points[i + width]) && isNaN(speckled.points[i + width]);
      lost_in_runs += above || below ? 1 : 0;
    }
  }
  ASSERT_GT(band_returns, 2000U);
  ASSERT_GT(band_without_return, 1000U);
  // Spurious returns: 10 % of the band's pixels without a return (all of them hit the wall or
  // the box); binomial spread about 1 %.
  EXPECT_NEAR(static_cast<double>(added) / static_cast<double>(band_without_return), 0.1, 0.03);
  // Lost: a stripe starts at 6 % of the returns and takes 2-6 pixels down the column, fewer
  // where it leaves the band: between 10 % and 25 % of the band's returns.
  const double lost_share = static_cast<double>(lost) / static_cast<double>(band_returns);
  EXPECT_GT(lost_share, 0.10);
  EXPECT_LT(lost_share, 0.25);
  // Stripes, not single pixels.
  EXPECT_GT(static_cast<double>(lost_in_runs) / static_cast<double>(lost), 0.8);

  // The listing counts what the labels hold.
  std::vector<std::size_t> counts(speckled.planes.size() + 1, 0);
  for (const std::uint32_t label : speckled.labels) ++counts[label];
  for (const GroundTruthPlane& plane : speckled.planes) EXPECT_EQ(plane.pixel_count, counts[plane.id]);
  EXPECT_TRUE(speckled.quirks.speckle);
  EXPECT_FALSE(plain.quirks.speckle);
}

TEST(ScannerSpeckle, IsTheSameForTheSameSeedAndAnotherForAnother) {
  const Scene scene = boxBeforeWall();
  ScannerParams params = wideField();
  params.speckle = true;
  const RenderedFrame first = render(scene, SensorModel::scanner, params, 3);
  const RenderedFrame again = render(scene, SensorModel::scanner, params, 3);
  const RenderedFrame other = render(scene, SensorModel::scanner, params, 4);
  ASSERT_EQ(first.points.size(), again.points.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < first.points.size(); ++i) {
    ASSERT_EQ(isNaN(first.points[i]), isNaN(again.points[i]));
    if (!isNaN(first.points[i])) {
      ASSERT_EQ(first.points[i], again.points[i]);
    }
    differing += isNaN(first.points[i]) != isNaN(other.points[i]) ? 1 : 0;
  }
  EXPECT_GT(differing, 100U);
}

// The library's band on a picture drawn here, 12 x 8 pixels: a surface at 1 m with a step to
// 1.5 m from column 6 on, a shadow over columns 1-2 of rows 0-1, and the projector's field
// ending at row 7 (no edge there). Band radius 1.
TEST(ScannerSpeckle, TheBandIsEveryPixelNearADepthStepOrAShadowEdgeButNotTheFieldsEdge) {
  const int width = 12;
  const int height = 8;
  std::vector<double> depth(width * height, 1.0);
  std::vector<ProjectorLight> light(depth.size(), ProjectorLight::lit);
  for (int v = 0; v < height; ++v) {
    for (int u = 6; u < width; ++u) depth[v * width + u] = 1.5;
  }
  for (int v = 0; v < 2; ++v) {
    for (int u = 1; u < 3; ++u) light[v * width + u] = ProjectorLight::shadowed;
  }
  for (int u = 0; u < width; ++u) light[7 * width + u] = ProjectorLight::outside_field;
  ScannerParams params;
  params.speckle_band = 1;
  const std::vector<std::uint8_t> band = scannerSpeckleBand(depth, light, params, width, height);
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      // The step lies between columns 5 and 6, in every row: columns 4 to 7 are in the band.
      // The shadow's edge: its four pixels and their lit neighbours, columns 0-3 of rows 0-1
      // and columns 1-2 of row 2; widened by one pixel that is columns 0-4 of rows 0-2 and
      // columns 0-3 of row 3. The field's edge below row 6 adds nothing.
      const bool near_step = u >= 4 && u <= 7;
      const bool near_shadow = (u <= 4 && v <= 2) || (u <= 3 && v == 3);
      const bool expected = near_step || near_shadow;
      EXPECT_EQ(band[v * width + u] != 0, expected) << "pixel " << u << ", " << v;
    }
  }
}

}  // namespace
