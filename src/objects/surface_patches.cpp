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

double angularPitch(const PointGrid& grid) {
  std::vector<double> angles;
  const int rows = std::min(grid.height, 9);
  for (int k = 0; k < rows; ++k) {
    const int y = (k + 1) * grid.height / (rows + 1);
    for (int x = 0; x + 1 < grid.width; x += 2) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(grid.width) + x;
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

namespace {

Eigen::Vector3d pointAt(const PointGrid& grid, std::size_t index) {
  const float* p = grid.point(index);
  return Eigen::Vector3d(p[0], p[1], p[2]);
}

// Bits of SurfacePatches' pixel links: joined to the right and to the lower neighbour.
constexpr std::uint8_t kRight = 1;
constexpr std::uint8_t kDown = 2;

}  // namespace

void buildSurfacePatches(const PointGrid& grid, const std::vector<std::uint32_t>& plane_labels,
                         const std::vector<std::uint8_t>& candidate, const SurfaceStep& step, int side,
                         UnionFind& union_find, SurfacePatches& out) {
  const int width = grid.width;
  const int height = grid.height;
  const std::size_t n = grid.size();
  side = std::max(side, 1);
  union_find.reset(n);
  std::vector<std::uint8_t> links(n, 0);
  auto onOneSurface = [&](std::size_t a, std::size_t b) {
    const Eigen::Vector3d p = pointAt(grid, a);
    const Eigen::Vector3d q = pointAt(grid, b);
    const double range = std::min(p.norm(), q.norm());
    const double tolerance = step.tolerance(range);
    return (p - q).squaredNorm() <= tolerance * tolerance;
  };
  // Two neighbours on one surface are in one patch when they share a plane (or both are on
  // none) within one square.
  auto samePatch = [&](std::size_t a, int xa, int ya, std::size_t b, int xb, int yb) {
    return plane_labels[a] == plane_labels[b] && xa / side == xb / side && ya / side == yb / side;
  };
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + x;
      if (!candidate[i]) continue;
      if (x + 1 < width && candidate[i + 1] && onOneSurface(i, i + 1)) {
        links[i] |= kRight;
        if (samePatch(i, x, y, i + 1, x + 1, y))
          union_find.unite(static_cast<std::int32_t>(i), static_cast<std::int32_t>(i + 1));
      }
      const std::size_t below = i + static_cast<std::size_t>(width);
      if (y + 1 < height && candidate[below] && onOneSurface(i, below)) {
        links[i] |= kDown;
        if (samePatch(i, x, y, below, x, y + 1))
          union_find.unite(static_cast<std::int32_t>(i), static_cast<std::int32_t>(below));
      }
    }
  }
  // Number the patches in raster order of their first pixel and sum their points.
  out.patch_of_pixel.assign(n, -1);
  out.patches.clear();
  std::vector<std::int32_t> index_of_root(n, -1);
  std::vector<Eigen::Vector3d> sums;
  std::vector<Eigen::Matrix3d> squares;
  for (std::size_t i = 0; i < n; ++i) {
    if (!candidate[i]) continue;
    const std::int32_t root = union_find.find(static_cast<std::int32_t>(i));
    std::int32_t& index = index_of_root[static_cast<std::size_t>(root)];
    if (index < 0) {
      index = static_cast<std::int32_t>(out.patches.size());
      out.patches.emplace_back();
      sums.push_back(Eigen::Vector3d::Zero());
      squares.push_back(Eigen::Matrix3d::Zero());
    }
    out.patch_of_pixel[i] = index;
    const Eigen::Vector3d p = pointAt(grid, i);
    out.patches[static_cast<std::size_t>(index)].pixels += 1;
    out.patches[static_cast<std::size_t>(index)].plane = plane_labels[i];
    sums[static_cast<std::size_t>(index)] += p;
    squares[static_cast<std::size_t>(index)] += p * p.transpose();
  }
  // The normal of a patch on no plane is its own; a plane's patches share the plane's (the
  // fit over all of them, steadier than a square's).
  auto normalOf = [](const Eigen::Vector3d& sum, const Eigen::Matrix3d& square, double count) -> Eigen::Vector3d {
    if (count < 3) return Eigen::Vector3d::Zero();
    const Eigen::Vector3d centroid = sum / count;
    const Eigen::Matrix3d covariance = square / count - centroid * centroid.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
    // A line of points (or a single point repeated) spans no plane.
    if (!(solver.eigenvalues()[1] > 1e-12)) return Eigen::Vector3d::Zero();
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
      plane_normals[plane] = normalOf(plane_sums[plane], plane_squares[plane], plane_counts[plane]);
  }
  for (std::size_t k = 0; k < out.patches.size(); ++k) {
    SurfacePatch& patch = out.patches[k];
    patch.centroid = sums[k] / static_cast<double>(patch.pixels);
    patch.normal = patch.plane != 0 ? plane_normals[patch.plane] : normalOf(sums[k], squares[k], patch.pixels);
  }
  // The contacts: pixel pairs on one surface across two patches, counted per pair of patches.
  std::vector<std::uint64_t> keys;
  auto addContact = [&](std::size_t a, std::size_t b) {
    std::int32_t pa = out.patch_of_pixel[a];
    std::int32_t pb = out.patch_of_pixel[b];
    if (pa == pb) return;
    if (pb < pa) std::swap(pa, pb);
    keys.push_back((static_cast<std::uint64_t>(pa) << 32) | static_cast<std::uint32_t>(pb));
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (links[i] & kRight) addContact(i, i + 1);
    if (links[i] & kDown) addContact(i, i + static_cast<std::size_t>(width));
  }
  std::sort(keys.begin(), keys.end());
  out.contacts.clear();
  for (std::size_t k = 0; k < keys.size();) {
    std::size_t end = k;
    while (end < keys.size() && keys[end] == keys[k]) ++end;
    PatchContact contact;
    contact.first = static_cast<std::int32_t>(keys[k] >> 32);
    contact.second = static_cast<std::int32_t>(keys[k] & 0xffffffffu);
    contact.pairs = static_cast<std::uint32_t>(end - k);
    out.contacts.push_back(contact);
    k = end;
  }
}

}  // namespace floodplane
