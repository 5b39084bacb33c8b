// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// floodplane::FloodFillPlaneSegmentation over a point type of the user's own, which the
// library does not instantiate: its template definitions must be compiled here. Built twice
// (CMakeLists.txt): with PCL_NO_PRECOMPILE, and with the definitions' headers included.
#ifdef CONSUMER_INCLUDE_TEMPLATE_DEFINITIONS
#include <floodplane/flood_fill_plane_segmentation.h>
#include <floodplane/impl/flood_fill_plane_segmentation.hpp>
// PCLBase<PointT>'s definitions too: libpcl_common has them only for PCL's own point types.
#include <pcl/impl/pcl_base.hpp>
#else
// Before any PCL or floodplane header: every template's definitions come with its header.
#define PCL_NO_PRECOMPILE
#include <floodplane/flood_fill_plane_segmentation.h>
#endif

#include <pcl/point_types.h>
#include <pcl/register_point_struct.h>

#include <cmath>
#include <cstdio>

// A range-sensor point: x y z and the measured range.
struct EIGEN_ALIGN16 RangePoint {
  PCL_ADD_POINT4D;
  float range;
  PCL_MAKE_ALIGNED_OPERATOR_NEW
};
POINT_CLOUD_REGISTER_POINT_STRUCT(RangePoint, (float, x, x)(float, y, y)(float, z, z)(float, range, range))

int main() {
  // A 160 x 120 pinhole (f = 131.25 px): floor 1 m below, wall 3 m ahead, wall 1 m right.
  pcl::PointCloud<RangePoint>::Ptr cloud(new pcl::PointCloud<RangePoint>(160, 120));
  for (int v = 0; v < 120; ++v) {
    for (int u = 0; u < 160; ++u) {
      const float x = (u - 79.5f) / 131.25f, y = (v - 59.5f) / 131.25f;
      float t = 3.0f;
      if (y > 0.0f) t = std::fmin(t, 1.0f / y);
      if (x > 0.0f) t = std::fmin(t, 1.0f / x);
      RangePoint& point = (*cloud)(u, v);
      point.x = x * t;
      point.y = y * t;
      point.z = t;
      point.range = t * std::sqrt(x * x + y * y + 1.0f);
    }
  }

  floodplane::FloodFillPlaneSegmentation<RangePoint> seg;
  seg.setMinInliers(500);
  seg.setInputCloud(cloud);
  floodplane::FloodFillPlaneSegmentation<RangePoint>::Regions regions;
  seg.segmentAndRefine(regions);
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const Eigen::Vector4f c = regions[k].getCoefficients();
    std::printf("custom point type, plane %zu: %u points, n = (%.3f %.3f %.3f), d = %.3f\n", k + 1,
                regions[k].getCount(), c[0], c[1], c[2], c[3]);
  }
  return regions.size() == 3 ? 0 : 1;
}
