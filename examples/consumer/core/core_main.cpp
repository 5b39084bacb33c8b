// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Segments a synthetic room corner with the PCL-free core: a plain x y z grid in, a label per
// pixel and the planes out. Links floodplane::core only.
#include <floodplane/segmenter.h>

#include <cmath>
#include <cstdio>
#include <vector>

int main() {
  // A 160 x 120 pinhole (f = 131.25 px): floor 1 m below, wall 3 m ahead, wall 1 m right.
  const int width = 160, height = 120;
  std::vector<float> xyz;
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      const float x = (u - 79.5f) / 131.25f, y = (v - 59.5f) / 131.25f;
      float t = 3.0f;
      if (y > 0.0f) t = std::fmin(t, 1.0f / y);
      if (x > 0.0f) t = std::fmin(t, 1.0f / x);
      xyz.insert(xyz.end(), {x * t, y * t, t});
    }
  }
  floodplane::PointGrid grid;
  grid.data = xyz.data();
  grid.stride = 3;
  grid.width = width;
  grid.height = height;

  floodplane::Params params;
  params.min_inliers = 500;
  floodplane::Segmenter segmenter(params);
  const floodplane::Segmentation& result = segmenter.segment(grid);
  for (std::size_t k = 0; k < result.planes.size(); ++k) {
    const floodplane::PlaneFit& fit = result.planes[k].fit;
    std::printf("core plane %zu: %u points, n = (%.3f %.3f %.3f), d = %.3f\n", k + 1, result.planes[k].inlier_count,
                fit.normal.x(), fit.normal.y(), fit.normal.z(), fit.offset);
  }
  return result.planes.size() == 3 ? 0 : 1;
}
