// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Footprints of generated objects: overlap by the separating axis theorem, with a gap, and the
// support's border.

#include "synth/floor_plan.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace floodplane::synth;

constexpr double kPi = 3.14159265358979323846;

TEST(FloorPlan, FootprintsOverlapOnlyWhenNoAxisSeparatesThem) {
  const Footprint a{Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0.5), 0.0};
  EXPECT_TRUE(footprintsOverlap(a, {Eigen::Vector2d(1.8, 0), Eigen::Vector2d(1, 0.5), 0.0}, 0.0));
  EXPECT_FALSE(footprintsOverlap(a, {Eigen::Vector2d(2.2, 0), Eigen::Vector2d(1, 0.5), 0.0}, 0.0));
  // 0.2 apart: apart for a gap of 0.1, too close for a gap of 0.3.
  EXPECT_FALSE(footprintsOverlap(a, {Eigen::Vector2d(2.2, 0), Eigen::Vector2d(1, 0.5), 0.0}, 0.1));
  EXPECT_TRUE(footprintsOverlap(a, {Eigen::Vector2d(2.2, 0), Eigen::Vector2d(1, 0.5), 0.0}, 0.3));
  // A square turned 45 degrees reaches sqrt(2) * 0.5 = 0.71 from its centre along x.
  const Footprint diamond{Eigen::Vector2d(1.6, 0), Eigen::Vector2d(0.5, 0.5), kPi / 4};
  EXPECT_TRUE(footprintsOverlap(a, diamond, 0.0));
  EXPECT_FALSE(footprintsOverlap(a, {Eigen::Vector2d(1.8, 0), Eigen::Vector2d(0.5, 0.5), kPi / 4}, 0.0));
  // Corner to corner: apart although their bounding circles overlap.
  EXPECT_FALSE(footprintsOverlap({Eigen::Vector2d(0, 0), Eigen::Vector2d(0.5, 0.5), kPi / 4},
                                 {Eigen::Vector2d(1.0, 1.0), Eigen::Vector2d(0.5, 0.5), kPi / 4}, 0.0));
}

TEST(FloorPlan, FitsInsideTheSupportAndApartFromWhatIsPlaced) {
  FloorPlan plan(Eigen::Vector2d(0, 0), Eigen::Vector2d(4, 3));
  const Footprint table{Eigen::Vector2d(1, 1), Eigen::Vector2d(0.5, 0.4), 0.3};
  EXPECT_TRUE(plan.fits(table, 0.25, 0.1));
  plan.add(table);
  EXPECT_FALSE(plan.fits({Eigen::Vector2d(1.8, 1), Eigen::Vector2d(0.3, 0.3), 0.0}, 0.25, 0.1));  // too close
  EXPECT_TRUE(plan.fits({Eigen::Vector2d(3, 2), Eigen::Vector2d(0.3, 0.3), 0.0}, 0.25, 0.1));
  EXPECT_FALSE(plan.fits({Eigen::Vector2d(3.75, 2), Eigen::Vector2d(0.3, 0.3), 0.0}, 0.25, 0.1));  // over the border
  EXPECT_TRUE(plan.fits({Eigen::Vector2d(3.7, 2), Eigen::Vector2d(0.3, 0.3), 0.0}, 0.25, -1e-9));  // touching it
}

}  // namespace
