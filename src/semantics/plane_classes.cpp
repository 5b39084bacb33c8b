// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/plane_classes.h"

#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace floodplane {
namespace {

constexpr double kQuarterTurn = 0.7853981633974483;  // pi / 4

void checkOption(const char* name, double value, double upper = std::numeric_limits<double>::infinity()) {
  if (!std::isfinite(value) || value < 0.0 || value >= upper) {
    throw std::invalid_argument(std::string("floodplane::describePlanes: PlaneClassOptions::") + name + " is " +
                                std::to_string(value) + "; it must be finite, at least 0" +
                                (std::isfinite(upper) ? " and below pi/4" : ""));
  }
}

void checkOptions(const PlaneClassOptions& options) {
  checkOption("horizontal_tolerance_rad", options.horizontal_tolerance_rad, kQuarterTurn);
  checkOption("vertical_tolerance_rad", options.vertical_tolerance_rad, kQuarterTurn);
  checkOption("min_floor_area_m2", options.min_floor_area_m2);
  checkOption("floor_height_tolerance_m", options.floor_height_tolerance_m);
  checkOption("min_ceiling_area_m2", options.min_ceiling_area_m2);
  checkOption("min_ceiling_height_m", options.min_ceiling_height_m);
}

enum class Orientation { up_facing, down_facing, vertical, inclined };

// The plane's orientation to the unit up direction; inclined for a normal that is zero or not
// finite (it says nothing).
Orientation orientationOf(const PlaneFit& fit, const Eigen::Vector3d& up, const PlaneClassOptions& options) {
  const double length = fit.normal.norm();
  if (!std::isfinite(length) || length == 0.0) return Orientation::inclined;
  const double cosine = fit.normal.dot(up) / length;  // of the angle between the normal and up
  const double horizontal = std::cos(options.horizontal_tolerance_rad);
  if (cosine >= horizontal) return Orientation::up_facing;
  if (cosine <= -horizontal) return Orientation::down_facing;
  if (std::abs(cosine) <= std::sin(options.vertical_tolerance_rad)) return Orientation::vertical;
  return Orientation::inclined;
}

// The area of the surface the inliers cover [m^2]: that of the rectangle with their spread
// along the plane (a side a covered uniformly has variance a^2 / 12).
double spreadArea(const PlaneFit& fit) {
  const double product = fit.eigenvalues[1] * fit.eigenvalues[2];
  return std::isfinite(product) && product > 0.0 ? 12.0 * std::sqrt(product) : 0.0;
}

// The floor's plane: the points p with normal . p + offset = 0, normal facing up.
struct FloorPlane {
  Eigen::Vector3d normal;
  double offset = 0.0;
  // The signed distance along unit `up` from this plane to `point`: the t with
  // point - t up on the plane (normal . up > 0 for an up-facing plane).
  double heightOf(const Eigen::Vector3d& point, const Eigen::Vector3d& up) const {
    return (normal.dot(point) + offset) / normal.dot(up);
  }
};

}  // namespace

const char* planeClassName(PlaneClass plane_class) {
  switch (plane_class) {
    case PlaneClass::kOther:
      return "other";
    case PlaneClass::kFloor:
      return "floor";
    case PlaneClass::kCeiling:
      return "ceiling";
    case PlaneClass::kWall:
      return "wall";
    case PlaneClass::kHorizontalSurface:
      return "horizontal_surface";
  }
  return "unknown";
}

namespace {

// The class of a plane of this orientation, `height` above the floor (when the frame has one).
PlaneClass classOf(Orientation orientation, const PlaneFit& fit, double height, bool has_floor,
                   const PlaneClassOptions& options) {
  switch (orientation) {
    case Orientation::up_facing:
      return has_floor && std::abs(height) <= options.floor_height_tolerance_m ? PlaneClass::kFloor
                                                                               : PlaneClass::kHorizontalSurface;
    case Orientation::down_facing: {
      const bool large = spreadArea(fit) >= options.min_ceiling_area_m2;
      // Without a floor, the height cannot be told: the size alone decides.
      const bool high = !has_floor || height >= options.min_ceiling_height_m;
      return large && high ? PlaneClass::kCeiling : PlaneClass::kOther;
    }
    case Orientation::vertical:
      return PlaneClass::kWall;
    case Orientation::inclined:
      break;
  }
  return PlaneClass::kOther;
}

}  // namespace

std::vector<PlaneDescription> describePlanes(const std::vector<SegmentedPlane>& planes, const Eigen::Vector3d& up,
                                             const PlaneClassOptions& options) {
  if (!up.allFinite() || up.isZero(0.0)) {
    throw std::invalid_argument("floodplane::describePlanes: the up direction (" + std::to_string(up.x()) + ", " +
                                std::to_string(up.y()) + ", " + std::to_string(up.z()) +
                                ") must be finite and not zero");
  }
  checkOptions(options);
  const Eigen::Vector3d unit_up = up.stableNormalized();  // without overflow or underflow of its squares

  std::vector<Orientation> orientations(planes.size());
  // The floor: the lowest (at its centroid, along up) large up-facing plane.
  std::optional<std::size_t> floor;
  double floor_level = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < planes.size(); ++k) {
    const PlaneFit& fit = planes[k].fit;
    orientations[k] = orientationOf(fit, unit_up, options);
    if (orientations[k] != Orientation::up_facing || !fit.centroid.allFinite() || !std::isfinite(fit.offset)) continue;
    const double level = unit_up.dot(fit.centroid);
    if (spreadArea(fit) >= options.min_floor_area_m2 && level < floor_level) {
      floor = k;
      floor_level = level;
    }
  }
  std::optional<FloorPlane> floor_plane;
  if (floor) {
    const PlaneFit& fit = planes[*floor].fit;
    const double length = fit.normal.norm();
    floor_plane = FloorPlane{fit.normal / length, fit.offset / length};
  }

  std::vector<PlaneDescription> descriptions(planes.size());
  for (std::size_t k = 0; k < planes.size(); ++k) {
    const PlaneFit& fit = planes[k].fit;
    PlaneDescription& description = descriptions[k];
    description.height_above_floor = floor_plane && fit.centroid.allFinite()
                                         ? floor_plane->heightOf(fit.centroid, unit_up)
                                         : std::numeric_limits<double>::quiet_NaN();
    description.plane_class =
        classOf(orientations[k], fit, description.height_above_floor, floor_plane.has_value(), options);
  }
  return descriptions;
}

}  // namespace floodplane
