// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The back-projection of depth images: the pinhole formula, zero as no return, and the
// checks of the intrinsics.

#include "floodplane/io/depth_camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace {

using floodplane::io::backProjectDepth;
using floodplane::io::backProjectPixel;
using floodplane::io::DepthCamera;

DepthCamera tumCamera() { return {525.0, 520.0, 319.5, 239.5, 5000.0}; }

TEST(DepthCamera, BackProjectsAPixelThroughThePinholeModel) {
  float p[3];
  backProjectPixel(100, 400, 10000.0, tumCamera(), p);  // 2 m
  EXPECT_FLOAT_EQ(p[2], 2.0f);
  EXPECT_FLOAT_EQ(p[0], static_cast<float>((100 - 319.5) * 2.0 / 525.0));
  EXPECT_FLOAT_EQ(p[1], static_cast<float>((400 - 239.5) * 2.0 / 520.0));
}

TEST(DepthCamera, PutsThePrincipalPointOnTheOpticalAxis) {
  DepthCamera camera{500.0, 500.0, 12.0, 7.0, 1000.0};
  float p[3];
  backProjectPixel(12, 7, 1234.0, camera, p);
  EXPECT_EQ(p[0], 0.0f);
  EXPECT_EQ(p[1], 0.0f);
  EXPECT_FLOAT_EQ(p[2], 1.234f);
}

TEST(DepthCamera, TurnsZeroDepthIntoNoReturn) {
  float p[3] = {1.0f, 1.0f, 1.0f};
  backProjectPixel(3, 4, 0.0, tumCamera(), p);
  EXPECT_TRUE(std::isnan(p[0]) && std::isnan(p[1]) && std::isnan(p[2]));
}

TEST(DepthCamera, BackProjectsAnImageRowMajorAsPixelByPixel) {
  const int width = 4;
  const int height = 3;
  std::vector<std::uint16_t> depth;
  for (int i = 0; i < width * height; ++i) depth.push_back(static_cast<std::uint16_t>(i % 5 == 0 ? 0 : 900 + 37 * i));
  std::vector<float> xyz(depth.size() * 3);
  backProjectDepth(depth.data(), width, height, tumCamera(), xyz.data());
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      const std::size_t i = static_cast<std::size_t>(v * width + u);
      float expected[3];
      backProjectPixel(u, v, depth[i], tumCamera(), expected);
      for (int k = 0; k < 3; ++k) {
        if (std::isnan(expected[k])) {
          EXPECT_TRUE(std::isnan(xyz[3 * i + static_cast<std::size_t>(k)]));
        } else {
          EXPECT_EQ(xyz[3 * i + static_cast<std::size_t>(k)], expected[k]) << "pixel " << u << "," << v;
        }
      }
    }
  }
}

TEST(DepthCamera, NamesTheFirstIntrinsicItCannotUse) {
  EXPECT_EQ(tumCamera().problem(), "");
  DepthCamera camera = tumCamera();
  camera.fx = 0.0;
  EXPECT_NE(camera.problem().find("fx must be"), std::string::npos) << camera.problem();
  camera = tumCamera();
  camera.fy = -1.0;
  EXPECT_NE(camera.problem().find("fy must be"), std::string::npos) << camera.problem();
  camera = tumCamera();
  camera.cx = NAN;
  EXPECT_NE(camera.problem().find("cx must be"), std::string::npos) << camera.problem();
  camera = tumCamera();
  camera.cy = INFINITY;
  EXPECT_NE(camera.problem().find("cy must be"), std::string::npos) << camera.problem();
  camera = tumCamera();
  camera.depth_scale = 0.0;
  EXPECT_NE(camera.problem().find("depth_scale must be"), std::string::npos) << camera.problem();
  camera.cx = -5.0;  // a principal point outside the image is unusual but valid
  camera.depth_scale = 1.0;
  EXPECT_EQ(camera.problem(), "");
}

}  // namespace
