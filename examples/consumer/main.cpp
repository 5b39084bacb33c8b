// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Segments a synthetic room corner (floor, back wall, side wall) and prints its planes:
// the drop-in use of floodplane in place of pcl::OrganizedMultiPlaneSegmentation.
#include <floodplane/flood_fill_plane_segmentation.h>

#include <cmath>
#include <cstdio>
#include <limits>

int main() {
  // A 160 x 120 pinhole (f = 131.25 px) looking at a floor 1 m below, a wall 3 m ahead
  // and a wall 1 m to the right.
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>(160, 120));
  for (int v = 0; v < 120; ++v) {
    for (int u = 0; u < 160; ++u) {
      const float x = (u - 79.5f) / 131.25f, y = (v - 59.5f) / 131.25f;  // the ray (x, y, 1)
      float t = 3.0f;                                                    // back wall z = 3
      if (y > 0.0f) t = std::fmin(t, 1.0f / y);                          // floor y = 1
      if (x > 0.0f) t = std::fmin(t, 1.0f / x);                          // side wall x = 1
      (*cloud)(u, v) = pcl::PointXYZ(x * t, y * t, t);
    }
  }

  floodplane::FloodFillPlaneSegmentation<pcl::PointXYZ> seg;  // was pcl::OrganizedMultiPlaneSegmentation
  seg.setMinInliers(500);    // OMPS's setters, same units; the lengths left unset (distance threshold,
  seg.setInputCloud(cloud);  // seed size, merge distance) come from the frame's noise; no setInputNormals
  floodplane::FloodFillPlaneSegmentation<pcl::PointXYZ>::Regions regions;
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> inliers, label_indices, boundaries;
  pcl::PointCloud<pcl::Label>::Ptr labels(new pcl::PointCloud<pcl::Label>);
  seg.segmentAndRefine(regions, coefficients, inliers, labels, label_indices, boundaries);

  for (std::size_t k = 0; k < regions.size(); ++k) {
    const Eigen::Vector4f c = regions[k].getCoefficients();
    std::printf("plane %zu: %u points, n = (%.3f %.3f %.3f), d = %.3f\n", k + 1, regions[k].getCount(), c[0], c[1],
                c[2], c[3]);
  }
  return regions.size() == 3 ? 0 : 1;  // the three surfaces, or the package is broken
}
