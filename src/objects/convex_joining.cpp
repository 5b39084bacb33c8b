// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "objects/convex_joining.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

namespace floodplane {

bool convexContact(const SurfacePatch& a, const SurfacePatch& b, double concavity_tolerance_rad) {
  if (a.normal.isZero() || b.normal.isZero()) return false;
  const Eigen::Vector3d line = a.centroid - b.centroid;
  const double length = line.norm();
  if (!(length > 0.0)) return true;
  const double normal_angle = std::acos(std::clamp(a.normal.dot(b.normal), -1.0, 1.0));
  if (normal_angle <= concavity_tolerance_rad) {
    // Nearly parallel: one surface when the line between them runs along it, within the same
    // angle; not two parallel surfaces at a step (a box's top beside the top of the box it
    // stands on, seen across the hidden side between them).
    const double along = std::sin(concavity_tolerance_rad) * length;
    return std::abs(a.normal.dot(line)) <= along && std::abs(b.normal.dot(line)) <= along;
  }
  // LCCP's sanity criterion: the line between the centroids must not run nearly along the
  // line where the two planes meet (a singular configuration, which a step also gives).
  const Eigen::Vector3d crossing = a.normal.cross(b.normal);
  const double crossing_angle = std::acos(std::clamp(std::abs(crossing.normalized().dot(line / length)), 0.0, 1.0));
  const double normal_degrees = normal_angle * 180.0 / M_PI;
  const double least = 60.0 / (1.0 + std::exp(-0.25 * (normal_degrees - 25.0))) * M_PI / 180.0;
  if (crossing_angle < least) return false;
  return (a.normal - b.normal).dot(line) > 0.0;
}

namespace {

/// The steps of joinConvexPatches over one frame's patches, in the order they unite.
class ConvexJoiner {
 public:
  ConvexJoiner(const SurfacePatches& patches, double concavity_tolerance_rad, UnionFind& objects)
      : patches_(patches), tolerance_(concavity_tolerance_rad), objects_(objects) {}

  void run() {
    joinPlaneParts();
    judgeContacts();
    judgeAcrossStrips();
    countVotes();
    joinStrips();
  }

 private:
  /// Votes of the contacts between two surfaces at least one of which is a plane: pixel pairs
  /// in convex contacts (positive) against concave ones.
  struct Vote {
    std::int64_t first;
    std::int64_t second;
    std::int64_t pairs;
    std::int32_t patch_a;
    std::int32_t patch_b;
  };
  /// A neighbour with a normal of a patch without one.
  struct Across {
    std::int32_t middle;
    std::int32_t other;
    std::uint32_t pairs;
  };

  const SurfacePatch& patch(std::int32_t k) const { return patches_.patches[static_cast<std::size_t>(k)]; }

  /// The touching patches of one plane are one surface: a plane seen in two parts (a box's top
  /// on either side of what stands before it) is two, as the image shows them. Then the surface
  /// a patch is part of: its plane's part (as a negative number), or itself on none.
  void joinPlaneParts() {
    const std::size_t count = patches_.patches.size();
    objects_.reset(count);
    for (const PatchContact& contact : patches_.contacts) {
      const std::uint32_t plane = patch(contact.first).plane;
      if (plane != 0 && plane == patch(contact.second).plane) objects_.unite(contact.first, contact.second);
    }
    surface_of_.resize(count);
    for (std::size_t k = 0; k < count; ++k) {
      const auto id = static_cast<std::int32_t>(k);
      surface_of_[k] = patches_.patches[k].plane != 0 ? -1 - static_cast<std::int64_t>(objects_.find(id)) : id;
    }
    best_.assign(count, -1);
    best_pairs_.assign(count, 0);
  }

  /// Keeps the contact with the most pixel pairs of each patch that spans no plane.
  void offer(std::int32_t strip, std::int32_t other, std::uint32_t pairs) {
    const auto k = static_cast<std::size_t>(strip);
    if (pairs > best_pairs_[k]) {
      best_pairs_[k] = pairs;
      best_[k] = other;
    }
  }

  /// Two patches with normals that touch, directly or across a patch with none (a strip along
  /// a crease), weighing `pairs` pixel pairs.
  void judge(std::int32_t first, std::int32_t second, std::uint32_t pairs) {
    const std::int64_t sa = surface_of_[static_cast<std::size_t>(first)];
    const std::int64_t sb = surface_of_[static_cast<std::size_t>(second)];
    if (sa == sb) return;
    const SurfacePatch& a = patch(first);
    const SurfacePatch& b = patch(second);
    const bool convex = convexContact(a, b, tolerance_);
    if (a.plane == 0 && b.plane == 0) {
      if (convex) objects_.unite(first, second);
      return;
    }
    const std::int64_t weight = convex ? pairs : -static_cast<std::int64_t>(pairs);
    votes_.push_back({std::min(sa, sb), std::max(sa, sb), weight, first, second});
  }

  void judgeContacts() {
    for (const PatchContact& contact : patches_.contacts) {
      const bool a_flat = patch(contact.first).normal.isZero();
      const bool b_flat = patch(contact.second).normal.isZero();
      if (!a_flat && !b_flat) {
        judge(contact.first, contact.second, contact.pairs);
        continue;
      }
      if (a_flat) offer(contact.first, contact.second, contact.pairs);
      if (b_flat) offer(contact.second, contact.first, contact.pairs);
      if (a_flat && !b_flat) across_.push_back({contact.first, contact.second, contact.pairs});
      if (b_flat && !a_flat) across_.push_back({contact.second, contact.first, contact.pairs});
    }
  }

  /// The patches with normals on either side of a strip without one, judged as touching.
  void judgeAcrossStrips() {
    std::sort(across_.begin(), across_.end(), [](const Across& x, const Across& y) { return x.middle < y.middle; });
    for (std::size_t k = 0; k < across_.size();) {
      std::size_t end = k;
      while (end < across_.size() && across_[end].middle == across_[k].middle) ++end;
      for (std::size_t i = k; i < end; ++i) {
        for (std::size_t j = i + 1; j < end; ++j) {
          judge(std::min(across_[i].other, across_[j].other), std::max(across_[i].other, across_[j].other),
                std::min(across_[i].pairs, across_[j].pairs));
        }
      }
      k = end;
    }
  }

  /// Two surfaces one of which is a plane are joined when their contacts' votes sum positive.
  void countVotes() {
    std::sort(votes_.begin(), votes_.end(), [](const Vote& x, const Vote& y) {
      return x.first != y.first ? x.first < y.first : x.second < y.second;
    });
    for (std::size_t k = 0; k < votes_.size();) {
      std::size_t end = k;
      std::int64_t sum = 0;
      while (end < votes_.size() && votes_[end].first == votes_[k].first && votes_[end].second == votes_[k].second) {
        sum += votes_[end].pairs;
        ++end;
      }
      if (sum > 0) objects_.unite(votes_[k].patch_a, votes_[k].patch_b);
      k = end;
    }
  }

  /// Each strip without a normal joins the patch it shares the most pixel pairs with.
  void joinStrips() {
    for (std::size_t k = 0; k < best_.size(); ++k) {
      if (best_[k] >= 0) objects_.unite(static_cast<std::int32_t>(k), best_[k]);
    }
  }

  const SurfacePatches& patches_;
  const double tolerance_;
  UnionFind& objects_;
  std::vector<std::int64_t> surface_of_;
  std::vector<std::int32_t> best_;
  std::vector<std::uint32_t> best_pairs_;
  std::vector<Vote> votes_;
  std::vector<Across> across_;
};

}  // namespace

void joinConvexPatches(const SurfacePatches& patches, double concavity_tolerance_rad, UnionFind& objects) {
  ConvexJoiner(patches, concavity_tolerance_rad, objects).run();
}

void absorbFragments(const SurfacePatches& patches, std::uint32_t min_pixels, UnionFind& objects) {
  const std::size_t count = patches.patches.size();
  std::vector<std::uint32_t> pixels(count, 0);
  for (std::size_t k = 0; k < count; ++k) {
    pixels[static_cast<std::size_t>(objects.find(static_cast<std::int32_t>(k)))] += patches.patches[k].pixels;
  }
  // Pixel pairs from each small group to each large one, summed over their contacts.
  struct Link {
    std::int32_t small;
    std::int32_t large;
    std::uint32_t pairs;
  };
  std::vector<Link> links;
  for (const PatchContact& contact : patches.contacts) {
    const std::int32_t a = objects.find(contact.first);
    const std::int32_t b = objects.find(contact.second);
    if (a == b) continue;
    const bool a_small = pixels[static_cast<std::size_t>(a)] < min_pixels;
    const bool b_small = pixels[static_cast<std::size_t>(b)] < min_pixels;
    if (a_small && !b_small) links.push_back({a, b, contact.pairs});
    if (b_small && !a_small) links.push_back({b, a, contact.pairs});
  }
  std::sort(links.begin(), links.end(),
            [](const Link& x, const Link& y) { return x.small != y.small ? x.small < y.small : x.large < y.large; });
  std::vector<std::int32_t> target(count, -1);
  std::vector<std::uint32_t> target_pairs(count, 0);
  for (std::size_t k = 0; k < links.size();) {
    std::size_t end = k;
    std::uint32_t sum = 0;
    while (end < links.size() && links[end].small == links[k].small && links[end].large == links[k].large) {
      sum += links[end].pairs;
      ++end;
    }
    const auto small = static_cast<std::size_t>(links[k].small);
    if (sum > target_pairs[small]) {
      target_pairs[small] = sum;
      target[small] = links[k].large;
    }
    k = end;
  }
  for (std::size_t k = 0; k < count; ++k) {
    if (target[k] >= 0) objects.unite(static_cast<std::int32_t>(k), target[k]);
  }
}

}  // namespace floodplane
