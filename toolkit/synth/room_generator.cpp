// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Random rooms: a shell with openings, furniture of one of three kinds placed without
// overlaps, and a camera aimed at one of the objects (see scene_generator.h).

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "synth/camera_placement.h"
#include "synth/floor_plan.h"
#include "synth/furniture.h"
#include "synth/random_source.h"
#include "synth/room_shell.h"
#include "synth/scene_generator.h"

namespace floodplane::synth {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::uint64_t kRoomStream = 1;  // the blocks scene of a seed draws from stream 2
constexpr int kLayoutAttempts = 20;
constexpr int kPoseAttempts = 150;
constexpr double kObjectGap = 0.25;     // metres between footprints of furniture on the floor
constexpr double kWallGap = 0.15;       // metres between openings and objects along a wall
constexpr double kDoorClearance = 0.9;  // metres kept free in front of a door

double degrees(double value) { return value * kPi / 180.0; }

enum class RoomKind { office, hall, storage };

// "1 box", "2 boxes", "2 shelves".
std::string plural(const std::string& noun, int number) {
  if (number == 1) return noun;
  if (noun == "shelf") return "shelves";
  return noun + (noun.back() == 'x' || noun.back() == 's' ? "es" : "s");
}

const char* roomKindName(RoomKind kind) {
  switch (kind) {
    case RoomKind::office:
      return "office";
    case RoomKind::hall:
      return "hall";
    case RoomKind::storage:
      return "storage";
  }
  return "room";
}

// Places furniture into a room shell: footprints on the floor kept apart, intervals along
// the walls kept free, names numbered per kind ("table 2 top").
class RoomLayout {
 public:
  RoomLayout(RoomShell shell, RandomSource& random)
      : shell_(std::move(shell)),
        random_(random),
        floor_(Eigen::Vector2d::Zero(), Eigen::Vector2d(shell_.width, shell_.depth)) {}

  // An opening in a random wall where it fits; a floor-level one keeps the floor in front free.
  bool addOpening(Opening opening) {
    const double width = opening.end - opening.start;
    for (int attempt = 0; attempt < 20; ++attempt) {
      const int index = random_.integer(0, 3);
      const Wall& wall = shell_.walls[static_cast<std::size_t>(index)];
      if (wall.length < width + 0.6) continue;
      const double start = random_.uniform(0.3, wall.length - width - 0.3);
      if (!wallFree(index, start, start + width)) continue;
      const Eigen::Vector3d centre = wall.poseAt(start + width / 2, kDoorClearance / 2).translation();
      const Footprint front{centre.head<2>(), Eigen::Vector2d(width / 2, kDoorClearance / 2), wallYaw(wall)};
      if (opening.bottom == 0.0 && !floor_.fits(front, 0.0, -1e-6)) continue;
      if (opening.bottom == 0.0) floor_.add(front);
      opening.start = start;
      opening.end = start + width;
      shell_.openings[static_cast<std::size_t>(index)].push_back(opening);
      wall_taken_[static_cast<std::size_t>(index)].emplace_back(start, start + width);
      const Eigen::Vector3d middle = wall.poseAt(start + width / 2, 0).translation();
      room_.interest.push_back(middle + (opening.bottom + opening.top) / 2 * Eigen::Vector3d::UnitZ());
      count(opening.door ? "door" : "recess");
      return true;
    }
    return false;
  }

  // Anywhere on the floor, turned square to the walls or at random.
  bool placeOnFloor(const Assembly& object, const std::string& kind) {
    for (int attempt = 0; attempt < 40; ++attempt) {
      double yaw = 0.0;
      if (random_.chance(0.5)) {
        const int quarter_turns = random_.integer(0, 3);
        yaw = quarter_turns * kPi / 2 + random_.uniform(-0.1, 0.1);
      } else {
        yaw = random_.uniform(0, 2 * kPi);
      }
      const double y = random_.uniform(0, shell_.depth);
      const double x = random_.uniform(0, shell_.width);
      const Footprint footprint{Eigen::Vector2d(x, y), object.half_size, yaw};
      if (!floor_.fits(footprint, kObjectGap, 0.1)) continue;
      place(object, kind, standingPose(footprint.center.x(), footprint.center.y(), 0, yaw), footprint);
      return true;
    }
    return false;
  }

  // Back against a wall (distance 0), or standing `distance` in front of it (a column); only an
  // object touching the wall takes a stretch of it.
  bool placeAtWall(const Assembly& object, const std::string& kind, double distance = 0.0) {
    const double half_width = object.half_size.x();
    for (int attempt = 0; attempt < 30; ++attempt) {
      const int index = random_.integer(0, 3);
      const Wall& wall = shell_.walls[static_cast<std::size_t>(index)];
      if (wall.length < 2 * half_width + 0.2) continue;
      const double offset = random_.uniform(half_width + 0.1, wall.length - half_width - 0.1);
      if (distance == 0.0 && !wallFree(index, offset - half_width, offset + half_width)) continue;
      const Eigen::Isometry3d pose = wall.poseAt(offset, object.half_size.y() + distance);
      const Footprint footprint{pose.translation().head<2>(), object.half_size, wallYaw(wall)};
      if (!floor_.fits(footprint, distance == 0.0 ? kObjectGap : 0.4, -1e-6)) continue;
      if (distance == 0.0)
        wall_taken_[static_cast<std::size_t>(index)].emplace_back(offset - half_width, offset + half_width);
      place(object, kind, pose, footprint);
      return true;
    }
    return false;
  }

  // Up to `items` small objects on the supports (table top, shelves) of the object placed last.
  void addItems(int items) {
    for (int item = 0; item < items && !supports_.empty(); ++item) {
      Support& support =
          supports_[static_cast<std::size_t>(random_.integer(0, static_cast<int>(supports_.size()) - 1))];
      const SupportSurface& surface = support.surface;
      const Assembly object = makeTableItem(surface.clearance - 0.02, random_);
      if (object.parts.empty()) continue;
      for (int attempt = 0; attempt < 15; ++attempt) {
        const double yaw = random_.uniform(0, 2 * kPi);
        const double y = random_.uniform(surface.low.y(), surface.high.y());
        const double x = random_.uniform(surface.low.x(), surface.high.x());
        const Footprint footprint{Eigen::Vector2d(x, y), object.half_size, yaw};
        if (!support.plan.fits(footprint, 0.03, 0.0)) continue;
        support.plan.add(footprint);
        const Eigen::Isometry3d on_support =
            standingPose(footprint.center.x(), footprint.center.y(), surface.height, yaw);
        room_.merge(object, support.pose * on_support, "item " + std::to_string(++item_count_));
        break;
      }
    }
  }

  // The room: the shell's surfaces first (floor, walls, openings, ceiling), then the furniture
  // in the order placed.
  Assembly finish() const {
    Assembly all;
    addShellSurfaces(shell_, all);
    all.parts.insert(all.parts.end(), room_.parts.begin(), room_.parts.end());
    all.interest = room_.interest;
    return all;
  }

  const RoomShell& shell() const { return shell_; }

  // "2 tables, 1 shelf, 1 door" for the scene's description.
  std::string contents() const {
    std::string text;
    for (const auto& [kind, number] : counts_) {
      text += (text.empty() ? "" : ", ") + std::to_string(number) + " " + plural(kind, number);
    }
    return text;
  }

 private:
  static double wallYaw(const Wall& wall) { return std::atan2(wall.along.y(), wall.along.x()); }

  bool wallFree(int index, double start, double end) const {
    for (const auto& [taken_start, taken_end] : wall_taken_[static_cast<std::size_t>(index)]) {
      if (start < taken_end + kWallGap && end > taken_start - kWallGap) return false;
    }
    return true;
  }

  void place(const Assembly& object, const std::string& kind, const Eigen::Isometry3d& pose,
             const Footprint& footprint) {
    floor_.add(footprint);
    room_.merge(object, pose, kind + " " + std::to_string(count(kind)));
    supports_.clear();
    for (const SupportSurface& surface : object.supports) {
      supports_.push_back({surface, pose, FloorPlan(surface.low, surface.high)});
    }
  }

  int count(const std::string& kind) { return ++counts_[kind]; }

  RoomShell shell_;
  RandomSource& random_;
  FloorPlan floor_;
  std::array<std::vector<std::pair<double, double>>, 4> wall_taken_;
  Assembly room_;
  std::map<std::string, int> counts_;
  int item_count_ = 0;
  // The supports of the object placed last, each with what already stands on it.
  struct Support {
    SupportSurface surface;
    Eigen::Isometry3d pose;
    FloorPlan plan;
  };
  std::vector<Support> supports_;
};

Opening randomDoor(double room_height, RandomSource& random) {
  const double width = random.uniform(0.8, 1.0);
  const double top = random.uniform(1.95, std::min(2.2, room_height - 0.2));
  const double depth = random.uniform(0.04, 0.15);
  return {0.0, width, 0.0, top, depth, true};
}

// A niche in the wall (0.4-1.4 m wide, from 0.4-1.2 m above the floor) or, one time in three, an
// alcove from the floor (0.6-1.6 m wide, up to 2.2 m); 0.15-0.6 m deep.
Opening randomRecess(double room_height, RandomSource& random) {
  if (random.chance(1.0 / 3.0)) {
    const double width = random.uniform(0.6, 1.6);
    const double top = random.uniform(1.0, std::min(2.2, room_height - 0.2));
    const double depth = random.uniform(0.2, 0.6);
    return {0.0, width, 0.0, top, depth, false};
  }
  const double width = random.uniform(0.4, 1.4);
  const double bottom = random.uniform(0.4, 1.2);
  const double top = bottom + random.uniform(0.3, std::max(0.31, std::min(1.2, room_height - bottom - 0.3)));
  const double depth = random.uniform(0.15, 0.5);
  return {0.0, width, bottom, top, depth, false};
}

void addTables(RoomLayout& layout, int tables, RandomSource& random) {
  double height = random.uniform(0.65, 0.8);
  for (int t = 0; t < tables; ++t) {
    // Often the next table has the same height: coplanar tops, separate planes.
    if (t > 0 && !random.chance(0.5)) height = random.uniform(0.65, 0.8);
    if (layout.placeOnFloor(makeTable(height, random), "table")) layout.addItems(random.integer(1, 5));
  }
}

// A column 0.15-1 m out of a wall (the distance drawn before the column).
void addColumn(RoomLayout& layout, double height, RandomSource& random) {
  const double depth = random.uniform(0.15, 1.0);
  layout.placeAtWall(makeColumn(height, random), "column", depth);
}

void addShelves(RoomLayout& layout, int shelves, RandomSource& random) {
  for (int s = 0; s < shelves; ++s) {
    if (layout.placeAtWall(makeShelf(layout.shell().height - 0.3, random), "shelf")) {
      layout.addItems(random.integer(0, 4));
    }
  }
}

void repeat(int times, const std::function<void()>& action) {
  for (int i = 0; i < times; ++i) action();
}

void furnishOffice(RoomLayout& layout, RandomSource& random) {
  const double height = layout.shell().height;
  repeat(random.integer(0, 1), [&] { layout.addOpening(randomDoor(height, random)); });
  repeat(random.integer(0, 1), [&] { layout.addOpening(randomRecess(height, random)); });
  addTables(layout, random.integer(1, 3), random);
  addShelves(layout, random.integer(0, 2), random);
  repeat(random.integer(1, 3), [&] { layout.placeAtWall(makeWallBoard(height, random), "board"); });
  repeat(random.integer(0, 1), [&] { layout.placeAtWall(makeLeaningBoard(height, random), "leaning board"); });
  repeat(random.integer(0, 2), [&] { layout.placeOnFloor(makeBoxStack(random), "box"); });
  repeat(random.integer(0, 1), [&] { layout.placeOnFloor(makeCurvedObject(random), "round object"); });
  repeat(random.integer(0, 1), [&] { addColumn(layout, height, random); });
}

void furnishHall(RoomLayout& layout, RandomSource& random) {
  const double height = layout.shell().height;
  repeat(random.integer(1, 2), [&] { layout.addOpening(randomDoor(height, random)); });
  repeat(random.integer(1, 2), [&] { layout.addOpening(randomRecess(height, random)); });
  layout.placeAtWall(makeStairs(height - 0.8, random), "staircase");
  if (random.chance(0.6)) layout.placeOnFloor(makeRamp(random), "ramp");
  if (random.chance(0.4)) layout.placeOnFloor(makePlatform(random), "platform");
  repeat(random.integer(0, 2), [&] { addColumn(layout, height, random); });
  repeat(random.integer(0, 2), [&] { layout.placeAtWall(makeWallBoard(height, random), "board"); });
  repeat(random.integer(0, 1), [&] { layout.placeAtWall(makeLeaningBoard(height, random), "leaning board"); });
  repeat(random.integer(0, 2), [&] { layout.placeOnFloor(makeBoxStack(random), "box"); });
  repeat(random.integer(0, 1), [&] { layout.placeOnFloor(makeCurvedObject(random), "round object"); });
}

void furnishStorage(RoomLayout& layout, RandomSource& random) {
  const double height = layout.shell().height;
  repeat(random.integer(0, 1), [&] { layout.addOpening(randomDoor(height, random)); });
  repeat(random.integer(0, 1), [&] { layout.addOpening(randomRecess(height, random)); });
  addShelves(layout, random.integer(1, 3), random);
  repeat(random.integer(3, 7), [&] { layout.placeOnFloor(makeBoxStack(random), "box"); });
  repeat(random.integer(1, 3), [&] { layout.placeOnFloor(makeCurvedObject(random), "round object"); });
  repeat(random.integer(0, 2), [&] { layout.placeAtWall(makeLeaningBoard(height, random), "leaning board"); });
  if (random.chance(0.3)) layout.placeOnFloor(makePlatform(random), "platform");
  if (random.chance(0.4)) addTables(layout, 1, random);
}

// A camera 0.6-5 m from an object of the room, 0.7-2.3 m above the floor, looking at it from
// 3 degrees above to 45 degrees below the horizontal, rolled by up to 5 degrees, until the view
// meets the requirements.
bool placeCamera(Scene& scene, const Assembly& room, const RoomShell& shell, RandomSource& random) {
  const ViewRequirements requirements;
  for (int attempt = 0; attempt < kPoseAttempts; ++attempt) {
    Eigen::Vector3d jitter;
    for (int axis = 2; axis >= 0; --axis) jitter[axis] = random.gaussian();
    const Eigen::Vector3d target = random.pick(room.interest) + 0.1 * jitter;
    // Mostly 1-5 m (a view of a part of the room), sometimes a close-up.
    const double distance = random.chance(0.15) ? random.uniform(0.6, 1.0) : random.uniform(1.0, 5.0);
    const double azimuth = random.uniform(0, 2 * kPi);
    const double pitch = degrees(random.uniform(-3, 45));
    const Eigen::Vector3d forward(std::cos(pitch) * std::cos(azimuth), std::cos(pitch) * std::sin(azimuth),
                                  -std::sin(pitch));
    const Eigen::Vector3d position = target - distance * forward;
    if (position.x() < 0.5 || position.x() > shell.width - 0.5 || position.y() < 0.5 ||
        position.y() > shell.depth - 0.5 || position.z() < 0.7 || position.z() > std::min(2.3, shell.height - 0.4)) {
      continue;
    }
    const Eigen::Vector3d up = Eigen::AngleAxisd(degrees(random.uniform(-5, 5)), forward) * Eigen::Vector3d::UnitZ();
    scene.world_from_camera = lookAt(position, target, up);
    if (meetsRequirements(summarizeView(scene, requirements), requirements)) {
      return true;
    }
  }
  return false;
}

}  // namespace

std::string randomSceneName(std::uint64_t seed) {
  char digits[32];
  std::snprintf(digits, sizeof digits, "%04llu", static_cast<unsigned long long>(seed));
  return std::string("random_") + digits;
}

Scene generateRoomScene(std::uint64_t seed) {
  RandomSource random(seed, kRoomStream);
  for (int layout_attempt = 0; layout_attempt < kLayoutAttempts; ++layout_attempt) {
    const auto kind = static_cast<RoomKind>(random.integer(0, 2));
    const double min_side = kind == RoomKind::hall ? 4.0 : 3.0;
    const bool ceiling = random.chance(0.5);
    const double height = random.uniform(2.4, 3.2);
    const double depth = random.uniform(min_side, 8.0);
    const double width = random.uniform(min_side, 8.0);
    RoomShell shell = makeRoomShell(width, depth, height, ceiling);
    RoomLayout layout(std::move(shell), random);
    switch (kind) {
      case RoomKind::office:
        furnishOffice(layout, random);
        break;
      case RoomKind::hall:
        furnishHall(layout, random);
        break;
      case RoomKind::storage:
        furnishStorage(layout, random);
        break;
    }
    const Assembly room = layout.finish();
    if (room.interest.empty()) continue;
    Scene scene;
    scene.name = randomSceneName(seed);
    scene.source = "random room scene, seed " + std::to_string(seed);
    for (const Primitive& part : room.parts) scene.primitives.push_back(part);
    if (!placeCamera(scene, room, layout.shell(), random)) continue;
    char size[64];
    std::snprintf(size, sizeof size, "%.1f x %.1f x %.1f m", layout.shell().width, layout.shell().depth,
                  layout.shell().height);
    scene.description = std::string("Random ") + roomKindName(kind) + " room, seed " + std::to_string(seed) + ": " +
                        size + (layout.shell().ceiling ? " with a ceiling" : " without a ceiling") + "; " +
                        layout.contents() + ".";
    return scene;
  }
  throw std::runtime_error("random room scene, seed " + std::to_string(seed) + ": no camera pose found in " +
                           std::to_string(kLayoutAttempts) + " layouts");
}

}  // namespace floodplane::synth
