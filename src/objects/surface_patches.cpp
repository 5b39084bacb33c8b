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

namespace {

/// Whether a column (row) and the next are in one square, looked up: no division per point.
std::vector<std::uint8_t> sameSquareAsNext(int length, int side) {
  std::vector<std::uint8_t> same(static_cast<std::size_t>(std::max(length, 0)));
  for (int c = 0; c < length; ++c) same[static_cast<std::size_t>(c)] = (c + 1) % side != 0;
  return same;
}

/// The patches' forest: every link points to a lower number, so that one pass in order finds
/// each point's root (which a union by size would not keep).
struct LowerForest {
  std::vector<std::int32_t>& parent;
  std::int32_t root(std::int32_t x) {
    while (parent[static_cast<std::size_t>(x)] != x) {
      parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
      x = parent[static_cast<std::size_t>(x)];
    }
    return x;
  }
  void link(std::int32_t a, std::int32_t b) {
    a = root(a);
    b = root(b);
    if (a < b) parent[static_cast<std::size_t>(b)] = a;
    if (b < a) parent[static_cast<std::size_t>(a)] = b;
  }
};

/// Neighbours on one surface: within the tolerance at the nearer one's range (the tolerance
/// grows with the range).
struct SurfaceTest {
  const PointGrid& grid;
  const std::vector<std::size_t>& pixel_of;
  const std::vector<float>& tolerance_of;
  bool operator()(std::size_t a, std::size_t b) const {
    const float* p = grid.point(pixel_of[a]);
    const float* q = grid.point(pixel_of[b]);
    const float dx = p[0] - q[0];
    const float dy = p[1] - q[1];
    const float dz = p[2] - q[2];
    const float tolerance = std::min(tolerance_of[a], tolerance_of[b]);
    return dx * dx + dy * dy + dz * dz <= tolerance * tolerance;
  }
};

/// One raster pass over the object points: each point's right and upper neighbours on one
/// surface (work.right_of, work.above_of), and the patches as a LowerForest in work.parent
/// (each point joins its left or upper neighbour in the patch, two sets meeting at a point are
/// linked). Two neighbours on one surface are in one patch when they share a plane (or both
/// are on none) within one square. The lower neighbour is found by a second cursor a row ahead.
void linkNeighbours(const PointGrid& grid, const std::vector<std::uint32_t>& plane_labels, const ObjectPoints& points,
                    const SurfaceStep& step, int side, SurfaceWorkspace& work) {
  const int width = grid.width;
  const int height = grid.height;
  const std::vector<std::size_t>& pixel_of = points.pixels;
  const std::size_t count = pixel_of.size();
  work.tolerance_of.resize(count);
  for (std::size_t k = 0; k < count; ++k) work.tolerance_of[k] = static_cast<float>(step.tolerance(points.ranges[k]));
  work.parent.resize(count);
  work.up_in_patch.assign(count, -1);
  work.right_of.assign(count, -1);
  work.above_of.assign(count, -1);
  LowerForest forest{work.parent};
  const SurfaceTest onOneSurface{grid, pixel_of, work.tolerance_of};
  const std::vector<std::uint8_t> column_joins = sameSquareAsNext(width, side);
  const std::vector<std::uint8_t> row_joins = sameSquareAsNext(height, side);
  bool left_in_patch = false;
  std::size_t cursor = 0;
  std::size_t row_start = 0;
  int row = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = pixel_of[k];
    for (; i >= row_start + static_cast<std::size_t>(width); ++row) row_start += static_cast<std::size_t>(width);
    const int x = static_cast<int>(i - row_start);
    const auto self = static_cast<std::int32_t>(k);
    const std::int32_t up = work.up_in_patch[k];
    work.parent[k] = left_in_patch ? self - 1 : (up >= 0 ? up : self);
    if (left_in_patch && up >= 0) forest.link(self - 1, up);
    left_in_patch = false;
    if (x + 1 < width && k + 1 < count && pixel_of[k + 1] == i + 1 && onOneSurface(k, k + 1)) {
      work.right_of[k] = self + 1;
      left_in_patch = plane_labels[i] == plane_labels[i + 1] && column_joins[static_cast<std::size_t>(x)];
    }
    const std::size_t below = i + static_cast<std::size_t>(width);
    if (row + 1 >= height) continue;
    cursor = std::max(cursor, k);
    while (cursor < count && pixel_of[cursor] < below) ++cursor;
    if (cursor < count && pixel_of[cursor] == below && onOneSurface(k, cursor)) {
      work.above_of[cursor] = self;
      if (plane_labels[i] == plane_labels[below] && row_joins[static_cast<std::size_t>(row)])
        work.up_in_patch[cursor] = self;
    }
  }
}

/// Two patches as one number, the lower first.
std::uint64_t pairKey(std::int32_t a, std::int32_t b) {
  if (b < a) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

/// A run of pixels of one patch (up to a square's side along a row), summed in registers and
/// added to the patch's sums once.
struct RunSums {
  std::int32_t patch = -1;
  std::uint32_t pixels = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;

  void add(const float* p) {
    const double x = p[0];
    const double y = p[1];
    const double z = p[2];
    pixels += 1;
    sum += Eigen::Vector3d(x, y, z);
    xx += x * x;
    xy += x * y;
    xz += x * z;
    yy += y * y;
    yz += y * z;
    zz += z * z;
  }
  void flush(SurfacePatches& out, SurfaceWorkspace& work) {
    if (patch < 0) return;
    const auto r = static_cast<std::size_t>(patch);
    out.patches[r].pixels += pixels;
    work.sums[r] += sum;
    Eigen::Matrix3d& m = work.squares[r];
    m(0, 0) += xx;
    m(0, 1) += xy;
    m(0, 2) += xz;
    m(1, 1) += yy;
    m(1, 2) += yz;
    m(2, 2) += zz;
    *this = RunSums{};
  }
};

/// Numbers the patches in raster order of their first pixel (out.patch_of_point), sums their
/// points (work.sums, work.squares) and gathers the pixel pairs on one surface across two
/// patches (work.crossings), from linkNeighbours' forest.
void numberPatches(const PointGrid& grid, const std::vector<std::uint32_t>& plane_labels,
                   const std::vector<std::size_t>& pixel_of, SurfacePatches& out, SurfaceWorkspace& work) {
  const std::size_t count = pixel_of.size();
  out.patches.clear();
  std::vector<std::int32_t>& patch_of = out.patch_of_point;
  patch_of.assign(count, -1);
  work.index_of_root.assign(count, -1);
  work.sums.clear();
  work.squares.clear();
  work.crossings.clear();
  RunSums run;
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = pixel_of[k];
    // Its parent, lower, has its root as its parent already.
    std::int32_t& link = work.parent[k];
    link = work.parent[static_cast<std::size_t>(link)];
    std::int32_t& index = work.index_of_root[static_cast<std::size_t>(link)];
    if (index < 0) {
      index = static_cast<std::int32_t>(out.patches.size());
      out.patches.emplace_back();
      out.patches.back().plane = plane_labels[i];
      work.sums.push_back(Eigen::Vector3d::Zero());
      work.squares.push_back(Eigen::Matrix3d::Zero());
    }
    patch_of[k] = index;
    // The pixel pairs on one surface with the left and upper neighbours (numbered already).
    const auto self = static_cast<std::int32_t>(k);
    if (k > 0 && work.right_of[k - 1] == self && patch_of[k - 1] != index)
      work.crossings.push_back(pairKey(patch_of[k - 1], index));
    const std::int32_t above = work.above_of[k];
    if (above >= 0 && patch_of[static_cast<std::size_t>(above)] != index)
      work.crossings.push_back(pairKey(patch_of[static_cast<std::size_t>(above)], index));
    if (index != run.patch) {
      run.flush(out, work);
      run.patch = index;
    }
    run.add(grid.point(i));
  }
  run.flush(out, work);
  for (Eigen::Matrix3d& m : work.squares)
    m.triangularView<Eigen::StrictlyLower>() = m.transpose().triangularView<Eigen::StrictlyLower>();
}

/// The normal of points with these sums (towards the sensor), zero where they span no plane:
/// a line of points (or a single point repeated). A patch on no plane (`own`) must be at least
/// a pixel footprint wide across (the spread of its points' narrower direction) for its own
/// normal to mean anything: a strip one or two pixels wide along a crease (between a box's top
/// and its front) has none, and joins the patch it shares the most pixel pairs with instead.
Eigen::Vector3d normalOf(const SurfaceStep& step, const Eigen::Vector3d& sum, const Eigen::Matrix3d& square,
                         double pixels, bool own) {
  if (pixels < 3) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d centroid = sum / pixels;
  const Eigen::Matrix3d covariance = square / pixels - centroid * centroid.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(covariance);
  const double footprint = step.pitch * centroid.norm();
  const double least = own ? footprint * footprint : 1e-12;
  if (!(solver.eigenvalues()[1] > least)) return Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = solver.eigenvectors().col(0);
  return normal.dot(centroid) > 0.0 ? Eigen::Vector3d(-normal) : normal;
}

/// The patches' centroids and normals: a patch on no plane has its own; a plane's patches
/// share the plane's (the fit over all of them, steadier than a square's).
void fitPatches(const SurfaceStep& step, const SurfaceWorkspace& work, SurfacePatches& out) {
  std::uint32_t largest_plane = 0;
  for (const SurfacePatch& patch : out.patches) largest_plane = std::max(largest_plane, patch.plane);
  std::vector<Eigen::Vector3d> plane_sums(largest_plane + 1, Eigen::Vector3d::Zero());
  std::vector<Eigen::Matrix3d> plane_squares(largest_plane + 1, Eigen::Matrix3d::Zero());
  std::vector<double> plane_counts(largest_plane + 1, 0.0);
  for (std::size_t k = 0; k < out.patches.size(); ++k) {
    const std::uint32_t plane = out.patches[k].plane;
    if (plane == 0) continue;
    plane_sums[plane] += work.sums[k];
    plane_squares[plane] += work.squares[k];
    plane_counts[plane] += out.patches[k].pixels;
  }
  std::vector<Eigen::Vector3d> plane_normals(largest_plane + 1, Eigen::Vector3d::Zero());
  for (std::uint32_t plane = 1; plane <= largest_plane; ++plane) {
    if (plane_counts[plane] > 0)
      plane_normals[plane] = normalOf(step, plane_sums[plane], plane_squares[plane], plane_counts[plane], false);
  }
  for (std::size_t k = 0; k < out.patches.size(); ++k) {
    SurfacePatch& patch = out.patches[k];
    patch.centroid = work.sums[k] / static_cast<double>(patch.pixels);
    patch.normal = patch.plane != 0 ? plane_normals[patch.plane]
                                    : normalOf(step, work.sums[k], work.squares[k], patch.pixels, true);
  }
}

/// Counts per pair of patches in an open-addressing table kept at most half full (a pair of
/// squares meets along up to a side's pixels, so the pairs are many and the contacts few).
class PairCounter {
 public:
  PairCounter(std::vector<std::uint64_t>& keys, std::vector<std::uint32_t>& counts, std::size_t expected)
      : keys_(keys), counts_(counts) {
    std::size_t slots = 64;
    while (slots < 8 * expected) slots *= 2;
    keys_.assign(slots, kEmpty);
    counts_.assign(slots, 0);
  }
  void add(std::uint64_t key) {
    const std::size_t slot = find(keys_, key);
    if (keys_[slot] == kEmpty) {
      keys_[slot] = key;
      ++used_;
    }
    ++counts_[slot];
    if (2 * used_ > keys_.size()) grow();
  }
  std::size_t used() const { return used_; }
  /// Every pair counted, in no particular order.
  template <class Visit>
  void forEach(Visit visit) const {
    for (std::size_t j = 0; j < keys_.size(); ++j)
      if (keys_[j] != kEmpty) visit(keys_[j], counts_[j]);
  }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  static std::size_t find(const std::vector<std::uint64_t>& keys, std::uint64_t key) {
    const std::size_t mask = keys.size() - 1;
    std::size_t slot = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 40) & mask;
    while (keys[slot] != key && keys[slot] != kEmpty) slot = (slot + 1) & mask;
    return slot;
  }
  void grow() {
    std::vector<std::uint64_t> old_keys(2 * keys_.size(), kEmpty);
    std::vector<std::uint32_t> old_counts(2 * keys_.size(), 0);
    old_keys.swap(keys_);
    old_counts.swap(counts_);
    for (std::size_t j = 0; j < old_keys.size(); ++j) {
      if (old_keys[j] == kEmpty) continue;
      const std::size_t slot = find(keys_, old_keys[j]);
      keys_[slot] = old_keys[j];
      counts_[slot] = old_counts[j];
    }
  }
  std::vector<std::uint64_t>& keys_;
  std::vector<std::uint32_t>& counts_;
  std::size_t used_ = 0;
};

/// The contacts: the crossings counted per pair of patches, sorted.
void countContacts(SurfaceWorkspace& work, SurfacePatches& out) {
  PairCounter counter(work.table_keys, work.table_pairs, out.patches.size());
  for (const std::uint64_t key : work.crossings) counter.add(key);
  out.contacts.clear();
  out.contacts.reserve(counter.used());
  counter.forEach([&out](std::uint64_t key, std::uint32_t pairs) {
    PatchContact contact;
    contact.first = static_cast<std::int32_t>(key >> 32);
    contact.second = static_cast<std::int32_t>(key & 0xffffffffu);
    contact.pairs = pairs;
    out.contacts.push_back(contact);
  });
  std::sort(out.contacts.begin(), out.contacts.end(), [](const PatchContact& x, const PatchContact& z) {
    return x.first != z.first ? x.first < z.first : x.second < z.second;
  });
}

}  // namespace

void buildSurfacePatches(const PointGrid& grid, const std::vector<std::uint32_t>& plane_labels,
                         const ObjectPoints& points, const SurfaceStep& step, int side, SurfacePatches& out,
                         SurfaceWorkspace& work) {
  linkNeighbours(grid, plane_labels, points, step, std::max(side, 1), work);
  numberPatches(grid, plane_labels, points.pixels, out, work);
  fitPatches(step, work, out);
  countContacts(work, out);
}

}  // namespace floodplane
