#pragma once

#include <cstdint>
#include <vector>

#include "floodplane/plane_fit.h"
#include "tolerances.h"
#include "vec3.h"

namespace floodplane {

/// Beyond the paper: the planarity test. A facet of a cylinder, a ball or a person stays within
/// three noise deviations of its own plane, so it passes every test of the flood and the
/// merge. Here each plane's inliers are fitted with a quadratic surface
///   w = a u^2 + b u v + c v^2 + d u + e v + f
/// in the plane's own frame (u, v along it, w across it), from running moment sums. A plane is
/// curved when what the quadratic explains beyond the plane is beyond what the noise could fake
/// (a chi-square test against the noise model across the surface) and its larger principal
/// curvature is that of the curved things in rooms (radii below half a metre): a real wall
/// bent by a few millimetres over metres, or by a depth camera's calibration, stays a plane.
class PlanarityTest {
 public:
  /// Starts the sums for planes 1..fits.size() (fits[k - 1] is plane k).
  void reset(const std::vector<PlaneFit>& fits);
  /// Adds an inlier of plane k.
  void add(std::uint32_t k, const Vec3& point);
  /// Whether plane k bends more than its noise explains.
  bool curved(std::uint32_t k, const Tolerances& tolerances) const;
  /// The larger principal curvature of plane k's quadratic [1/m].
  double curvature(std::uint32_t k) const;

 private:
  struct Frame {
    Vec3 centroid, u, v, w;  // the plane's frame: w its normal
  };
  struct Sums {
    double normal[21] = {};  // the upper triangle of sum m m^T, m = (1, u, v, u^2, uv, v^2)
    double rhs[6] = {};      // sum m w
    double ww = 0.0;         // sum w^2
    double count = 0.0;
  };
  // Plane k's quadratic fit: the sum of squares it explains beyond the plane, and its larger
  // principal curvature [1/m].
  struct Quadric {
    double explained = 0.0, curvature = 0.0;
  };
  Quadric fitQuadric(std::uint32_t k) const;

  std::vector<Frame> frames_;
  std::vector<Sums> sums_;
  std::vector<PlaneFit> fits_;
};

}  // namespace floodplane
