// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "objects/surface_patches.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "models/depth_noise.h"

namespace floodplane {

double SurfaceStep::tolerance(double range) const {
  return kDifferenceDeviations * noise.sigma(range) + noise.step(range) + footprints * pitch * range;
}

void ObjectPoints::add(const PointGrid& grid, std::size_t index) {
  const float* p = grid.point(index);
  pixels.push_back(index);
  ranges.push_back(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
}

double angularPitch(const PointGrid& grid) {
  std::vector<double> angles;
  const int rows = std::min(grid.height, 9);
  for (int k = 0; k < rows; ++k) {
    const int y = (k + 1) * grid.height / (rows + 1);
    for (int x = 0; x + 1 < grid.width; x += 2) {
      const std::size_t i =
          static_cast<std::size_t>(y) * static_cast<std::size_t>(grid.width) + static_cast<std::size_t>(x);
      if (!grid.isFinite(i) || !grid.isFinite(i + 1)) continue;
      const float* p = grid.point(i);
      const float* q = grid.point(i + 1);
      const Eigen::Vector3d a(p[0], p[1], p[2]);
      const Eigen::Vector3d b(q[0], q[1], q[2]);
      const double na = a.norm();
      const double nb = b.norm();
      if (na <= 0.0 || nb <= 0.0) continue;
      angles.push_back(std::atan2(a.cross(b).norm(), a.dot(b)));
    }
  }
  if (angles.empty()) return 0.0;
  auto middle = angles.begin() + static_cast<std::ptrdiff_t>(angles.size() / 2);
  std::nth_element(angles.begin(), middle, angles.end());
  return *middle;
}

void buildSurfacePatches(const PointGrid& grid, const std::vector<std::uint32_t>& plane_labels,
                         const ObjectPoints& points, const SurfaceStep& step, int side, SurfacePatches& out) {
  SurfaceWorkspace work;
  buildSurfacePatches(grid, plane_labels, points, step, side, out, work);
}

void buildSurfacePatches(const PointGrid& grid, const std::vector<std::uint32_t>& plane_labels,
                         const ObjectPoints& points, const SurfaceStep& step, int side, SurfacePatches& out,
                         SurfaceWorkspace& work) {
  const int width = grid.width;
  const int height = grid.height;
  side = std::max(side, 1);
  // The object points by their number k (raster order), each with its tolerance: the work and
  // memory follow the object points, not the frame.
  const std::vector<std::size_t>& pixel_of = points.pixels;
  const std::size_t count = pixel_of.size();
  std::vector<float>& tolerance_of = work.tolerance_of;
  tolerance_of.resize(count);
  for (std::size_t k = 0; k < count; ++k) tolerance_of[k] = static_cast<float>(step.tolerance(points.ranges[k]));
  // The patches are labelled in one raster pass (each point joins its left or upper neighbour
  // in the patch, two sets meeting at a point are linked), in a forest whose every link points
  // to a lower number: one pass in order then finds each point's root.
  std::vector<std::int32_t>& parent = work.parent;
  std::vector<std::int32_t>& up_in_patch = work.up_in_patch;
  parent.resize(count);
  up_in_patch.assign(count, -1);
  const auto root = [&parent](std::int32_t x) {
    while (parent[static_cast<std::size_t>(x)] != x) {
      parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
      x = parent[static_cast<std::size_t>(x)];
    }
    return x;
  };
  bool left_in_patch = false;
  // The numbers of the right and upper neighbours each point is on one surface with (-1: none).
  std::vector<std::int32_t>& right_of = work.right_of;
  std::vector<std::int32_t>& above_of = work.above_of;
  right_of.assign(count, -1);
  above_of.assign(count, -1);
  // Neighbours on one surface: within the tolerance at the nearer one's range (the tolerance
  // grows with the range).
  auto onOneSurface = [&](std::size_t a, std::size_t b) {
    const float* p = grid.point(pixel_of[a]);
    const float* q = grid.point(pixel_of[b]);
    const float dx = p[0] - q[0];
    const float dy = p[1] - q[1];
    const float dz = p[2] - q[2];
    const float tolerance = std::min(tolerance_of[a], tolerance_of[b]);
    return dx * dx + dy * dy + dz * dz <= tolerance * tolerance;
  };
  // Two neighbours on one surface are in one patch when they share a plane (or both are on
  // none) within one square. The lower neighbour is found by a second cursor a row ahead.
  // Whether a column (row) and the next are in one square, looked up: no division per point.
  const auto sameSquareAsNext = [side](int length) {
    std::vector<std::uint8_t> same(static_cast<std::size_t>(std::max(length, 0)));
    for (int c = 0; c < length; ++c) same[static_cast<std::size_t>(c)] = (c + 1) % side != 0;
    return same;
  };
  const std::vector<std::uint8_t> column_joins = sameSquareAsNext(width);
  const std::vector<std::uint8_t> row_joins = sameSquareAsNext(height);
  std::size_t cursor = 0;
  std::size_t row_start = 0;
  int row = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = pixel_of[k];
    while (i >= row_start + static_cast<std::size_t>(width)) {
      row_start += static_cast<std::size_t>(width);
      ++row;
    }
    const int x = static_cast<int>(i - row_start);
    const auto self = static_cast<std::int32_t>(k);
    const std::int32_t up = up_in_patch[k];
    if (left_in_patch) {
      parent[k] = self - 1;
      if (up >= 0) {
        const std::int32_t a = root(self - 1);
        const std::int32_t b = root(up);
        if (a < b) parent[static_cast<std::size_t>(b)] = a;
        if (b < a) parent[static_cast<std::size_t>(a)] = b;
      }
    } else {
      parent[k] = up >= 0 ? up : self;
    }
    left_in_patch = false;
    if (x + 1 < width && k + 1 < count && pixel_of[k + 1] == i + 1 && onOneSurface(k, k + 1)) {
      right_of[k] = self + 1;
      left_in_patch = plane_labels[i] == plane_labels[i + 1] && column_joins[static_cast<std::size_t>(x)];
    }
    const std::size_t below = i + static_cast<std::size_t>(width);
    if (row + 1 >= height) continue;
    cursor = std::max(cursor, k);
    while (cursor < count && pixel_of[cursor] < below) ++cursor;
    if (cursor < count && pixel_of[cursor] == below && onOneSurface(k, cursor)) {
      above_of[cursor] = self;
      if (plane_labels[i] == plane_labels[below] && row_joins[static_cast<std::size_t>(row)])
        up_in_patch[cursor] = self;
    }
  }
  // Number the patches in raster order of their first pixel and sum their points.
  out.patches.clear();
  std::vector<std::int32_t>& patch_of = out.patch_of_point;
  std::vector<std::int32_t>& index_of_root = work.index_of_root;
  patch_of.assign(count, -1);
  index_of_root.assign(count, -1);
  std::vector<Eigen::Vector3d>& sums = work.sums;
  std::vector<Eigen::Matrix3d>& squares = work.squares;
  sums.clear();
  squares.clear();
  std::vector<std::uint64_t>& crossings = work.crossings;
  crossings.clear();
  // Two patches as one number, the lower first.
  const auto pairKey = [](std::int32_t a, std::int32_t b) {
    if (b < a) std::swap(a, b);
    return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
  };
  // A run of pixels of one patch (up to a square's side along a row) is summed in registers and
  // added to the patch's sums once.
  std::int32_t run = -1;
  std::uint32_t run_pixels = 0;
  Eigen::Vector3d run_sum = Eigen::Vector3d::Zero();
  double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
  const auto flush = [&] {
    if (run < 0) return;
    const auto r = static_cast<std::size_t>(run);
    out.patches[r].pixels += run_pixels;
    sums[r] += run_sum;
    Eigen::Matrix3d& m = squares[r];
    m(0, 0) += xx;
    m(0, 1) += xy;
    m(0, 2) += xz;
    m(1, 1) += yy;
    m(1, 2) += yz;
    m(2, 2) += zz;
    run_pixels = 0;
    run_sum.setZero();
    xx = xy = xz = yy = yz = zz = 0;
  };
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = pixel_of[k];
    // Its parent, lower, has its root as its parent already.
    std::int32_t& link = parent[k];
    link = parent[static_cast<std::size_t>(link)];
    std::int32_t& index = index_of_root[static_cast<std::size_t>(link)];
    if (index < 0) {
      index = static_cast<std::int32_t>(out.patches.size());
      out.patches.emplace_back();
      out.patches.back().plane = plane_labels[i];
      sums.push_back(Eigen::Vector3d::Zero());
      squares.push_back(Eigen::Matrix3d::Zero());
    }
    patch_of[k] = index;
    // The pixel pairs on one surface with the left and upper neighbours (numbered already)
    // across two patches, for the contacts.
    const auto self = static_cast<std::int32_t>(k);
    if (k > 0 && right_of[k - 1] == self && patch_of[k - 1] != index)
      crossings.push_back(pairKey(patch_of[k - 1], index));
    const std::int32_t above = above_of[k];
    if (above >= 0 && patch_of[static_cast<std::size_t>(above)] != index) {
      crossings.push_back(pairKey(patch_of[static_cast<std::size_t>(above)], index));
    }
    if (index != run) {
      flush();
      run = index;
    }
    const float* p = grid.point(i);
    const double x = p[0];
    const double y = p[1];
    const double z = p[2];
    run_pixels += 1;
    run_sum += Eigen::Vector3d(x, y, z);
    xx += x * x;
    xy += x * y;
    xz += x * z;
    yy += y * y;
    yz += y * z;
    zz += z * z;
  }
  flush();
  for (Eigen::Matrix3d& m : squares)
    m.triangularView<Eigen::StrictlyLower>() = m.transpose().triangularView<Eigen::StrictlyLower>();
  // The normal of a patch on no plane is its own; a plane's patches share the plane's (the
  // fit over all of them, steadier than a square's).
  // A patch on no plane must be at least a pixel footprint wide across (the spread of its
  // points' narrower direction) for its own normal to mean anything: a strip one or two pixels
  // wide along a crease (between a box's top and its front) has none, and joins the patch it
  // shares the most pixel pairs with instead.
  auto normalOf = [&step](const Eigen::Vector3d& sum, const Eigen::Matrix3d& square, double pixels,
                          bool own) -> Eigen::Vector3d {
    if (pixels < 3) return Eigen::Vector3d::Zero();
    const Eigen::Vector3d centroid = sum / pixels;
    const Eigen::Matrix3d covariance = square / pixels - centroid * centroid.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(covariance);
    const double footprint = step.pitch * centroid.norm();
    const double least = own ? footprint * footprint : 1e-12;
    // A line of points (or a single point repeated) spans no plane.
    if (!(solver.eigenvalues()[1] > least)) return Eigen::Vector3d::Zero();
    Eigen::Vector3d normal = solver.eigenvectors().col(0);
    return normal.dot(centroid) > 0.0 ? Eigen::Vector3d(-normal) : normal;
  };
  std::uint32_t largest_plane = 0;
  for (const SurfacePatch& patch : out.patches) largest_plane = std::max(largest_plane, patch.plane);
  std::vector<Eigen::Vector3d> plane_sums(largest_plane + 1, Eigen::Vector3d::Zero());
  std::vector<Eigen::Matrix3d> plane_squares(largest_plane + 1, Eigen::Matrix3d::Zero());
  std::vector<double> plane_counts(largest_plane + 1, 0.0);
  for (std::size_t k = 0; k < out.patches.size(); ++k) {
    const std::uint32_t plane = out.patches[k].plane;
    if (plane == 0) continue;
    plane_sums[plane] += sums[k];
    plane_squares[plane] += squares[k];
    plane_counts[plane] += out.patches[k].pixels;
  }
  std::vector<Eigen::Vector3d> plane_normals(largest_plane + 1, Eigen::Vector3d::Zero());
  for (std::uint32_t plane = 1; plane <= largest_plane; ++plane) {
    if (plane_counts[plane] > 0)
      plane_normals[plane] = normalOf(plane_sums[plane], plane_squares[plane], plane_counts[plane], false);
  }
  for (std::size_t k = 0; k < out.patches.size(); ++k) {
    SurfacePatch& patch = out.patches[k];
    patch.centroid = sums[k] / static_cast<double>(patch.pixels);
    patch.normal = patch.plane != 0 ? plane_normals[patch.plane] : normalOf(sums[k], squares[k], patch.pixels, true);
  }
  // The contacts: pixel pairs on one surface across two patches (the crossings, gathered while
  // numbering the patches), counted per pair of patches
  // in an open-addressing table (a pair of squares meets along up to a side's pixels, so the
  // pairs are many and the contacts few), then sorted.
  std::size_t slots = 64;
  while (slots < 8 * out.patches.size()) slots *= 2;
  constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  std::vector<std::uint64_t>& table_keys = work.table_keys;
  std::vector<std::uint32_t>& table_pairs = work.table_pairs;
  table_keys.assign(slots, kEmpty);
  table_pairs.assign(slots, 0);
  std::size_t used = 0;
  const auto addContact = [&](std::uint64_t key) {
    std::size_t slot = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 40) & (slots - 1);
    while (table_keys[slot] != key && table_keys[slot] != kEmpty) slot = (slot + 1) & (slots - 1);
    if (table_keys[slot] == kEmpty) {
      table_keys[slot] = key;
      ++used;
    }
    ++table_pairs[slot];
  };
  for (const std::uint64_t key : crossings) {
    addContact(key);
    // Keep the table at most half full (a frame whose patches touch more than usual).
    if (2 * used > slots) {
      std::vector<std::uint64_t> old_keys(2 * slots, kEmpty);
      std::vector<std::uint32_t> old_pairs(2 * slots, 0);
      old_keys.swap(table_keys);
      old_pairs.swap(table_pairs);
      slots *= 2;
      for (std::size_t j = 0; j < old_keys.size(); ++j) {
        if (old_keys[j] == kEmpty) continue;
        std::size_t slot = static_cast<std::size_t>((old_keys[j] * 0x9E3779B97F4A7C15ull) >> 40) & (slots - 1);
        while (table_keys[slot] != kEmpty) slot = (slot + 1) & (slots - 1);
        table_keys[slot] = old_keys[j];
        table_pairs[slot] = old_pairs[j];
      }
    }
  }
  out.contacts.clear();
  out.contacts.reserve(used);
  for (std::size_t j = 0; j < slots; ++j) {
    if (table_keys[j] == kEmpty) continue;
    PatchContact contact;
    contact.first = static_cast<std::int32_t>(table_keys[j] >> 32);
    contact.second = static_cast<std::int32_t>(table_keys[j] & 0xffffffffu);
    contact.pairs = table_pairs[j];
    out.contacts.push_back(contact);
  }
  std::sort(out.contacts.begin(), out.contacts.end(), [](const PatchContact& x, const PatchContact& z) {
    return x.first != z.first ? x.first < z.first : x.second < z.second;
  });
}

}  // namespace floodplane
