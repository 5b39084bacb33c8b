// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "objects/convex_joining.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace floodplane {

bool convexContact(const SurfacePatch& a, const SurfacePatch& b, double concavity_tolerance_rad) {
  if (a.normal.isZero() || b.normal.isZero()) return false;
  if (a.normal.dot(b.normal) >= std::cos(concavity_tolerance_rad)) return true;
  return (a.normal - b.normal).dot(a.centroid - b.centroid) > 0.0;
}

void joinConvexPatches(const SurfacePatches& patches, double concavity_tolerance_rad, UnionFind& objects) {
  const std::size_t count = patches.patches.size();
  objects.reset(count);
  // The contact with the most pixel pairs of each patch that spans no plane.
  std::vector<std::int32_t> best(count, -1);
  std::vector<std::uint32_t> best_pairs(count, 0);
  auto offer = [&](std::int32_t patch, std::int32_t other, std::uint32_t pairs) {
    const auto k = static_cast<std::size_t>(patch);
    if (!patches.patches[k].normal.isZero()) return;
    if (pairs > best_pairs[k]) {
      best_pairs[k] = pairs;
      best[k] = other;
    }
  };
  for (const PatchContact& contact : patches.contacts) {
    const SurfacePatch& a = patches.patches[static_cast<std::size_t>(contact.first)];
    const SurfacePatch& b = patches.patches[static_cast<std::size_t>(contact.second)];
    if (convexContact(a, b, concavity_tolerance_rad)) objects.unite(contact.first, contact.second);
    offer(contact.first, contact.second, contact.pairs);
    offer(contact.second, contact.first, contact.pairs);
  }
  for (std::size_t k = 0; k < count; ++k) {
    if (best[k] >= 0) objects.unite(static_cast<std::int32_t>(k), best[k]);
  }
}

}  // namespace floodplane
