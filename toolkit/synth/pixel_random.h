// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The renderer's random numbers: one small generator per pixel, seeded from the render seed
// and the pixel's row-major index.
//
// Why per pixel: a pixel's noise then depends only on (seed, pixel), not on how many draws
// other pixels made, so the same scene and seed give the same cloud bit for bit, and editing
// one object leaves the noise everywhere else unchanged. Why our own generator and Gaussian:
// std::normal_distribution differs between standard libraries, which would change the bytes.

#include <cmath>
#include <cstdint>

namespace floodplane::synth {

class PixelRandom {
 public:
  PixelRandom(std::uint64_t seed, std::uint64_t pixel_index) : state_(mix(mix(seed) + pixel_index)) {}

  /// Uniform in [0, 1), 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  /// Standard normal by the Box-Muller transform (cosine branch only, so every Gaussian
  /// takes exactly two uniforms).
  double gaussian() {
    constexpr double kTwoPi = 6.283185307179586476925;
    const double u1 = 1.0 - uniform();  // in (0, 1], so the logarithm is finite
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(kTwoPi * u2);
  }

 private:
  // splitmix64 (Steele, Lea and Flood 2014): a Weyl sequence through a bijective mixer.
  static std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  std::uint64_t next() {
    state_ += 0x9e3779b97f4a7c15ULL;
    return mix(state_);
  }

  std::uint64_t state_;
};

}  // namespace floodplane::synth
