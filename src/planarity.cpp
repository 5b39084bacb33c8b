#include "planarity.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace floodplane {

namespace {

// Fewer sampled inliers than this cannot show a bend.
constexpr double kSmallestSample = 24.0;
// The quadratic's three extra terms explain chi^2_3 noise variances on a true plane (mean 3);
// a bend must explain this many.
constexpr double kSignificance = 30.0;
// ... and bend the surface with a radius below half a metre (the curved things in rooms:
// people, balls, bins, pipes, columns). A depth camera's calibration bends real walls and
// tables too, by half a millimetre over a metre at 1 m (a radius of 100 m and more), and at
// close range that bend is significant; a small plane's noise fakes radii of a metre.
constexpr double kSmallestCurvature = 2.0;  // 1/m
// Noise across a surface never below this share of a pixel footprint (exact data: float
// round-off).
constexpr double kFootprintFloor = 0.02;

// Where entry (i, j) of sum m m^T, m = (1, u, v, u^2, uv, v^2), is kept in Sums::moments
// (each distinct product once; -1: the count).
constexpr int kMoment[6][6] = {{-1, 0, 1, 2, 3, 4},   {0, 2, 3, 5, 6, 7},    {1, 3, 4, 8, 9, 10},
                               {2, 5, 8, 11, 12, 13}, {3, 6, 9, 12, 14, 15}, {4, 7, 10, 13, 15, 16}};

}  // namespace

void PlanarityTest::reset(const std::vector<PlaneFit>& fits) {
  fits_ = fits;
  frames_.resize(fits.size());
  sums_.assign(fits.size(), Sums());
  for (std::size_t k = 0; k < fits.size(); ++k) {
    const Eigen::Vector3d n = fits[k].normal;
    // Any axis along the plane: the quadratic has every term, so its fit does not depend on it.
    const Eigen::Vector3d u = n.unitOrthogonal();
    const Eigen::Vector3d v = n.cross(u);
    const auto vec = [](const Eigen::Vector3d& e) {
      return Vec3{static_cast<float>(e.x()), static_cast<float>(e.y()), static_cast<float>(e.z())};
    };
    frames_[k] = {vec(fits[k].centroid), vec(u), vec(v), vec(n)};
  }
}

PlanarityTest::Quadric PlanarityTest::fitQuadric(std::uint32_t k) const {
  const Sums& s = sums_[k - 1];
  Eigen::Matrix<double, 6, 6> a;
  Eigen::Matrix<double, 6, 1> b;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) a(i, j) = kMoment[i][j] < 0 ? s.count : s.moments[kMoment[i][j]];
    b(i) = s.rhs[i];
  }
  Quadric q;
  // Fitted by the plane's own terms (1, u, v) and by all six; the difference is the bend.
  const Eigen::Vector3d linear = a.topLeftCorner<3, 3>().ldlt().solve(b.head<3>());
  const Eigen::Matrix<double, 6, 1> full = a.ldlt().solve(b);
  const double by_plane = linear.dot(b.head<3>());
  const double by_quadratic = full.dot(b);
  if (!std::isfinite(by_quadratic) || !std::isfinite(by_plane) || !full.allFinite()) return q;
  q.explained = std::max(0.0, by_quadratic - by_plane);
  // The principal curvatures: the eigenvalues of the Hessian [2a b; b 2c].
  Eigen::Matrix2d hessian;
  hessian << 2.0 * full(3), full(4), full(4), 2.0 * full(5);
  const Eigen::Vector2d principal =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(hessian, Eigen::EigenvaluesOnly).eigenvalues();
  q.curvature = std::max(std::abs(principal(0)), std::abs(principal(1)));
  return q;
}

double PlanarityTest::curvature(std::uint32_t k) const { return fitQuadric(k).curvature; }

bool PlanarityTest::curved(std::uint32_t k, const Tolerances& tolerances) const {
  const Sums& s = sums_[k - 1];
  if (s.count < kSmallestSample) return false;
  const Quadric q = fitQuadric(k);
  // The noise across the surface: along the rays, projected on the normal.
  const PlaneFit& fit = fits_[k - 1];
  const double range = fit.centroid.norm();
  const double incidence = range > 0.0 ? std::abs(fit.normal.dot(fit.centroid)) / range : 1.0;
  const double across = std::max(depthSigma(tolerances.noise(), range * range) * incidence,
                                 kFootprintFloor * tolerances.footprint(range));
  return q.explained > kSignificance * across * across && q.curvature > kSmallestCurvature;
}

}  // namespace floodplane
