// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cmath>

namespace floodplane {

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
  /// Writes x y z 0 to out[0..3]: the layout of the grids the stages build (four floats a point,
  /// as PCL's point types, so that SIMD code loads a point in one register).
  void storePadded(float* out) const {
    out[0] = x;
    out[1] = y;
    out[2] = z;
    out[3] = 0.f;
  }
};

}  // namespace floodplane
