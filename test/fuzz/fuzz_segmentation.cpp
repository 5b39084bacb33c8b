// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target (issue 7): input bytes -> an organized cloud up to 64 x 64 and parameters,
// then segmentAndRefine, then the invariants every output must satisfy. Any violation
// aborts, so libFuzzer reports it with the input that caused it.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>

#include "floodplane/flood_fill_plane_segmentation.h"

namespace {

// Reads the input front to back; past its end it yields zeros.
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  float unit() { return byte() / 255.0f; }
  bool empty() const { return pos_ >= size_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "invariant violated: %s\n", what);
  std::abort();
}

// A coordinate: mostly a point on one of a few planes (so that planes are found), sometimes
// one of the values sensors and bugs produce.
float coordinate(ByteReader& in, float on_plane) {
  switch (in.byte() % 16) {
    case 0:
      return std::numeric_limits<float>::quiet_NaN();
    case 1:
      return std::numeric_limits<float>::infinity();
    case 2:
      return -std::numeric_limits<float>::infinity();
    case 3:
      return 0.0f;
    case 4:
      return std::numeric_limits<float>::denorm_min();
    case 5:
      return 1e30f;
    case 6:
      return 1e5f * (in.unit() - 0.5f);  // 100 km
    default:
      return on_plane + 0.002f * (in.unit() - 0.5f);
  }
}

// A parameter value within its valid range most of the time, just outside it sometimes.
double parameter(ByteReader& in, double low, double high) {
  const std::uint8_t kind = in.byte();
  if (kind == 0) return low - 1e-3;
  if (kind == 1) return high * 1.5;
  if (kind == 2) return std::numeric_limits<double>::quiet_NaN();
  return low + (high - low) * in.unit();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  ByteReader in(data, size);
  const int width = 1 + in.byte() % 64;
  const int height = 1 + in.byte() % 64;
  using Segmentation = floodplane::FloodFillPlaneSegmentation<pcl::PointXYZ>;
  Segmentation seg;
  try {
    seg.setDistanceThreshold(parameter(in, 0.001, 0.1));
    seg.setSeedSize(parameter(in, 0.005, 0.5));
    seg.setAngularThreshold(parameter(in, 0.01, 1.5));
    seg.setMergeDistance(parameter(in, 0.001, 0.2));
    seg.setSubsampling(1 << (in.byte() % 5));  // 1..16: 16 is invalid
    seg.setMinInliers(in.byte() % 64);
  } catch (const std::invalid_argument&) {
    // Rejected in the setter, as documented; the remaining parameters keep their defaults.
  }

  // The scene: up to three planes z = a + b x + c y picked per pixel by the input.
  float a[3], b[3], c[3];
  for (int k = 0; k < 3; ++k) {
    a[k] = 0.5f + 4.0f * in.unit();
    b[k] = in.unit() - 0.5f;
    c[k] = in.unit() - 0.5f;
  }
  const bool one_plane = in.byte() % 4 == 0;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>(width, height));
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      const int k = one_plane ? 0 : (in.empty() ? (u * 3 / width) : in.byte() % 3);
      const float x = (u - width / 2.0f) * 0.01f, y = (v - height / 2.0f) * 0.01f;
      const float z = a[k] + b[k] * x + c[k] * y;
      pcl::PointXYZ& p = (*cloud)(u, v);
      p.x = in.empty() ? x * z : coordinate(in, x * z);
      p.y = in.empty() ? y * z : coordinate(in, y * z);
      p.z = in.empty() ? z : coordinate(in, z);
    }
  }
  seg.setInputCloud(cloud);

  Segmentation::Regions regions;
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> inliers, label_indices, boundaries;
  pcl::PointCloud<pcl::Label>::Ptr labels(new pcl::PointCloud<pcl::Label>);
  seg.segmentAndRefine(regions, coefficients, inliers, labels, label_indices, boundaries);

  const std::size_t planes = regions.size();
  if (coefficients.size() != planes || inliers.size() != planes || boundaries.size() != planes) fail("output sizes");
  if (planes > 0 && (labels->width != cloud->width || labels->height != cloud->height)) fail("label grid size");
  for (std::size_t k = 0; k < planes; ++k) {
    if (inliers[k].indices.size() < seg.getMinInliers()) fail("plane below min inliers");
    if (regions[k].getCount() != inliers[k].indices.size()) fail("region count");
    const auto& n = coefficients[k].values;
    if (n.size() != 4) fail("coefficient count");
    const double norm = std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2]);
    if (!(std::abs(norm - 1.0) < 1e-3) || !std::isfinite(n[3])) fail("normal not unit or offset not finite");
    for (int i : inliers[k].indices) {
      if (i < 0 || static_cast<std::size_t>(i) >= cloud->size()) fail("inlier index out of range");
      if ((*labels)[i].label != k + 1) fail("inlier not labelled with its plane");
      if (!pcl::isFinite((*cloud)[i])) fail("non-finite point labelled");
    }
    for (int i : boundaries[k].indices) {
      if (i < 0 || static_cast<std::size_t>(i) >= cloud->size() || (*labels)[i].label != k + 1)
        fail("boundary pixel not on its region");
    }
  }
  for (const pcl::Label& l : labels->points)
    if (l.label > planes) fail("label out of range");
  return 0;
}
