#pragma once

#include <cmath>
#include <cstddef>

namespace floodplane {

/// A read-only view of an organized cloud: width x height points, row-major, whose x y z are
/// three consecutive floats every `stride` floats. A pcl::PointCloud<PointXYZ...> is such a
/// grid in place (x y z lead every PCL point type), so the core reads the caller's memory
/// without a copy. Points whose coordinates are not finite are holes; the core never tests
/// for them explicitly: every acceptance test is written `value < threshold`, which NaN fails.
struct PointGrid {
  const float* data = nullptr;
  std::size_t stride = 3;  ///< floats from one point to the next
  int width = 0;
  int height = 0;

  std::size_t size() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
  const float* point(std::size_t index) const { return data + index * stride; }
  bool isFinite(std::size_t index) const {
    const float* p = point(index);
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
  }
};

/// A small fixed-size vector for the hot loops: no Eigen temporaries, no alignment rules.
struct Vec3 {
  float x = 0.f, y = 0.f, z = 0.f;

  static Vec3 load(const float* p) { return {p[0], p[1], p[2]}; }
  Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  Vec3 operator*(float s) const { return {x * s, y * s, z * s}; }
  float dot(const Vec3& o) const { return x * o.x + y * o.y + z * o.z; }
  Vec3 cross(const Vec3& o) const { return {y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x}; }
  float squaredNorm() const { return dot(*this); }
  float norm() const { return std::sqrt(squaredNorm()); }
};

}  // namespace floodplane
