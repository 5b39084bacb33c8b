// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "models/planarity_test.h"

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

#include "models/plane_sums.h"

namespace floodplane {

namespace {

// Fewer sampled inliers than this cannot show a bend.
constexpr double kSmallestSample = 24.0;
// The quadratic's three extra terms explain chi^2_3 noise variances on a true plane (mean 3);
// a bend must explain this many.
constexpr double kSignificance = 30.0;
// ... and bend the surface with a radius below half a metre (PlanarityTest::kSmallestCurvature:
// the curved things in rooms: people, balls, bins, pipes, columns). A depth camera's
// calibration bends real walls and tables too, by half a millimetre over a metre at 1 m (a
// radius of 100 m and more), and at close range that bend is significant; a small plane's
// noise fakes radii of a metre.
// Noise across a surface never below this share of a pixel footprint (exact data: float
// round-off).
constexpr double kFootprintFloor = 0.02;

// Where entry (i, j) of sum m m^T, m = (1, u, v, u^2, uv, v^2), is kept in Sums::moments
// (each distinct product once; -1: the count).
constexpr int kMoment[6][6] = {{-1, 0, 1, 2, 3, 4},   {0, 2, 3, 5, 6, 7},    {1, 3, 4, 8, 9, 10},
                               {2, 5, 8, 11, 12, 13}, {3, 6, 9, 12, 14, 15}, {4, 7, 10, 13, 15, 16}};

// The monomials x^a y^b z^c, a + b + c <= 4, in PlanarityTest's order, and for those of degree
// up to 3 the index of the monomial times x, y and z.
struct MonomialTable {
  int exponent[PlanarityTest::kMonomials][3];
  int times[PlanarityTest::kMonomials][3];  // -1 past the fourth degree
  MonomialTable() {
    int n = 0;
    for (int degree = 0; degree <= 4; ++degree)
      for (int a = degree; a >= 0; --a)
        for (int b = degree - a; b >= 0; --b) {
          exponent[n][0] = a;
          exponent[n][1] = b;
          exponent[n][2] = degree - a - b;
          ++n;
        }
    for (int i = 0; i < PlanarityTest::kMonomials; ++i)
      for (int axis = 0; axis < 3; ++axis) {
        int e[3] = {exponent[i][0], exponent[i][1], exponent[i][2]};
        ++e[axis];
        times[i][axis] = indexOf(e);
      }
  }
  int indexOf(const int (&e)[3]) const {
    for (int i = 0; i < PlanarityTest::kMonomials; ++i)
      if (exponent[i][0] == e[0] && exponent[i][1] == e[1] && exponent[i][2] == e[2]) return i;
    return -1;
  }
};

const MonomialTable& monomials() {
  static const MonomialTable table;
  return table;
}

// A polynomial of degree <= 4 in x, y and z: a coefficient per monomial.
struct Polynomial {
  double c[PlanarityTest::kMonomials] = {};

  // A coordinate of a point in a frame, c0 + a . (x, y, z).
  static Polynomial linear(double c0, const Eigen::Vector3d& a) {
    Polynomial p;
    p.c[0] = c0;
    p.c[1] = a.x();
    p.c[2] = a.y();
    p.c[3] = a.z();
    return p;
  }
  // This times a linear polynomial (degree <= 3 here).
  Polynomial operator*(const Polynomial& l) const {
    const MonomialTable& table = monomials();
    Polynomial out;
    for (int i = 0; i < PlanarityTest::kMonomials; ++i) {
      if (c[i] == 0.0) continue;
      out.c[i] += c[i] * l.c[0];
      for (int axis = 0; axis < 3; ++axis)
        if (table.times[i][axis] >= 0) out.c[table.times[i][axis]] += c[i] * l.c[1 + axis];
    }
    return out;
  }
  // Its sum over the points whose monomial sums are `moments`.
  double sum(const double* moments) const {
    double total = 0.0;
    for (int i = 0; i < PlanarityTest::kMonomials; ++i) total += c[i] * moments[i];
    return total;
  }
};

}  // namespace

void PlanarityTest::reset(const std::vector<PlaneFit>& fits) {
  fits_ = fits;
  origins_.resize(fits.size());
  for (std::size_t k = 0; k < fits.size(); ++k) {
    const Eigen::Vector3d& c = fits[k].centroid;
    origins_[k] = Vec3{static_cast<float>(c.x()), static_cast<float>(c.y()), static_cast<float>(c.z())};
  }
  moments_.assign(fits.size() * kMonomials, 0.0);
}

PlanarityTest::Frame PlanarityTest::frameOf(const PlaneFit& fit) {
  const Eigen::Vector3d n = fit.normal;
  // Any axis along the plane: the quadratic has every term, so its fit does not depend on it.
  const Eigen::Vector3d u = n.unitOrthogonal();
  return {fit.centroid, u, n.cross(u), n};
}

PlanarityTest::Sums PlanarityTest::sumsIn(std::uint32_t k, const Frame& frame) const {
  const double* m = moments_.data() + static_cast<std::size_t>(k - 1) * kMonomials;
  // A point's coordinates in the frame as polynomials in its offset from the plane's origin.
  const Vec3& o = origins_[k - 1];
  const Eigen::Vector3d shift = Eigen::Vector3d(o.x, o.y, o.z) - frame.centroid;
  const Polynomial u = Polynomial::linear(frame.u.dot(shift), frame.u);
  const Polynomial v = Polynomial::linear(frame.v.dot(shift), frame.v);
  const Polynomial w = Polynomial::linear(frame.w.dot(shift), frame.w);
  const Polynomial uu = u * u, uv = u * v, vv = v * v;
  const Polynomial uuu = uu * u, uuv = uu * v, uvv = uv * v, vvv = vv * v;
  Sums s;
  s.count = m[0];
  s.moments[0] = u.sum(m);
  s.moments[1] = v.sum(m);
  s.moments[2] = uu.sum(m);
  s.moments[3] = uv.sum(m);
  s.moments[4] = vv.sum(m);
  s.moments[5] = uuu.sum(m);
  s.moments[6] = s.moments[8] = uuv.sum(m);
  s.moments[7] = s.moments[9] = uvv.sum(m);
  s.moments[10] = vvv.sum(m);
  s.moments[11] = (uuu * u).sum(m);
  s.moments[12] = (uuu * v).sum(m);
  s.moments[13] = s.moments[14] = (uuv * v).sum(m);
  s.moments[15] = (uvv * v).sum(m);
  s.moments[16] = (vvv * v).sum(m);
  s.rhs[0] = w.sum(m);
  s.rhs[1] = (u * w).sum(m);
  s.rhs[2] = (v * w).sum(m);
  s.rhs[3] = (uu * w).sum(m);
  s.rhs[4] = (uv * w).sum(m);
  s.rhs[5] = (vv * w).sum(m);
  s.ww = (w * w).sum(m);
  return s;
}

PlanarityTest::Sums& PlanarityTest::Sums::operator+=(const Sums& o) {
  for (int i = 0; i < 17; ++i) moments[i] += o.moments[i];
  for (int i = 0; i < 6; ++i) rhs[i] += o.rhs[i];
  ww += o.ww;
  count += o.count;
  return *this;
}

PlanarityTest::Quadric PlanarityTest::fitQuadric(const Sums& s) {
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
  q.plane_residual = std::max(0.0, s.ww - by_plane);
  q.residual = std::max(0.0, s.ww - by_quadratic);
  // The principal curvatures: the eigenvalues of the Hessian [2a b; b 2c].
  Eigen::Matrix2d hessian;
  hessian << 2.0 * full(3), full(4), full(4), 2.0 * full(5);
  const Eigen::Vector2d principal =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(hessian, Eigen::EigenvaluesOnly).eigenvalues();
  q.curvature = std::max(std::abs(principal(0)), std::abs(principal(1)));
  return q;
}

double PlanarityTest::curvature(std::uint32_t k) const {
  return fitQuadric(sumsIn(k, frameOf(fits_[k - 1]))).curvature;
}

bool PlanarityTest::bends(const Sums& s, const Quadric& q, const PlaneFit& fit, const Tolerances& tolerances) {
  if (s.count < kSmallestSample) return false;
  // The noise across the surface: along the rays, projected on the normal.
  const double range = fit.centroid.norm();
  const double incidence = viewIncidence(fit);
  const double across = std::max(depthSigma(tolerances.noise(), range * range) * incidence,
                                 kFootprintFloor * tolerances.footprint(range));
  return q.explained > kSignificance * across * across && q.curvature > kSmallestCurvature;
}

bool PlanarityTest::judgeable(std::uint32_t k) const {
  return moments_[static_cast<std::size_t>(k - 1) * kMonomials] >= kSmallestSample;
}

bool PlanarityTest::curved(std::uint32_t k, const Tolerances& tolerances) const {
  if (!judgeable(k)) return false;
  const Sums s = sumsIn(k, frameOf(fits_[k - 1]));
  return bends(s, fitQuadric(s), fits_[k - 1], tolerances);
}

double PlanarityTest::unionCurvature(std::uint32_t k, std::uint32_t l, const PlaneFit& joint) const {
  const Frame frame = frameOf(joint);
  Sums both = sumsIn(k, frame);
  both += sumsIn(l, frame);
  return fitQuadric(both).curvature;
}

bool PlanarityTest::curvedPair(std::uint32_t k, std::uint32_t l, const PlaneFit& joint, const Tolerances& tolerances,
                               bool* union_bends) const {
  if (union_bends) *union_bends = false;
  if (!judgeable(k) || !judgeable(l)) return false;
  const Frame frame = frameOf(joint);
  const Sums first = sumsIn(k, frame), second = sumsIn(l, frame);
  Sums both = first;
  both += second;
  const Quadric q = fitQuadric(both);
  if (!bends(both, q, joint, tolerances)) return false;
  if (union_bends) *union_bends = true;
  // Residuals along one direction, the union's normal, on both sides: measured across each
  // facet's own plane they would be smaller by the cosine of its tilt for the noise alone.
  return q.residual < fitQuadric(first).plane_residual + fitQuadric(second).plane_residual;
}

}  // namespace floodplane
