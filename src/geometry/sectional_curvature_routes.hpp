#pragma once
// The two routes of geometry/sectional_curvature.hpp for any embedding of the unit sphere S^k into (R^N, M): the
// chain's Psi there, and in tests model spaces whose curvature is known (the round S^3 embedded as itself, K = 1).
// An Embedding provides
//   int sphereDimension() const;                         // k
//   const Eigen::MatrixXd& mass() const;                 // M, N x N
//   template <class S> VectorX<S> operator()(const std::vector<int>& axes, const VectorX<S>& coords) const;
// the embedded point in an atlas chart (linkage/sphere_coordinates.hpp), templated on the scalar so that forward AD
// and the second-order jet flow through it.

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <unsupported/Eigen/AutoDiff>

#include "geometry/second_order_jet.hpp"
#include "geometry/sectional_curvature.hpp"
#include "linkage/sphere_coordinates.hpp"

// The intrinsic route differentiates the embedding once more by forward AD whose scalar is a second-order jet; the
// chart multiplies by plain doubles, so declare that product (as simulation/exact_fields.cpp does for nested duals).
namespace Eigen {
template <int R, int O, int MR, typename BinOp>
struct ScalarBinaryOpTraits<AutoDiffScalar<Matrix<sl::SecondOrderJet, R, 1, O, MR, 1>>, double, BinOp> {
  using ReturnType = AutoDiffScalar<Matrix<sl::SecondOrderJet, R, 1, O, MR, 1>>;
};
template <int R, int O, int MR, typename BinOp>
struct ScalarBinaryOpTraits<double, AutoDiffScalar<Matrix<sl::SecondOrderJet, R, 1, O, MR, 1>>, BinOp> {
  using ReturnType = AutoDiffScalar<Matrix<sl::SecondOrderJet, R, 1, O, MR, 1>>;
};
}  // namespace Eigen

namespace sl::sectional {

// A point in the atlas chart best conditioned there, and the conversions between sphere velocities and that chart's
// rates.
struct ChartPoint {
  std::vector<int> axes;
  Eigen::VectorXd coords;

  static ChartPoint bestAt(const Eigen::VectorXd& spherePoint) {
    const Eigen::VectorXd x = spherePoint.normalized();
    ChartPoint p;
    p.axes = sphereChartAxes(static_cast<int>(x.size()), bestSphereChart(x));
    p.coords = coordinatesInChart(p.axes, x);
    return p;
  }
  Eigen::VectorXd rates(const Eigen::VectorXd& sphereVelocity) const {
    return ratesInChart(axes, coords, sphereVelocity);
  }
  Eigen::VectorXd sphereVelocity(const Eigen::VectorXd& rates) const {
    return sphereVelocityInChart(axes, coords, rates);
  }
};

// d^2 q along the rates U and V at once: q_U, q_V, q_UU, q_UV, q_VV from one second-order jet in (s, u) of
// q(c + s U + u V).
struct Derivatives {
  Eigen::VectorXd u, v, uu, uv, vv;
};
template <class Embedding>
Derivatives derivativesAlong(const Embedding& embed, const ChartPoint& p, const Eigen::VectorXd& U,
                             const Eigen::VectorXd& V) {
  const Eigen::Index k = p.coords.size();
  VectorX<SecondOrderJet> c(k);
  for (Eigen::Index i = 0; i < k; ++i) c(i) = SecondOrderJet(p.coords(i), U(i), V(i), 0.0, 0.0, 0.0);
  const VectorX<SecondOrderJet> q = embed(p.axes, c);
  Derivatives out;
  for (Eigen::VectorXd* d : {&out.u, &out.v, &out.uu, &out.uv, &out.vv}) d->resize(q.size());
  for (Eigen::Index r = 0; r < q.size(); ++r) {
    out.u(r) = q(r).g0;
    out.v(r) = q(r).g1;
    out.uu(r) = q(r).h00;
    out.uv(r) = q(r).h01;
    out.vv(r) = q(r).h11;
  }
  return out;
}

inline double planeArea2(const Eigen::MatrixXd& metric, const Eigen::VectorXd& U, const Eigen::VectorXd& V) {
  const double uu = U.dot(metric * U), vv = V.dot(metric * V), uv = U.dot(metric * V);
  const double area2 = uu * vv - uv * uv;
  if (!(area2 > 1e-24 * uu * vv) || !std::isfinite(area2))
    throw std::invalid_argument("sectional curvature: the two tangent vectors do not span a plane");
  return area2;
}

// The Gauss route's ingredients at one point: the Jacobian J (from jets along pairs of coordinate directions), the
// metric g = J^T M J, and the M-orthogonal projection onto the normal space, P_N w = w - J g^-1 J^T M w.
template <class Embedding>
struct AmbientFrame {
  const Embedding& embed;
  ChartPoint chart;
  Eigen::MatrixXd jacobian, metric;
  Eigen::LDLT<Eigen::MatrixXd> metricFactor;

  AmbientFrame(const Embedding& e, const Eigen::VectorXd& spherePoint)
      : embed(e), chart(ChartPoint::bestAt(spherePoint)) {
    const Eigen::Index k = chart.coords.size();
    for (Eigen::Index a = 0; a < k; a += 2) {
      const Eigen::Index b = std::min(a + 1, k - 1);
      const Derivatives d = derivativesAlong(embed, chart, Eigen::VectorXd::Unit(k, a), Eigen::VectorXd::Unit(k, b));
      if (jacobian.size() == 0) jacobian.resize(d.u.size(), k);
      jacobian.col(a) = d.u;
      jacobian.col(b) = d.v;
    }
    metric = jacobian.transpose() * embed.mass() * jacobian;
    metricFactor.compute(metric);
  }
  Eigen::VectorXd normalPart(const Eigen::VectorXd& w) const {
    return w - jacobian * metricFactor.solve(jacobian.transpose() * (embed.mass() * w));
  }
  double inner(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const { return a.dot(embed.mass() * b); }
};

// The Gauss equation: K(X, Y) = (<II(X,X), II(Y,Y)> - |II(X,Y)|^2) / (|X|^2 |Y|^2 - <X,Y>^2).
template <class Embedding>
double gaussRoute(const Embedding& embed, const Eigen::VectorXd& spherePoint, const Eigen::VectorXd& X,
                  const Eigen::VectorXd& Y) {
  const AmbientFrame<Embedding> frame(embed, spherePoint);
  const Eigen::VectorXd U = frame.chart.rates(X), V = frame.chart.rates(Y);
  const double area2 = planeArea2(frame.metric, U, V);
  const Derivatives d = derivativesAlong(embed, frame.chart, U, V);
  const Eigen::VectorXd iiUU = frame.normalPart(d.uu), iiUV = frame.normalPart(d.uv), iiVV = frame.normalPart(d.vv);
  return (frame.inner(iiUU, iiVV) - frame.inner(iiUV, iiUV)) / area2;
}

// The Riemann tensor of the chart metric:
//   R(X,Y,Y,X) = d_X d_Y g_XY - (d_Y d_Y g_XX + d_X d_X g_YY) / 2 + g(G(X,Y), G(X,Y)) - g(G(X,X), G(Y,Y)),
// with g_ab(c + sU + uV) carried as second-order jets (Psi's third derivatives enter through them) and the
// Christoffel symbols of the first kind G_n(P, Q) = (d_P g_nQ + d_Q g_nP - d_n g_PQ) / 2.
template <class Embedding>
double intrinsicRoute(const Embedding& embed, const Eigen::VectorXd& spherePoint, const Eigen::VectorXd& X,
                      const Eigen::VectorXd& Y) {
  using Outer = Eigen::AutoDiffScalar<VectorX<SecondOrderJet>>;
  const ChartPoint p = ChartPoint::bestAt(spherePoint);
  const Eigen::VectorXd U = p.rates(X), V = p.rates(Y);
  const Eigen::Index k = p.coords.size();
  // c + s U + u V, with d/dc_a carried alongside: the columns q_a of the Jacobian as jets in (s, u).
  VectorX<Outer> c(k);
  for (Eigen::Index i = 0; i < k; ++i) {
    VectorX<SecondOrderJet> seed = VectorX<SecondOrderJet>::Constant(k, SecondOrderJet(0.0));
    seed(i) = SecondOrderJet(1.0);
    c(i) = Outer(SecondOrderJet(p.coords(i), U(i), V(i), 0.0, 0.0, 0.0), seed);
  }
  const VectorX<Outer> q = embed(p.axes, c);
  const Eigen::Index rows = q.size();
  std::vector<VectorX<SecondOrderJet>> columns(static_cast<size_t>(k), VectorX<SecondOrderJet>(rows));
  for (Eigen::Index r = 0; r < rows; ++r) {
    const auto& d = q(r).derivatives();
    for (Eigen::Index a = 0; a < k; ++a) columns[static_cast<size_t>(a)](r) = d.size() ? d(a) : SecondOrderJet(0.0);
  }
  const Eigen::MatrixXd& M = embed.mass();
  auto innerJets = [&](const VectorX<SecondOrderJet>& u, const VectorX<SecondOrderJet>& w) {
    SecondOrderJet sum(0.0);
    for (Eigen::Index r = 0; r < rows; ++r)
      for (Eigen::Index s = 0; s < rows; ++s)
        if (M(r, s) != 0.0) sum += M(r, s) * (u(r) * w(s));
    return sum;
  };
  Eigen::MatrixXd g(k, k), gU(k, k), gV(k, k), gUU(k, k), gUV(k, k), gVV(k, k);
  for (Eigen::Index a = 0; a < k; ++a)
    for (Eigen::Index b = a; b < k; ++b) {
      const SecondOrderJet gab = innerJets(columns[static_cast<size_t>(a)], columns[static_cast<size_t>(b)]);
      g(a, b) = g(b, a) = gab.v;
      gU(a, b) = gU(b, a) = gab.g0;
      gV(a, b) = gV(b, a) = gab.g1;
      gUU(a, b) = gUU(b, a) = gab.h00;
      gUV(a, b) = gUV(b, a) = gab.h01;
      gVV(a, b) = gVV(b, a) = gab.h11;
    }
  const double area2 = planeArea2(g, U, V);
  // d_n g_PQ in every coordinate direction n, by the symmetry of second derivatives: d_n q_P = d_P q_n, the slice
  // derivative of column n.
  Eigen::VectorXd qU = Eigen::VectorXd::Zero(rows), qV = Eigen::VectorXd::Zero(rows);
  std::vector<Eigen::VectorXd> dUq(static_cast<size_t>(k), Eigen::VectorXd(rows)),
      dVq(static_cast<size_t>(k), Eigen::VectorXd(rows));
  for (Eigen::Index a = 0; a < k; ++a) {
    const auto ua = static_cast<size_t>(a);
    for (Eigen::Index r = 0; r < rows; ++r) {
      const SecondOrderJet& e = columns[ua](r);
      qU(r) += U(a) * e.v;
      qV(r) += V(a) * e.v;
      dUq[ua](r) = e.g0;
      dVq[ua](r) = e.g1;
    }
  }
  auto lowered = [&](const Eigen::MatrixXd& dP, const Eigen::VectorXd& P, const Eigen::VectorXd& qP,
                     const std::vector<Eigen::VectorXd>& dPq, const Eigen::MatrixXd& dQ, const Eigen::VectorXd& Q,
                     const Eigen::VectorXd& qQ, const std::vector<Eigen::VectorXd>& dQq) {
    Eigen::VectorXd out = 0.5 * (dP * Q + dQ * P);
    for (Eigen::Index n = 0; n < k; ++n) {
      const auto un = static_cast<size_t>(n);
      out(n) -= 0.5 * (dPq[un].dot(M * qQ) + qP.dot(M * dQq[un]));
    }
    return out;
  };
  const Eigen::VectorXd gammaUU = lowered(gU, U, qU, dUq, gU, U, qU, dUq);
  const Eigen::VectorXd gammaUV = lowered(gU, U, qU, dUq, gV, V, qV, dVq);
  const Eigen::VectorXd gammaVV = lowered(gV, V, qV, dVq, gV, V, qV, dVq);
  const Eigen::LDLT<Eigen::MatrixXd> inverse(g);
  const double riemann = U.dot(gUV * V) - 0.5 * (U.dot(gVV * U) + V.dot(gUU * V)) +
                         gammaUV.dot(inverse.solve(gammaUV)) - gammaUU.dot(inverse.solve(gammaVV));
  return riemann / area2;
}

// II(e_a, e_b) for a g-orthonormal basis (e_a) of rates: every pair from one jet per pair a < b.
struct OrthonormalSecondForm {
  Eigen::MatrixXd basis;                         // columns e_a, as rates
  std::vector<std::vector<Eigen::VectorXd>> ii;  // ii[a][b] = II(e_a, e_b)
  int dimension() const { return static_cast<int>(basis.cols()); }
};

template <class Embedding>
OrthonormalSecondForm orthonormalSecondForm(const AmbientFrame<Embedding>& frame) {
  const Eigen::Index k = frame.metric.rows();
  OrthonormalSecondForm form;
  // g = L L^T, so the columns of L^-T are g-orthonormal.
  const Eigen::LLT<Eigen::MatrixXd> cholesky(frame.metric);
  form.basis = cholesky.matrixU().solve(Eigen::MatrixXd::Identity(k, k));
  form.ii.assign(static_cast<size_t>(k), std::vector<Eigen::VectorXd>(static_cast<size_t>(k)));
  for (Eigen::Index a = 0; a < k; ++a)
    for (Eigen::Index b = a + 1; b < k; ++b) {
      const Derivatives d = derivativesAlong(frame.embed, frame.chart, form.basis.col(a), form.basis.col(b));
      const auto ua = static_cast<size_t>(a), ub = static_cast<size_t>(b);
      if (form.ii[ua][ua].size() == 0) form.ii[ua][ua] = frame.normalPart(d.uu);
      if (form.ii[ub][ub].size() == 0) form.ii[ub][ub] = frame.normalPart(d.vv);
      form.ii[ua][ub] = form.ii[ub][ua] = frame.normalPart(d.uv);
    }
  return form;
}

// II(X, Y) for X, Y given by their coefficients in the orthonormal basis.
inline Eigen::VectorXd secondForm(const OrthonormalSecondForm& form, const Eigen::VectorXd& x,
                                  const Eigen::VectorXd& y) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(form.ii[0][0].size());
  for (int a = 0; a < form.dimension(); ++a)
    for (int b = 0; b < form.dimension(); ++b)
      if (x(a) != 0.0 && y(b) != 0.0) out += x(a) * y(b) * form.ii[static_cast<size_t>(a)][static_cast<size_t>(b)];
  return out;
}

// The Jacobi operator of x restricted to x's orthogonal complement: A(b, d) = R(x ^ e_b, x ^ e_d), whose Rayleigh
// quotient on a unit y orthogonal to x is K(x, y).
template <class Embedding>
Eigen::MatrixXd jacobiOperator(const OrthonormalSecondForm& form, const AmbientFrame<Embedding>& frame,
                               const Eigen::VectorXd& x) {
  const int k = form.dimension();
  const Eigen::VectorXd xx = secondForm(form, x, x);
  std::vector<Eigen::VectorXd> xe(static_cast<size_t>(k));
  for (int b = 0; b < k; ++b) xe[static_cast<size_t>(b)] = secondForm(form, x, Eigen::VectorXd::Unit(k, b));
  Eigen::MatrixXd A(k, k);
  for (int b = 0; b < k; ++b)
    for (int d = b; d < k; ++d)
      A(b, d) = A(d, b) = frame.inner(xx, form.ii[static_cast<size_t>(b)][static_cast<size_t>(d)]) -
                          frame.inner(xe[static_cast<size_t>(b)], xe[static_cast<size_t>(d)]);
  return A;
}

// The unit eigenvector of A on the orthogonal complement of x with the largest (sign +1) or smallest (-1)
// eigenvalue.
inline Eigen::VectorXd extremeDirection(const Eigen::MatrixXd& A, const Eigen::VectorXd& x, double sign,
                                        double& value) {
  const Eigen::Index k = A.rows();
  // An orthonormal basis of x's complement: the last k - 1 columns of a Householder QR of x.
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(x);
  const Eigen::MatrixXd Q = qr.householderQ() * Eigen::MatrixXd::Identity(k, k);
  const Eigen::MatrixXd B = Q.rightCols(k - 1);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(B.transpose() * A * B);
  const Eigen::Index which = sign > 0 ? k - 2 : 0;
  value = eigen.eigenvalues()(which);
  return B * eigen.eigenvectors().col(which);
}

struct Plane {
  Eigen::VectorXd x, y;  // orthonormal coefficients in the orthonormal basis
  double curvature = 0;
};

// Alternating ascent (sign +1) or descent (-1) of K(x, y): with x fixed the best y is an extreme eigenvector of x's
// Jacobi operator, and the other way round; each half-step can only improve K, so it converges to a local extremum.
template <class Embedding>
Plane alternatingExtremum(const OrthonormalSecondForm& form, const AmbientFrame<Embedding>& frame, Plane plane,
                          double sign) {
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double before = plane.curvature;
    plane.y = extremeDirection(jacobiOperator(form, frame, plane.x), plane.x, sign, plane.curvature);
    plane.x = extremeDirection(jacobiOperator(form, frame, plane.y), plane.y, sign, plane.curvature);
    if (iteration > 0 && std::abs(plane.curvature - before) <= 1e-15 * (1.0 + std::abs(before))) break;
  }
  return plane;
}

// Two orthonormal vectors spanning the complement of a unit n in R^3.
inline void complementOf(const Eigen::Vector3d& n, Eigen::VectorXd& a, Eigen::VectorXd& b) {
  const Eigen::Vector3d helper = std::abs(n(0)) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d u = (helper - helper.dot(n) * n).normalized();
  a = u;
  b = n.cross(u);
}

// The range of K over the planes at a point (sectionalCurvatureRange).
template <class Embedding>
SectionalRange curvatureRange(const Embedding& embed, const Eigen::VectorXd& spherePoint) {
  const AmbientFrame<Embedding> frame(embed, spherePoint);
  const OrthonormalSecondForm form = orthonormalSecondForm(frame);
  const int k = form.dimension();
  auto curvature = [&](const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
    const Eigen::VectorXd xy = secondForm(form, x, y);
    return frame.inner(secondForm(form, x, x), secondForm(form, y, y)) - frame.inner(xy, xy);
  };
  Plane lowest, highest;
  if (k == 2) {
    lowest.x = highest.x = Eigen::VectorXd::Unit(2, 0);
    lowest.y = highest.y = Eigen::VectorXd::Unit(2, 1);
    lowest.curvature = highest.curvature = curvature(lowest.x, lowest.y);
  } else if (k == 3) {
    // The curvature operator on the bivectors e12, e13, e23; a unit bivector w is the plane normal to its Hodge
    // dual (w23, -w13, w12).
    const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    Eigen::Matrix3d R;
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j) {
        const auto a = static_cast<size_t>(pairs[i][0]), b = static_cast<size_t>(pairs[i][1]);
        const auto c = static_cast<size_t>(pairs[j][0]), d = static_cast<size_t>(pairs[j][1]);
        R(i, j) = R(j, i) = frame.inner(form.ii[a][c], form.ii[b][d]) - frame.inner(form.ii[a][d], form.ii[b][c]);
      }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(R);
    for (int which : {0, 2}) {
      const Eigen::Vector3d w = eigen.eigenvectors().col(which);
      Plane& plane = which == 0 ? lowest : highest;
      complementOf(Eigen::Vector3d(w(2), -w(1), w(0)).normalized(), plane.x, plane.y);
      plane.curvature = eigen.eigenvalues()(which);
    }
  } else {
    lowest.curvature = INFINITY;
    highest.curvature = -INFINITY;
    for (int a = 0; a < k; ++a)
      for (int b = a + 1; b < k; ++b)
        for (double sign : {-1.0, 1.0}) {
          Plane start{Eigen::VectorXd::Unit(k, a), Eigen::VectorXd::Unit(k, b), 0.0};
          start.curvature = curvature(start.x, start.y);
          const Plane found = alternatingExtremum(form, frame, start, sign);
          if (sign < 0 && found.curvature < lowest.curvature) lowest = found;
          if (sign > 0 && found.curvature > highest.curvature) highest = found;
        }
  }
  SectionalRange range;
  range.minimum = lowest.curvature;
  range.maximum = highest.curvature;
  range.minimumPlane[0] = frame.chart.sphereVelocity(form.basis * lowest.x);
  range.minimumPlane[1] = frame.chart.sphereVelocity(form.basis * lowest.y);
  range.maximumPlane[0] = frame.chart.sphereVelocity(form.basis * highest.x);
  range.maximumPlane[1] = frame.chart.sphereVelocity(form.basis * highest.y);
  return range;
}

// The smallest and largest K(v, w) over the planes through the tangent vector v (sectionalCurvatureThrough): the
// extreme eigenvalues of v's Jacobi operator on the complement of v.
template <class Embedding>
std::array<double, 2> rangeThrough(const Embedding& embed, const Eigen::VectorXd& spherePoint,
                                   const Eigen::VectorXd& velocity) {
  const AmbientFrame<Embedding> frame(embed, spherePoint);
  const OrthonormalSecondForm form = orthonormalSecondForm(frame);
  const Eigen::VectorXd coefficients = form.basis.partialPivLu().solve(frame.chart.rates(velocity));
  if (!(coefficients.norm() > 0) || !coefficients.allFinite())
    throw std::invalid_argument("sectional curvature: the velocity is zero or not finite");
  const Eigen::VectorXd v = coefficients.normalized();
  const Eigen::MatrixXd A = jacobiOperator(form, frame, v);
  std::array<double, 2> range{0, 0};
  extremeDirection(A, v, -1.0, range[0]);
  extremeDirection(A, v, 1.0, range[1]);
  return range;
}

}  // namespace sl::sectional
