#include "planarity.h"

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace floodplane {

namespace {

// Fewer sampled inliers than this cannot show a bend.
constexpr double kSmallestSample = 24.0;
// The quadratic's three extra terms explain chi^2_3 noise variances on a true plane (mean 3);
// a bend must explain this many.
constexpr double kSignificance = 30.0;
// ... and bend the surface with a radius below 1 m: a depth camera's calibration bends real
// walls and tables too (by half a millimetre over a metre at 1 m: a radius of 100 m and more),
// and at close range that bend is significant.
constexpr double kSmallestCurvature = 1.0;  // 1/m
// Noise across a surface never below this share of a pixel footprint (exact data: float
// round-off).
constexpr double kFootprintFloor = 0.02;

// Index into the upper triangle of a symmetric 6 x 6 matrix, row i <= column j.
constexpr int upper(int i, int j) { return i * 6 - i * (i - 1) / 2 + (j - i); }

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

void PlanarityTest::add(std::uint32_t k, const Vec3& point) {
  const Frame& f = frames_[k - 1];
  const Vec3 d = point - f.centroid;
  const double u = d.dot(f.u), v = d.dot(f.v), w = d.dot(f.w);
  const double m[6] = {1.0, u, v, u * u, u * v, v * v};
  Sums& s = sums_[k - 1];
  for (int i = 0; i < 6; ++i) {
    for (int j = i; j < 6; ++j) s.normal[upper(i, j)] += m[i] * m[j];
    s.rhs[i] += m[i] * w;
  }
  s.ww += w * w;
  s.count += 1.0;
}

void PlanarityTest::split(std::uint32_t k, double& explained, double& residual, double& curvature) const {
  const Sums& s = sums_[k - 1];
  Eigen::Matrix<double, 6, 6> a;
  Eigen::Matrix<double, 6, 1> b;
  for (int i = 0; i < 6; ++i) {
    for (int j = i; j < 6; ++j) a(i, j) = a(j, i) = s.normal[upper(i, j)];
    b(i) = s.rhs[i];
  }
  // Fitted by the plane's own terms (1, u, v) and by all six; the difference is the bend.
  const Eigen::Vector3d linear = a.topLeftCorner<3, 3>().ldlt().solve(b.head<3>());
  const Eigen::Matrix<double, 6, 1> full = a.ldlt().solve(b);
  const double by_plane = linear.dot(b.head<3>());
  const double by_quadratic = full.dot(b);
  explained = std::isfinite(by_quadratic) && std::isfinite(by_plane) ? std::max(0.0, by_quadratic - by_plane) : 0.0;
  residual = std::max(0.0, s.ww - (std::isfinite(by_quadratic) ? by_quadratic : 0.0));
  // The larger principal curvature: the larger |eigenvalue| of the Hessian [2a b; b 2c].
  const double a2 = full(3), b2 = full(4), c2 = full(5);
  curvature = std::abs(a2 + c2) + std::sqrt((a2 - c2) * (a2 - c2) + b2 * b2);
  if (!std::isfinite(curvature)) curvature = 0.0;
}

double PlanarityTest::bend(std::uint32_t k) const {
  const Sums& s = sums_[k - 1];
  if (s.count <= 0.0) return 0.0;
  double explained = 0.0, residual = 0.0, curvature = 0.0;
  split(k, explained, residual, curvature);
  return std::sqrt(explained / s.count);
}

bool PlanarityTest::curved(std::uint32_t k, const Tolerances& tolerances) const {
  const Sums& s = sums_[k - 1];
  if (s.count < kSmallestSample) return false;
  double explained = 0.0, residual = 0.0, curvature = 0.0;
  split(k, explained, residual, curvature);
  // The noise across the surface: along the rays, projected on the normal.
  const PlaneFit& fit = fits_[k - 1];
  const double range = fit.centroid.norm();
  const double incidence = range > 0.0 ? std::abs(fit.normal.dot(fit.centroid)) / range : 1.0;
  const double across =
      std::max(tolerances.noise().sigma(range * range) * incidence, kFootprintFloor * tolerances.footprint(range));
  const double variance = across * across;
  if (std::getenv("PNOTEST")) return false;
  if (std::getenv("PDEBUG"))
    std::fprintf(stderr, "plane %u n %.0f range %.2f across %.6f chi %.1f resid %.6f curvature %.3f\n", k, s.count,
                 range, across, explained / variance, std::sqrt(residual / s.count), curvature);
  static const double sig = std::getenv("PSIG") ? std::atof(std::getenv("PSIG")) : kSignificance;
  static const double kmin = std::getenv("PKMIN") ? std::atof(std::getenv("PKMIN")) : kSmallestCurvature;
  return explained > sig * variance && curvature > kmin;
}

}  // namespace floodplane
