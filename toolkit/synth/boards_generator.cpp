// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Random boards scenes: 2 cm boards standing, hung, leaning, lying and sticking out of the walls
// of a bare room, seen obliquely so that their 2 cm edges show (see scene_generator.h).

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "synth/camera_placement.h"
#include "synth/floor_plan.h"
#include "synth/random_source.h"
#include "synth/renderer.h"
#include "synth/room_shell.h"
#include "synth/scene_generator.h"

// Every draw from the random source is a statement of its own: the order in which a function's
// arguments are evaluated is unspecified, and two draws in one call could give another scene
// with another compiler.

namespace floodplane::synth {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::uint64_t kBoardsStream = 3;  // the room of a seed draws from stream 1, the blocks from 2
constexpr int kLayoutAttempts = 20;
constexpr int kPoseAttempts = 150;
constexpr double kBoardGap = 0.15;  // metres between boards, on the floor and along a wall
// The edge check renders at a quarter of the pixels: 77 pixels there are about 308 in the frame,
// pcd_segment's smallest plane at 640 x 480 (min_inliers: one pixel in a thousand).
constexpr int kEdgeCheckWidth = 320;
constexpr int kEdgeCheckHeight = 240;
constexpr std::size_t kMinEdgePixels = 77;
constexpr double kMainWallShare = 0.6;  // boards at a wall go to one main wall this often

double degrees(double value) { return value * kPi / 180.0; }

enum class BoardKind { standing, hung, leaning, lying, shelf };

const char* boardKindName(BoardKind kind) {
  switch (kind) {
    case BoardKind::standing:
      return "standing board";
    case BoardKind::hung:
      return "hung board";
    case BoardKind::leaning:
      return "leaning board";
    case BoardKind::lying:
      return "lying board";
    case BoardKind::shelf:
      return "shelf board";
  }
  return "board";
}

// A board: `width` along `width_axis`, `length` along `length_axis` (perpendicular to it), 2 cm
// thick along the box's own y (length_axis x width_axis), so that its +y and -y faces are the
// broad ones and +x, -x, +z, -z its edges (scene_generator.h).
Box board(const Eigen::Vector3d& center, const Eigen::Vector3d& width_axis, const Eigen::Vector3d& length_axis,
          double width, double length) {
  Eigen::Matrix3d rotation;
  rotation << width_axis, length_axis.cross(width_axis), length_axis;
  return Box{center, Eigen::Vector3d(width, kBoardThickness, length), rotation};
}

// A board of the scene, where the camera may look at it from, and from which side.
struct PlacedBoard {
  Eigen::Vector3d interest = Eigen::Vector3d::Zero();
  // The wall's inward normal for a board at a wall (seen from the room, at an angle to it);
  // zero for a board on the floor (seen from anywhere).
  Eigen::Vector3d facing = Eigen::Vector3d::Zero();
};

// Boards placed into a room shell: footprints on the floor (of every board, also those on the
// walls, so that nothing stands under a shelf) and stretches of the walls kept apart.
class BoardsLayout {
 public:
  BoardsLayout(RoomShell shell, RandomSource& random)
      : shell_(std::move(shell)),
        random_(random),
        floor_(Eigen::Vector2d::Zero(), Eigen::Vector2d(shell_.width, shell_.depth)),
        main_wall_(random.integer(0, 3)) {}

  bool add(BoardKind kind) {
    const double height = shell_.height;
    const double width = random_.uniform(0.2, 1.0);
    switch (kind) {
      case BoardKind::standing: {
        // On the floor, its back flat on the wall.
        const double length = random_.uniform(0.3, std::min(1.8, height - 0.3));
        return atWall(kind, width, kBoardThickness, [&](const Wall& wall, const Eigen::Vector3d& foot) {
          return std::make_pair(
              board(foot + kBoardThickness / 2 * wall.inward + length / 2 * Eigen::Vector3d::UnitZ(), wall.along,
                    Eigen::Vector3d::UnitZ(), width, length),
              Eigen::Vector3d(foot + kBoardThickness * wall.inward + length / 2 * Eigen::Vector3d::UnitZ()));
        });
      }
      case BoardKind::hung: {
        // Flat on the wall, its lower edge 0.3-1.2 m above the floor, its top 0.2 m or more
        // below the ceiling.
        const double length = random_.uniform(0.3, 1.0);
        const double bottom = random_.uniform(0.3, std::max(0.31, std::min(1.2, height - length - 0.2)));
        return atWall(kind, width, kBoardThickness, [&](const Wall& wall, const Eigen::Vector3d& foot) {
          const Eigen::Vector3d middle = foot + (bottom + length / 2) * Eigen::Vector3d::UnitZ();
          return std::make_pair(
              board(middle + kBoardThickness / 2 * wall.inward, wall.along, Eigen::Vector3d::UnitZ(), width, length),
              Eigen::Vector3d(middle + kBoardThickness * wall.inward));
        });
      }
      case BoardKind::leaning: {
        // Its back's lower edge on the floor L sin(lean) from the wall, its back's upper edge on
        // the wall at L cos(lean), as furniture.cpp's makeLeaningBoard.
        const double length = random_.uniform(0.3, std::min(1.8, height - 0.2));
        const double lean = degrees(random_.uniform(5, 25));
        const double depth = length * std::sin(lean) + kBoardThickness * std::cos(lean);
        return atWall(kind, width, depth, [&](const Wall& wall, const Eigen::Vector3d& foot) {
          const Eigen::Vector3d up = std::cos(lean) * Eigen::Vector3d::UnitZ() - std::sin(lean) * wall.inward;
          const Eigen::Vector3d out = std::cos(lean) * wall.inward + std::sin(lean) * Eigen::Vector3d::UnitZ();
          const Eigen::Vector3d back_foot = foot + length * std::sin(lean) * wall.inward;
          const Eigen::Vector3d middle = back_foot + length / 2 * up;
          return std::make_pair(board(middle + kBoardThickness / 2 * out, wall.along, up, width, length),
                                Eigen::Vector3d(middle + kBoardThickness * out));
        });
      }
      case BoardKind::lying: {
        // Flat on the floor anywhere, turned at random.
        const double length = random_.uniform(0.3, 1.8);
        for (int attempt = 0; attempt < 30; ++attempt) {
          const double yaw = random_.uniform(0, 2 * kPi);
          const double x = random_.uniform(0, shell_.width);
          const double y = random_.uniform(0, shell_.depth);
          const Footprint footprint{Eigen::Vector2d(x, y), Eigen::Vector2d(width / 2, length / 2), yaw};
          if (!floor_.fits(footprint, kBoardGap, 0.1)) continue;
          floor_.add(footprint);
          const Eigen::Vector3d across(std::cos(yaw), std::sin(yaw), 0.0);
          const Eigen::Vector3d along(-std::sin(yaw), std::cos(yaw), 0.0);
          const Eigen::Vector3d center(footprint.center.x(), footprint.center.y(), kBoardThickness / 2);
          place(kind, board(center, across, along, width, length),
                {center + kBoardThickness / 2 * Eigen::Vector3d::UnitZ(), Eigen::Vector3d::Zero()});
          return true;
        }
        return false;
      }
      case BoardKind::shelf: {
        // Sticking out of the wall level, 0.3-1.0 m along it, 0.2-0.4 m deep, 0.7-1.6 m up.
        const double along = random_.uniform(0.3, 1.0);
        const double depth = random_.uniform(0.2, 0.4);
        const double level = random_.uniform(0.7, std::min(1.6, height - 0.5));
        return atWall(kind, along, depth, [&](const Wall& wall, const Eigen::Vector3d& foot) {
          const Eigen::Vector3d middle = foot + level * Eigen::Vector3d::UnitZ() + depth / 2 * wall.inward;
          return std::make_pair(board(middle, wall.along, wall.inward, along, depth),
                                Eigen::Vector3d(middle + depth / 2 * wall.inward));
        });
      }
    }
    return false;
  }

  // The room: floor, walls, ceiling, then the boards in the order placed.
  std::vector<Primitive> primitives() const {
    Assembly room;
    addShellSurfaces(shell_, room);
    std::vector<Primitive> all = room.parts;
    all.insert(all.end(), boards_.begin(), boards_.end());
    return all;
  }

  const RoomShell& shell() const { return shell_; }
  const std::vector<PlacedBoard>& placed() const { return placed_; }

  // "2 standing boards, 1 shelf board" for the scene's description.
  std::string contents() const {
    std::string text;
    for (const auto& [kind, number] : counts_) {
      text += (text.empty() ? "" : ", ") + std::to_string(number) + " " + boardKindName(kind) + (number > 1 ? "s" : "");
    }
    return text;
  }

 private:
  // A board at a random free stretch of a wall: `make(wall, foot)` gives the board and
  // its point of interest for the point `foot` on the floor line of the wall under its middle;
  // `depth` is how far it reaches into the room (its footprint).
  template <typename Make>
  bool atWall(BoardKind kind, double width, double depth, const Make& make) {
    for (int attempt = 0; attempt < 30; ++attempt) {
      // Mostly the main wall, so that a view often shows several boards.
      const int index = random_.chance(kMainWallShare) ? main_wall_ : random_.integer(0, 3);
      const Wall& wall = shell_.walls[static_cast<std::size_t>(index)];
      if (wall.length < width + 0.4) continue;
      const double offset = random_.uniform(width / 2 + 0.2, wall.length - width / 2 - 0.2);
      if (!wallFree(index, offset - width / 2, offset + width / 2)) continue;
      const Eigen::Vector3d foot = wall.origin + offset * wall.along;
      const Eigen::Vector3d middle = foot + depth / 2 * wall.inward;
      const Footprint footprint{middle.head<2>(), Eigen::Vector2d(width / 2, depth / 2),
                                std::atan2(wall.along.y(), wall.along.x())};
      if (!floor_.fits(footprint, kBoardGap, -1e-6)) continue;
      floor_.add(footprint);
      wall_taken_[static_cast<std::size_t>(index)].emplace_back(offset - width / 2, offset + width / 2);
      const auto [box, interest] = make(wall, foot);
      place(kind, box, {interest, wall.inward});
      return true;
    }
    return false;
  }

  bool wallFree(int index, double start, double end) const {
    for (const auto& [taken_start, taken_end] : wall_taken_[static_cast<std::size_t>(index)]) {
      if (start < taken_end + kBoardGap && end > taken_start - kBoardGap) return false;
    }
    return true;
  }

  void place(BoardKind kind, const Box& box, const PlacedBoard& placed) {
    boards_.push_back({std::string(boardKindName(kind)) + " " + std::to_string(++counts_[kind]), box});
    placed_.push_back(placed);
  }

  RoomShell shell_;
  RandomSource& random_;
  FloorPlan floor_;
  int main_wall_;
  std::array<std::vector<std::pair<double, double>>, 4> wall_taken_;
  std::vector<Primitive> boards_;
  std::vector<PlacedBoard> placed_;
  std::map<BoardKind, int> counts_;
};

// Standing and leaning boards are the case (on and against walls): three in ten each;
// lying two in ten; hung and shelf boards one each.
BoardKind randomBoardKind(RandomSource& random) {
  const double draw = random.uniform();
  if (draw < 0.3) return BoardKind::standing;
  if (draw < 0.6) return BoardKind::leaning;
  if (draw < 0.8) return BoardKind::lying;
  if (draw < 0.9) return BoardKind::hung;
  return BoardKind::shelf;
}

// Whether a render shows at least one board edge (a 2 cm face) with kMinEdgePixels.
bool showsABoardEdge(const Scene& scene) {
  Scene check = scene;
  check.intrinsics = scene.intrinsics.scaledTo(kEdgeCheckWidth, kEdgeCheckHeight);
  for (const GroundTruthPlane& plane : renderScene(check, RenderSettings{}).planes) {
    if (isBoardEdgeFace(plane.primitive, plane.face) && plane.pixel_count >= kMinEdgePixels) return true;
  }
  return false;
}

// A camera 0.8-3.5 m from a board, 0.7-2.3 m above the floor; a board at a wall seen from
// 15-70 degrees to the wall's normal (left or right), a board on the floor from any side.
bool placeCamera(Scene& scene, const BoardsLayout& layout, RandomSource& random, double& distance) {
  ViewRequirements requirements;
  requirements.min_planes = 4;  // floor, a wall or two, a board's face
  const RoomShell& shell = layout.shell();
  for (int attempt = 0; attempt < kPoseAttempts; ++attempt) {
    const PlacedBoard& target_board = random.pick(layout.placed());
    Eigen::Vector3d jitter;
    for (int axis = 0; axis < 3; ++axis) jitter[axis] = random.gaussian();
    const Eigen::Vector3d target = target_board.interest + 0.05 * jitter;
    distance = random.uniform(0.8, 3.5);
    const double camera_height = random.uniform(0.7, std::min(2.3, shell.height - 0.4));
    double azimuth = random.uniform(0, 2 * kPi);
    if (target_board.facing != Eigen::Vector3d::Zero()) {
      const double side = random.chance(0.5) ? 1.0 : -1.0;
      azimuth = std::atan2(target_board.facing.y(), target_board.facing.x()) + side * degrees(random.uniform(15, 70));
    }
    const double rise = camera_height - target.z();
    if (distance < std::abs(rise) + 0.1) continue;
    const double across = std::sqrt(distance * distance - rise * rise);
    const Eigen::Vector3d position =
        target + Eigen::Vector3d(across * std::cos(azimuth), across * std::sin(azimuth), rise);
    if (position.x() < 0.3 || position.x() > shell.width - 0.3 || position.y() < 0.3 ||
        position.y() > shell.depth - 0.3) {
      continue;
    }
    const Eigen::Vector3d forward = (target - position).normalized();
    const Eigen::Vector3d up = Eigen::AngleAxisd(degrees(random.uniform(-3, 3)), forward) * Eigen::Vector3d::UnitZ();
    scene.world_from_camera = lookAt(position, target, up);
    if (meetsRequirements(summarizeView(scene, requirements), requirements) && showsABoardEdge(scene)) return true;
  }
  return false;
}

}  // namespace

std::string boardsSceneName(std::uint64_t seed) {
  char digits[32];
  std::snprintf(digits, sizeof digits, "%04llu", static_cast<unsigned long long>(seed));
  return std::string("boards_") + digits;
}

bool isBoardEdgeFace(const std::string& primitive, const std::string& face) {
  // "<kind> board <n>": three words, the last a number.
  std::istringstream words(primitive);
  std::string kind, noun, number, more;
  words >> kind >> noun >> number;
  const bool board = noun == "board" && !number.empty() &&
                     number.find_first_not_of("0123456789") == std::string::npos && !(words >> more);
  return board && (face == "+x" || face == "-x" || face == "+z" || face == "-z");
}

Scene generateBoardsScene(std::uint64_t seed) {
  RandomSource random(seed, kBoardsStream);
  for (int layout_attempt = 0; layout_attempt < kLayoutAttempts; ++layout_attempt) {
    const double width = random.uniform(3.0, 6.0);
    const double depth = random.uniform(3.0, 6.0);
    const double height = random.uniform(2.4, 3.0);
    const bool ceiling = random.chance(0.5);
    BoardsLayout layout(makeRoomShell(width, depth, height, ceiling), random);
    const int wanted = random.integer(2, 5);
    for (int b = 0; b < wanted; ++b) layout.add(randomBoardKind(random));
    if (layout.placed().size() < 2) continue;
    Scene scene;
    scene.name = boardsSceneName(seed);
    scene.source = "random boards scene, seed " + std::to_string(seed);
    scene.primitives = layout.primitives();
    double distance = 0.0;
    if (!placeCamera(scene, layout, random, distance)) continue;
    char size[96];
    std::snprintf(size, sizeof size, "%.1f x %.1f x %.1f m", layout.shell().width, layout.shell().depth,
                  layout.shell().height);
    scene.description = "Random boards scene, seed " + std::to_string(seed) + ": a room " + size +
                        (layout.shell().ceiling ? " with a ceiling" : " without a ceiling") + "; " + layout.contents() +
                        " (2 cm thick); a board seen from " + std::to_string(static_cast<int>(distance * 100.0 + 0.5)) +
                        " cm.";
    return scene;
  }
  throw std::runtime_error("random boards scene, seed " + std::to_string(seed) + ": no camera pose found in " +
                           std::to_string(kLayoutAttempts) + " layouts");
}

}  // namespace floodplane::synth
