// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <numeric>
#include <vector>

namespace floodplane {

/// Disjoint sets over 0..n-1 with path halving and union by size. The smaller root of two
/// equal-sized sets wins, so results do not depend on the order of unite() calls' arguments.
class UnionFind {
 public:
  void reset(std::size_t n) {
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), 0);
    size_.assign(n, 1);
  }

  /// Adds one singleton set and returns its id.
  std::int32_t add() {
    parent_.push_back(static_cast<std::int32_t>(parent_.size()));
    size_.push_back(1);
    return parent_.back();
  }

  std::int32_t find(std::int32_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];  // path halving
      x = parent_[x];
    }
    return x;
  }

  /// Joins the sets of a and b; returns the root of the union.
  std::int32_t unite(std::int32_t a, std::int32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return a;
    if (size_[a] < size_[b] || (size_[a] == size_[b] && b < a)) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
    return a;
  }

 private:
  std::vector<std::int32_t> parent_;
  std::vector<std::int32_t> size_;
};

}  // namespace floodplane
