// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Tiny ray-cast scenes with known planes for the core's tests: a pinhole camera at the
// origin (x right, y down, z forward) looking at bounded planes. Header-only on purpose:
// each test program includes it once.

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <vector>

#include "floodplane/point_grid.h"

namespace floodplane::test {

struct Pinhole {
  int width = 64;
  int height = 48;
  double focal = 52.5;  // a 640x480 Kinect (f = 525) scaled to the grid
  double cx() const { return (width - 1) / 2.0; }
  double cy() const { return (height - 1) / 2.0; }
};

/// A width x height grid with a Kinect's field of view: f = 525 px at 640 x 480, scaled.
inline Pinhole kinectView(int width, int height) {
  Pinhole c;
  c.width = width;
  c.height = height;
  c.focal = 525.0 * width / 640.0;
  return c;
}

struct ScenePlane {
  Eigen::Vector3d normal;  // unit; n . P + d = 0
  double offset = 0.0;
  int id = 1;
  std::function<bool(const Eigen::Vector3d&)> contains = [](const Eigen::Vector3d&) { return true; };
};

// A curved surface: the ray parameter t of a ray's nearest hit (the point t * ray), or
// infinity.
struct SceneSurface {
  std::function<double(const Eigen::Vector3d& ray)> hit;
  int id = 1;
};

struct RenderedGrid {
  int width = 0;
  int height = 0;
  std::vector<float> xyz;  // stride 3, NaN for no hit
  std::vector<int> truth;  // plane id, 0 for no hit

  PointGrid grid() const {
    PointGrid g;
    g.data = xyz.data();
    g.stride = 3;
    g.width = width;
    g.height = height;
    return g;
  }
  Eigen::Vector3f point(int x, int y) const {
    const std::size_t i = 3 * (static_cast<std::size_t>(y) * width + x);
    return {xyz[i], xyz[i + 1], xyz[i + 2]};
  }
  // The points with four floats each (x y z 1), as PCL lays them out: the layout the core's
  // four-pixel paths take (grid() has three, which they leave to the pixel-by-pixel code).
  std::vector<float> fourFloatPoints() const {
    std::vector<float> padded;
    padded.reserve(xyz.size() / 3 * 4);
    for (std::size_t i = 0; i < xyz.size(); i += 3) padded.insert(padded.end(), {xyz[i], xyz[i + 1], xyz[i + 2], 1.f});
    return padded;
  }
  // A grid over `points` (from fourFloatPoints(), kept alive by the caller).
  PointGrid fourFloatGrid(const std::vector<float>& points) const {
    PointGrid g = grid();
    g.data = points.data();
    g.stride = 4;
    return g;
  }
};

// The standard deviation [m] of the noise along a ray at range r [m].
using RangeNoise = std::function<double(double)>;

// The nearest plane hit along each pixel's ray, with Gaussian noise of standard deviation
// `noise(range)` along the ray (seeded, deterministic).
inline RenderedGrid render(const Pinhole& camera, const std::vector<ScenePlane>& planes, const RangeNoise& noise_of,
                           unsigned seed = 1);

// The same with noise of one standard deviation `range_noise` [m] at every range.
inline RenderedGrid render(const Pinhole& camera, const std::vector<ScenePlane>& planes, double range_noise = 0.0,
                           unsigned seed = 1) {
  return render(
      camera, planes, [range_noise](double) { return range_noise; }, seed);
}

// Planes and curved surfaces together.
inline RenderedGrid render(const Pinhole& camera, const std::vector<ScenePlane>& planes,
                           const std::vector<SceneSurface>& surfaces, const RangeNoise& noise_of, unsigned seed);

inline RenderedGrid render(const Pinhole& camera, const std::vector<ScenePlane>& planes, const RangeNoise& noise_of,
                           unsigned seed) {
  return render(camera, planes, {}, noise_of, seed);
}

inline RenderedGrid render(const Pinhole& camera, const std::vector<ScenePlane>& planes,
                           const std::vector<SceneSurface>& surfaces, const RangeNoise& noise_of, unsigned seed) {
  RenderedGrid out;
  out.width = camera.width;
  out.height = camera.height;
  out.xyz.assign(3 * static_cast<std::size_t>(camera.width) * camera.height, std::numeric_limits<float>::quiet_NaN());
  out.truth.assign(static_cast<std::size_t>(camera.width) * camera.height, 0);
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (int v = 0; v < camera.height; ++v) {
    for (int u = 0; u < camera.width; ++u) {
      const Eigen::Vector3d ray((u - camera.cx()) / camera.focal, (v - camera.cy()) / camera.focal, 1.0);
      double best = std::numeric_limits<double>::infinity();
      int id = 0;
      for (const ScenePlane& plane : planes) {
        const double facing = plane.normal.dot(ray);
        if (std::abs(facing) < 1e-12) continue;
        const double t = -plane.offset / facing;
        if (t > 0.0 && t < best && plane.contains(t * ray)) {
          best = t;
          id = plane.id;
        }
      }
      for (const SceneSurface& surface : surfaces) {
        const double t = surface.hit(ray);
        if (t > 0.0 && t < best) {
          best = t;
          id = surface.id;
        }
      }
      if (id == 0) continue;
      Eigen::Vector3d p = best * ray;
      const double sigma = noise_of(p.norm());
      if (sigma > 0.0) p *= 1.0 + sigma * noise(rng) / p.norm();
      const std::size_t i = static_cast<std::size_t>(v) * camera.width + u;
      out.xyz[3 * i] = static_cast<float>(p.x());
      out.xyz[3 * i + 1] = static_cast<float>(p.y());
      out.xyz[3 * i + 2] = static_cast<float>(p.z());
      out.truth[i] = id;
    }
  }
  return out;
}

// A plane facing the camera at depth z.
inline ScenePlane frontalPlane(double z, int id = 1) {
  ScenePlane p;
  p.normal = Eigen::Vector3d(0, 0, -1);
  p.offset = z;
  p.id = id;
  return p;
}

// An upright cylinder (axis along y through (x, ., z)) of the given radius.
inline SceneSurface uprightCylinder(double x, double z, double radius, int id) {
  SceneSurface s;
  s.id = id;
  s.hit = [x, z, radius](const Eigen::Vector3d& ray) {
    // |(t ray - c) projected on x z| = radius, the nearer root.
    const double a = ray.x() * ray.x() + ray.z() * ray.z();
    const double b = -2.0 * (ray.x() * x + ray.z() * z);
    const double c = x * x + z * z - radius * radius;
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) return std::numeric_limits<double>::infinity();
    return (-b - std::sqrt(discriminant)) / (2.0 * a);
  };
  return s;
}

// A ball of the given radius centred at `centre`.
inline SceneSurface ball(const Eigen::Vector3d& centre, double radius, int id) {
  SceneSurface s;
  s.id = id;
  s.hit = [centre, radius](const Eigen::Vector3d& ray) {
    const double a = ray.squaredNorm();
    const double b = -2.0 * ray.dot(centre);
    const double c = centre.squaredNorm() - radius * radius;
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) return std::numeric_limits<double>::infinity();
    return (-b - std::sqrt(discriminant)) / (2.0 * a);
  };
  return s;
}

// A room corner seen from 1 m above the floor: floor (id 1), back wall at z = 4 (id 2),
// left wall at x = -1.5 (id 3).
inline std::vector<ScenePlane> roomCorner() {
  ScenePlane floor, back, left;
  floor.normal = Eigen::Vector3d(0, -1, 0);
  floor.offset = 1.0;
  floor.id = 1;
  back.normal = Eigen::Vector3d(0, 0, -1);
  back.offset = 4.0;
  back.id = 2;
  left.normal = Eigen::Vector3d(1, 0, 0);
  left.offset = 1.5;
  left.id = 3;
  return {floor, back, left};
}

// IoU of ground-truth surface `id` with its best-matching label.
inline double bestIoU(const RenderedGrid& scene, const std::vector<std::uint32_t>& labels, int id) {
  std::map<std::uint32_t, std::size_t> overlap;
  std::map<std::uint32_t, std::size_t> label_size;
  std::size_t truth_size = 0;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] != 0) ++label_size[labels[i]];
    if (scene.truth[i] != id) continue;
    ++truth_size;
    if (labels[i] != 0) ++overlap[labels[i]];
  }
  double best = 0.0;
  for (const auto& [label, shared] : overlap)
    best = std::max(best, static_cast<double>(shared) / static_cast<double>(truth_size + label_size[label] - shared));
  return best;
}

}  // namespace floodplane::test
