// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// segmentObjects: the supports, the object points above them, their surface patches, the
// patches joined where they meet convexly, and the objects' records.
#include "floodplane/object_segmentation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/depth_noise.h"
#include "objects/convex_joining.h"
#include "objects/support_planes.h"
#include "objects/surface_patches.h"
#include "util/union_find.h"

namespace floodplane {

namespace {

void checkLength(const char* name, double value) {
  if (!std::isfinite(value) || value < 0.0) {
    throw std::invalid_argument(std::string("ObjectOptions::") + name + " must be finite and at least 0, not " +
                                std::to_string(value));
  }
}

void checkOptions(const ObjectOptions& options) {
  checkLength("min_support_area_m2", options.min_support_area_m2);
  checkLength("support_piece_angle_rad", options.support_piece_angle_rad);
  checkLength("support_piece_distance_m", options.support_piece_distance_m);
  checkLength("support_clearance_m", options.support_clearance_m);
  checkLength("max_step_footprints", options.max_step_footprints);
  checkLength("concavity_tolerance_rad", options.concavity_tolerance_rad);
  if (options.concavity_tolerance_rad >= M_PI / 2) {
    throw std::invalid_argument("ObjectOptions::concavity_tolerance_rad must be below pi/2, not " +
                                std::to_string(options.concavity_tolerance_rad));
  }
  if (options.local_patch_pixels < 1) {
    throw std::invalid_argument("ObjectOptions::local_patch_pixels must be at least 1, not " +
                                std::to_string(options.local_patch_pixels));
  }
  if (options.min_object_pixels < 1) {
    throw std::invalid_argument("ObjectOptions::min_object_pixels must be at least 1, not 0");
  }
}

// Per object point: the support it is lowest above (0: none) and its height above it [m].
struct LowestSupports {
  std::vector<double> height;
  std::vector<std::uint32_t> label;
};

// The object points: finite, on no support, and above every support by the clearance and
// three noise deviations at their range; with the support each is lowest above, found on the way.
void findObjectPoints(const PointGrid& grid, const Segmentation& planes, const Supports& supports,
                      const ObjectOptions& options, ObjectPoints& points, LowestSupports& lowest) {
  points.clear();
  lowest.height.clear();
  lowest.label.clear();
  // Room for every pixel: no copy as they grow (only the pages written are touched).
  points.pixels.reserve(grid.size());
  points.ranges.reserve(grid.size());
  lowest.height.reserve(grid.size());
  lowest.label.reserve(grid.size());
  // Bytes, not std::vector<bool>'s bits: one load per pixel.
  const std::vector<std::uint8_t> on_support(supports.is_support.begin(), supports.is_support.end());
  const std::size_t labels = on_support.size();
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const std::uint32_t label = planes.labels[i];
    if (label < labels && on_support[label] != 0) continue;
    if (!grid.isFinite(i)) continue;
    const float* p = grid.point(i);
    const Eigen::Vector3d point(p[0], p[1], p[2]);
    // The noise model needs r^2 alone; the range itself only for the points kept.
    const double range_sq = point.squaredNorm();
    const double clearance = options.support_clearance_m + noiseDeviations(planes.noise, kPointDeviations, range_sq) +
                             planes.noise.step_constant + planes.noise.step_quadratic * range_sq;
    bool above = true;
    double lowest_height = std::numeric_limits<double>::infinity();
    std::uint32_t lowest_label = 0;
    for (const SupportSurface& surface : supports.surfaces) {
      const double height = surface.height(point);
      if (height <= clearance) {
        above = false;
        break;
      }
      if (height < lowest_height) {
        lowest_height = height;
        lowest_label = surface.label;
      }
    }
    if (above) {
      points.pixels.push_back(i);
      points.ranges.push_back(static_cast<float>(std::sqrt(range_sq)));
      lowest.height.push_back(lowest_height);
      lowest.label.push_back(lowest_label);
    }
  }
}

// The buffers of one thread's calls, kept between them: the object points and patches follow
// the frame's size, and fresh memory for them on every frame (the kernel zeroing its pages)
// cost about as much as the work in it.
struct ObjectWorkspace {
  ObjectPoints points;
  LowestSupports lowest;
  UnionFind union_find;
  SurfacePatches patches;
  SurfaceWorkspace surfaces;
};

/// The objects: the joined patches, largest first (ties in raster order of their first
/// pixel), those still below the smallest size (touching no object) dropped. Returns the
/// object id of each patch (0: none) and sizes `objects`, numbered, with empty boxes.
std::vector<std::uint32_t> numberObjects(const SurfacePatches& patches, UnionFind& union_find, std::uint32_t min_pixels,
                                         std::vector<SegmentedObject>& objects) {
  const std::size_t patch_count = patches.patches.size();
  std::vector<std::uint32_t> pixels_of_root(patch_count, 0);
  for (std::size_t k = 0; k < patch_count; ++k) {
    pixels_of_root[static_cast<std::size_t>(union_find.find(static_cast<std::int32_t>(k)))] +=
        patches.patches[k].pixels;
  }
  std::vector<std::int32_t> roots;
  for (std::size_t k = 0; k < patch_count; ++k) {
    if (union_find.find(static_cast<std::int32_t>(k)) == static_cast<std::int32_t>(k) &&
        pixels_of_root[k] >= min_pixels) {
      roots.push_back(static_cast<std::int32_t>(k));
    }
  }
  std::stable_sort(roots.begin(), roots.end(), [&](std::int32_t a, std::int32_t b) {
    return pixels_of_root[static_cast<std::size_t>(a)] > pixels_of_root[static_cast<std::size_t>(b)];
  });
  std::vector<std::uint32_t> id_of_root(patch_count, 0);
  objects.resize(roots.size());
  for (std::size_t k = 0; k < roots.size(); ++k) {
    id_of_root[static_cast<std::size_t>(roots[k])] = static_cast<std::uint32_t>(k + 1);
    SegmentedObject& object = objects[k];
    object.id = static_cast<std::uint32_t>(k + 1);
    object.min.setConstant(std::numeric_limits<double>::infinity());
    object.max.setConstant(-std::numeric_limits<double>::infinity());
  }
  std::vector<std::uint32_t> id_of_patch(patch_count);
  for (std::size_t k = 0; k < patch_count; ++k) {
    id_of_patch[k] = id_of_root[static_cast<std::size_t>(union_find.find(static_cast<std::int32_t>(k)))];
  }
  return id_of_patch;
}

/// Writes the objects' labels and sums their points: size, centroid, box, and the support each
/// stands on (the one nearest below its lowest point, from each point's `lowest_support`).
void labelObjects(const PointGrid& grid, const ObjectPoints& points, const SurfacePatches& patches,
                  const std::vector<std::uint32_t>& id_of_patch, const LowestSupports& lowest_support,
                  ObjectSegmentation& result) {
  std::vector<double> lowest(result.objects.size(), std::numeric_limits<double>::infinity());
  std::vector<std::uint32_t> support_of(result.objects.size(), 0);
  for (std::size_t k = 0; k < points.pixels.size(); ++k) {
    const std::size_t i = points.pixels[k];
    const std::uint32_t id = id_of_patch[static_cast<std::size_t>(patches.patch_of_point[k])];
    if (id == 0) continue;
    result.labels[i] = id;
    SegmentedObject& object = result.objects[id - 1];
    const float* p = grid.point(i);
    const Eigen::Vector3d point(p[0], p[1], p[2]);
    object.pixel_count += 1;
    object.centroid += point;
    object.min = object.min.cwiseMin(point);
    object.max = object.max.cwiseMax(point);
    if (lowest_support.height[k] < lowest[id - 1]) {
      lowest[id - 1] = lowest_support.height[k];
      support_of[id - 1] = lowest_support.label[k];
    }
  }
  for (std::size_t k = 0; k < result.objects.size(); ++k) {
    SegmentedObject& object = result.objects[k];
    object.centroid /= static_cast<double>(object.pixel_count);
    object.support = support_of[k];
  }
}

}  // namespace

ObjectSegmentation segmentObjects(const PointGrid& grid, const Segmentation& planes, const ObjectOptions& options) {
  checkOptions(options);
  if (planes.width != grid.width || planes.height != grid.height || planes.labels.size() != grid.size()) {
    throw std::invalid_argument("segmentObjects: the segmentation is " + std::to_string(planes.width) + "x" +
                                std::to_string(planes.height) + ", the grid " + std::to_string(grid.width) + "x" +
                                std::to_string(grid.height));
  }
  ObjectSegmentation result;
  result.width = grid.width;
  result.height = grid.height;
  result.labels.assign(grid.size(), 0);
  if (grid.size() == 0) return result;

  const Supports supports = findSupports(planes.planes, options);
  for (const SupportSurface& surface : supports.surfaces) result.supports.push_back(surface.label);
  thread_local ObjectWorkspace work;
  ObjectPoints& points = work.points;
  findObjectPoints(grid, planes, supports, options, points, work.lowest);

  SurfaceStep step;
  step.noise = planes.noise;
  step.pitch = angularPitch(grid);
  step.footprints = options.max_step_footprints;
  UnionFind& union_find = work.union_find;
  SurfacePatches& patches = work.patches;
  buildSurfacePatches(grid, planes.labels, points, step, options.local_patch_pixels, patches, work.surfaces);
  joinConvexPatches(patches, options.concavity_tolerance_rad, union_find);
  absorbFragments(patches, options.min_object_pixels, union_find);

  const std::vector<std::uint32_t> id_of_patch =
      numberObjects(patches, union_find, options.min_object_pixels, result.objects);
  labelObjects(grid, points, patches, id_of_patch, work.lowest, result);
  return result;
}

}  // namespace floodplane
