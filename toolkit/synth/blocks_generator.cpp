// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Random scanner scenes: polyhedral blocks on a table about 1 m from the structured-light
// scanner, as in the SegComp structured-light images (see scene_generator.h).

#include <cmath>
#include <stdexcept>
#include <string>

#include "synth/blocks.h"
#include "synth/camera_placement.h"
#include "synth/floor_plan.h"
#include "synth/random_source.h"
#include "synth/scanner_model.h"
#include "synth/scene_generator.h"

namespace floodplane::synth {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::uint64_t kBlocksStream = 2;  // the room of a seed draws from stream 1
constexpr int kLayoutAttempts = 20;
constexpr int kPoseAttempts = 60;
constexpr double kClusterHalfSize = 0.12;  // blocks stand within +-12 cm of the table's centre

double degrees(double value) { return value * kPi / 180.0; }

// Cylinders are one kind in three as often as each polyhedral kind: the scenes are mostly flat
// faces, with some curved surfaces.
BlockKind randomBlockKind(RandomSource& random) {
  if (random.chance(0.1)) {
    return random.chance(0.5) ? BlockKind::standing_cylinder : BlockKind::lying_cylinder;
  }
  static const std::vector<BlockKind> polyhedral{
      BlockKind::box,  BlockKind::box,           BlockKind::wedge,          BlockKind::roof,
      BlockKind::arch, BlockKind::chamfered_box, BlockKind::standing_prism, BlockKind::lying_prism};
  return random.pick(polyhedral);
}

// One block in four is dark (albedo 0.2-0.4: the scanner loses 20-75 % of their returns), the
// others light (0.5-1).
void paint(Assembly& block, RandomSource& random) {
  const double albedo = random.chance(0.25) ? random.uniform(0.2, 0.4) : random.uniform(0.5, 1.0);
  for (Primitive& part : block.parts) part.albedo = albedo;
}

struct BlocksLayout {
  Assembly blocks;
  int count = 0;
};

// 4-8 blocks on the table around its centre, kept 5-25 mm apart; one box in three carries a
// smaller block.
BlocksLayout placeBlocks(RandomSource& random) {
  BlocksLayout layout;
  FloorPlan table(Eigen::Vector2d::Constant(-kClusterHalfSize), Eigen::Vector2d::Constant(kClusterHalfSize));
  const int wanted = random.integer(5, 9);
  for (int attempt = 0; attempt < 100 && layout.count < wanted; ++attempt) {
    Assembly block = makeBlock(randomBlockKind(random), 1.0, random);
    const double yaw = random.uniform(0, 2 * kPi);
    const double y = random.uniform(-kClusterHalfSize, kClusterHalfSize);
    const double x = random.uniform(-kClusterHalfSize, kClusterHalfSize);
    const Footprint footprint{Eigen::Vector2d(x, y), block.half_size, yaw};
    if (!table.fits(footprint, random.uniform(0.005, 0.025), 0.0)) continue;
    table.add(footprint);
    paint(block, random);
    const Eigen::Isometry3d pose = standingPose(footprint.center.x(), footprint.center.y(), 0.0, yaw);
    layout.blocks.merge(block, pose, "block " + std::to_string(++layout.count));
    if (block.supports.empty() || !random.chance(1.0 / 3.0)) continue;
    // A smaller block on top, if one fits inside the box's top.
    const SupportSurface& top = block.supports.front();
    Assembly upper = makeBlock(randomBlockKind(random), 0.6, random);
    paint(upper, random);
    const double upper_yaw = random.uniform(-0.4, 0.4);
    const Footprint upper_footprint{Eigen::Vector2d::Zero(), upper.half_size, upper_yaw};
    if (FloorPlan(top.low, top.high).fits(upper_footprint, 0.0, 0.0)) {
      layout.blocks.merge(upper, pose * standingPose(0.0, 0.0, top.height, upper_yaw),
                          "block " + std::to_string(++layout.count));
    }
  }
  return layout;
}

}  // namespace

Scene generateBlocksScene(std::uint64_t seed) {
  RandomSource random(seed, kBlocksStream);
  ViewRequirements requirements;
  requirements.preview_width = 64;
  requirements.preview_height = 64;
  requirements.min_coverage = 0.98;
  requirements.min_planes = 5;
  requirements.min_plane_fraction = 0.005;
  requirements.max_plane_fraction = 0.85;  // the table fills much of the view
  requirements.max_centre_depth = 1.5;
  for (int layout_attempt = 0; layout_attempt < kLayoutAttempts; ++layout_attempt) {
    const BlocksLayout layout = placeBlocks(random);
    if (layout.count < 3) continue;
    Scene scene;
    scene.name = randomSceneName(seed);
    scene.source = "random blocks scene, seed " + std::to_string(seed);
    scene.intrinsics = scannerIntrinsics();
    // The table's top is z = 0; the floor is 0.75 m below it.
    scene.primitives.push_back(
        {"table", Box{Eigen::Vector3d(0, 0, -0.02), Eigen::Vector3d(2.4, 1.8, 0.04), Eigen::Matrix3d::Identity()},
         random.uniform(0.75, 1.0)});
    scene.primitives.push_back(
        {"floor", Rectangle{Eigen::Vector3d(0, 0, -0.75), Eigen::Vector3d(8, 0, 0), Eigen::Vector3d(0, 8, 0)}});
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& point : layout.blocks.interest) centre += point;
    centre /= static_cast<double>(layout.blocks.interest.size());

    const double azimuth = random.uniform(0, 2 * kPi);
    const Eigen::Vector2d away(std::cos(azimuth), std::sin(azimuth));  // from the camera towards the blocks
    const bool backdrop = random.chance(0.35);
    if (backdrop) {
      // A board standing on the table behind the blocks, square to the view.
      const double height = random.uniform(0.25, 0.5);
      const Eigen::Vector2d at = centre.head<2>() + random.uniform(0.2, 0.3) * away;
      scene.primitives.push_back(
          {"backdrop",
           Box{Eigen::Vector3d(at.x(), at.y(), height / 2), Eigen::Vector3d(0.9, 0.02, height),
               Eigen::AngleAxisd(azimuth + kPi / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix()},
           random.uniform(0.5, 1.0)});
    }
    for (const Primitive& part : layout.blocks.parts) scene.primitives.push_back(part);

    for (int attempt = 0; attempt < kPoseAttempts; ++attempt) {
      const double elevation = degrees(random.uniform(35, 70));
      const double distance = random.uniform(0.9, 1.1);
      const double turn = azimuth + random.uniform(-0.3, 0.3);
      const Eigen::Vector3d forward(std::cos(elevation) * std::cos(turn), std::cos(elevation) * std::sin(turn),
                                    -std::sin(elevation));
      const double jitter_y = random.gaussian();
      const double jitter_x = random.gaussian();
      const Eigen::Vector3d target = centre + 0.02 * Eigen::Vector3d(jitter_x, jitter_y, 0.0);
      const Eigen::Vector3d up = Eigen::AngleAxisd(degrees(random.uniform(-8, 8)), forward) * Eigen::Vector3d::UnitZ();
      scene.world_from_camera = lookAt(target - distance * forward, target, up);
      if (meetsRequirements(summarizeView(scene, requirements), requirements)) {
        scene.description = "Random blocks on a table, seed " + std::to_string(seed) + ": " +
                            std::to_string(layout.count) + " blocks" + (backdrop ? " before a backdrop" : "") +
                            ", seen from " + std::to_string(static_cast<int>(distance * 100.0 + 0.5)) + " cm.";
        return scene;
      }
    }
  }
  throw std::runtime_error("random blocks scene, seed " + std::to_string(seed) + ": no camera pose found in " +
                           std::to_string(kLayoutAttempts) + " layouts");
}

}  // namespace floodplane::synth
