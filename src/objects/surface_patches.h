// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "floodplane/noise_model.h"
#include "floodplane/point_grid.h"
#include "util/union_find.h"

namespace floodplane {

/// When two neighbouring points are on one surface: at most
///   3 sqrt(2) sigma(r) + q(r) + footprints * pitch * r
/// apart, r the nearer one's range (the difference of two noisy depths, the depth lattice's
/// step, and a surface seen obliquely, whose neighbouring points lie several footprints apart).
struct SurfaceStep {
  NoiseModel noise;
  double pitch = 0.0;       ///< the angle between neighbouring viewing rays [rad]
  double footprints = 4.0;  ///< ObjectOptions::max_step_footprints
  double tolerance(double range) const;
};

/// The angle between neighbouring viewing rays [rad]: the median over finite horizontal
/// neighbours of a few rows (0 when there are none).
double angularPitch(const PointGrid& grid);

/// The object points: their pixels in raster order and their ranges [m].
struct ObjectPoints {
  std::vector<std::size_t> pixels;
  std::vector<float> ranges;
  void clear() {
    pixels.clear();
    ranges.clear();
  }
  /// Adds pixel `index` of `grid` (after those before it in raster order).
  void add(const PointGrid& grid, std::size_t index);
};

/// A small piece of surface: its size, plane, centroid and normal (towards the sensor).
struct SurfacePatch {
  std::uint32_t pixels = 0;
  std::uint32_t plane = 0;  ///< the plane it is part of (the segmentation's label), 0: none
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  /// The plane's normal, or on no plane its own; zero when its points span no plane.
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
};

/// Two patches that touch on the grid (first < second) and how many neighbouring pixel pairs
/// join them.
struct PatchContact {
  std::int32_t first = 0;
  std::int32_t second = 0;
  std::uint32_t pairs = 0;
};

/// The object points cut into patches that are each one small piece of surface: the pixels of
/// one plane of the segmentation (or of none) within one `side` x `side` square of the grid,
/// split where neighbours are not on one surface (SurfaceStep). Small, so that the convexity
/// test between two touching patches looks at the surfaces where they meet, not at the far
/// side of a large plane (whose centroid can lie anywhere: a strip around a box). Their contacts
/// are the neighbouring pixel pairs (4-neighbours) on one surface across two patches.
struct SurfacePatches {
  std::vector<std::int32_t> patch_of_point;  ///< the patch of each object point (ObjectPoints' order)
  std::vector<SurfacePatch> patches;
  std::vector<PatchContact> contacts;  ///< sorted by (first, second)
};

/// The buffers buildSurfacePatches works in, kept between calls so that a frame after the
/// first touches no fresh memory (their sizes follow the object points).
struct SurfaceWorkspace {
  std::vector<float> tolerance_of;
  std::vector<std::int32_t> parent;
  std::vector<std::int32_t> up_in_patch;
  std::vector<std::int32_t> right_of;
  std::vector<std::int32_t> above_of;
  std::vector<std::uint64_t> crossings;
  std::vector<std::int32_t> index_of_root;
  std::vector<Eigen::Vector3d> sums;
  std::vector<Eigen::Matrix3d> squares;
  std::vector<std::uint64_t> table_keys;
  std::vector<std::uint32_t> table_pairs;
};

/// Builds the patches of `points`; `plane_labels` is the segmentation's label image (0: no
/// plane). Costs a pass over the object points and one to mark
/// them in the frame's grid.
void buildSurfacePatches(const PointGrid& grid, const std::vector<std::uint32_t>& plane_labels,
                         const ObjectPoints& points, const SurfaceStep& step, int side, SurfacePatches& out);
/// The same in `work`'s buffers.
void buildSurfacePatches(const PointGrid& grid, const std::vector<std::uint32_t>& plane_labels,
                         const ObjectPoints& points, const SurfaceStep& step, int side, SurfacePatches& out,
                         SurfaceWorkspace& work);

}  // namespace floodplane
