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
    double moments[17] = {};  // the distinct entries of sum m m^T, m = (1, u, v, u^2, uv, v^2), but the count
    double rhs[6] = {};       // sum m w
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

// Inline: it runs for every sampled inlier of every plane, from region output.
inline void PlanarityTest::add(std::uint32_t k, const Vec3& point) {
  const Frame& f = frames_[k - 1];
  const Vec3 d = point - f.centroid;
  const double u = d.dot(f.u), v = d.dot(f.v), w = d.dot(f.w);
  const double uu = u * u, uv = u * v, vv = v * v;
  Sums& s = sums_[k - 1];
  // The distinct products of m m^T (see kMoment): the same sums as of every entry, each
  // once (1 * u^2 and u * u are one product).
  s.moments[0] += u;
  s.moments[1] += v;
  s.moments[2] += uu;
  s.moments[3] += uv;
  s.moments[4] += vv;
  s.moments[5] += u * uu;
  s.moments[6] += u * uv;
  s.moments[7] += u * vv;
  s.moments[8] += v * uu;
  s.moments[9] += v * uv;
  s.moments[10] += v * vv;
  s.moments[11] += uu * uu;
  s.moments[12] += uu * uv;
  s.moments[13] += uu * vv;
  s.moments[14] += uv * uv;
  s.moments[15] += uv * vv;
  s.moments[16] += vv * vv;
  s.rhs[0] += w;
  s.rhs[1] += u * w;
  s.rhs[2] += v * w;
  s.rhs[3] += uu * w;
  s.rhs[4] += uv * w;
  s.rhs[5] += vv * w;
  s.count += 1.0;
}

}  // namespace floodplane
