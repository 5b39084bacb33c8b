// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The scene generators' random numbers: a stream of draws fixed by (seed, stream), the same on
// every platform (our own generator and arithmetic, never the standard distributions, whose
// results differ between standard libraries) and with no global state, so one seed always
// gives the same scene and two generators never disturb each other.
//
// Every draw is a statement of its own: C++ leaves open the order in which a call's arguments
// (`Eigen::Vector3d(random.uniform(), random.uniform(), ...)`) or the operands of `+` are
// evaluated, so two draws in one expression give other scenes under another compiler. Where
// the draws stand in an order that reads backwards (y before x), it is the order in which GCC
// evaluated the expression they replace: the seeds keep the scenes every recorded figure was
// measured on (test/toolkit/synth/test_scene_checksums.cpp holds them to it under GCC and Clang).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "synth/pixel_random.h"

namespace floodplane::synth {

class RandomSource {
 public:
  /// Separate `stream` numbers give independent sequences for the same seed (the room and the
  /// blocks scene of one seed).
  RandomSource(std::uint64_t seed, std::uint64_t stream) : generator_(seed, stream) {}

  /// Uniform in [0, 1).
  double uniform() { return generator_.uniform(); }

  /// Uniform in [low, high).
  double uniform(double low, double high) { return low + (high - low) * generator_.uniform(); }

  /// A whole number from `low` to `high`, both included (low <= high).
  int integer(int low, int high) {
    const double span = static_cast<double>(high) - static_cast<double>(low) + 1.0;
    const int offset = static_cast<int>(span * generator_.uniform());
    return low + (offset < high - low ? offset : high - low);
  }

  /// True with probability `probability`.
  bool chance(double probability) { return generator_.uniform() < probability; }

  /// Standard normal.
  double gaussian() { return generator_.gaussian(); }

  /// One element of a non-empty list, each equally likely.
  template <typename T>
  const T& pick(const std::vector<T>& items) {
    return items[static_cast<std::size_t>(integer(0, static_cast<int>(items.size()) - 1))];
  }

 private:
  PixelRandom generator_;
};

}  // namespace floodplane::synth
