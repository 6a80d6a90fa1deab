#include "simulation/exact_fields.hpp"

#include <unsupported/Eigen/AutoDiff>

#include "linkage/chart.hpp"
#include "linkage/kinetic_metric.hpp"

// Eigen declares AutoDiffScalar<D> x D::Scalar products, but for a nested dual D::Scalar is the inner dual,
// not double; the chart multiplies by plain doubles (x * alpha), so declare that product too.
namespace Eigen {
template <typename InnerDerivatives, int R, int O, int MR, typename BinOp>
struct ScalarBinaryOpTraits<AutoDiffScalar<Matrix<AutoDiffScalar<InnerDerivatives>, R, 1, O, MR, 1>>, double, BinOp> {
  using ReturnType = AutoDiffScalar<Matrix<AutoDiffScalar<InnerDerivatives>, R, 1, O, MR, 1>>;
};
template <typename InnerDerivatives, int R, int O, int MR, typename BinOp>
struct ScalarBinaryOpTraits<double, AutoDiffScalar<Matrix<AutoDiffScalar<InnerDerivatives>, R, 1, O, MR, 1>>, BinOp> {
  using ReturnType = AutoDiffScalar<Matrix<AutoDiffScalar<InnerDerivatives>, R, 1, O, MR, 1>>;
};
}  // namespace Eigen

namespace sl {
namespace {

// Nested forward AD of Psi. Outer derivatives (direction b) give the Jacobian columns q_b; each of their
// entries is itself a dual number whose derivatives (direction a) are d_a q_b. Fixed-size duals for the
// 4-rod case (k = 2) keep the hot path free of heap traffic in the derivative vectors.
template <int K>
struct NestedJacobian {
  using Inner = Eigen::AutoDiffScalar<Eigen::Matrix<double, K, 1>>;
  using Outer = Eigen::AutoDiffScalar<Eigen::Matrix<Inner, K, 1>>;

  // columns[b](r) = d q_r / d c_b, carrying d/dc_a as inner derivatives.
  static std::vector<VectorX<Inner>> jacobianColumns(const ChainConstants& bound, const std::vector<int>& axes,
                                                     const Eigen::VectorXd& coords) {
    const Eigen::Index k = coords.size();
    VectorX<Outer> c(k);
    for (Eigen::Index i = 0; i < k; ++i) {
      Eigen::Matrix<Inner, K, 1> outerSeed(k);
      for (Eigen::Index b = 0; b < k; ++b)
        outerSeed(b) = Inner(b == i ? 1.0 : 0.0, Eigen::Matrix<double, K, 1>::Zero(k));
      c(i) = Outer(Inner(coords(i), k, i), outerSeed);
    }
    const HingeMatrix<Outer> hinges = hingePositionsInChart<Outer>(bound, axes, c);
    const Eigen::Index rows = 2 * hinges.cols();
    std::vector<VectorX<Inner>> columns(static_cast<size_t>(k), VectorX<Inner>(rows));
    for (Eigen::Index h = 0; h < hinges.cols(); ++h)
      for (int xy = 0; xy < 2; ++xy) {
        const auto& d = hinges(xy, h).derivatives();
        for (Eigen::Index b = 0; b < k; ++b) {
          Inner entry = d.size() ? d(b) : Inner(0.0);
          if (entry.derivatives().size() == 0) entry.derivatives() = Eigen::Matrix<double, K, 1>::Zero(k);
          columns[static_cast<size_t>(b)](2 * h + xy) = entry;
        }
      }
    return columns;
  }

  // h_bc with inner derivatives d_a h_bc: the metric differentiated exactly.
  static void metricAndDerivatives(const ChainConstants& bound, const std::vector<int>& axes,
                                   const Eigen::VectorXd& coords, Eigen::MatrixXd& h,
                                   std::vector<Eigen::MatrixXd>& dh) {
    const Eigen::Index k = coords.size();
    const std::vector<VectorX<Inner>> q = jacobianColumns(bound, axes, coords);
    const AmbientMassMatrix& mass = bound.mass;
    h.resize(k, k);
    dh.assign(static_cast<size_t>(k), Eigen::MatrixXd(k, k));
    for (Eigen::Index b = 0; b < k; ++b)
      for (Eigen::Index c = b; c < k; ++c) {
        const Inner hbc = massInnerProduct(mass, q[static_cast<size_t>(b)], q[static_cast<size_t>(c)], k);
        h(b, c) = h(c, b) = hbc.value();
        for (Eigen::Index a = 0; a < k; ++a)
          dh[static_cast<size_t>(a)](b, c) = dh[static_cast<size_t>(a)](c, b) = hbc.derivatives()(a);
      }
  }

  // <u, M w> for stacked hinge vectors, M block-tridiagonal (spec section 1).
  static Inner massInnerProduct(const AmbientMassMatrix& mass, const VectorX<Inner>& u, const VectorX<Inner>& w,
                                Eigen::Index k) {
    Inner sum(0.0, Eigen::Matrix<double, K, 1>::Zero(k));
    const Eigen::Index hinges = mass.diagonal.size();
    for (Eigen::Index j = 0; j < hinges; ++j)
      sum += mass.diagonal(j) * (u(2 * j) * w(2 * j) + u(2 * j + 1) * w(2 * j + 1));
    for (Eigen::Index j = 0; j + 1 < hinges; ++j) {
      if (mass.coupling(j) == 0.0) continue;
      sum += mass.coupling(j) * (u(2 * j) * w(2 * j + 2) + u(2 * j + 1) * w(2 * j + 3) + u(2 * j + 2) * w(2 * j) +
                                 u(2 * j + 3) * w(2 * j + 1));
    }
    return sum;
  }
};

template <int K>
std::vector<Eigen::MatrixXd> symbols(const ChainConstants& bound, const std::vector<int>& axes,
                                     const Eigen::VectorXd& coords) {
  Eigen::MatrixXd h;
  std::vector<Eigen::MatrixXd> dh;
  NestedJacobian<K>::metricAndDerivatives(bound, axes, coords, h, dh);
  const Eigen::Index k = coords.size();
  const Eigen::LDLT<Eigen::MatrixXd> inverse(h);
  // Gamma^i_jk = (1/2) h^il (d_j h_lk + d_k h_lj - d_l h_jk)
  std::vector<Eigen::MatrixXd> lowered(static_cast<size_t>(k), Eigen::MatrixXd(k, k));  // Gamma_l,jk
  for (Eigen::Index l = 0; l < k; ++l)
    for (Eigen::Index j = 0; j < k; ++j)
      for (Eigen::Index m = 0; m < k; ++m)
        lowered[static_cast<size_t>(l)](j, m) =
            0.5 *
            (dh[static_cast<size_t>(j)](l, m) + dh[static_cast<size_t>(m)](l, j) - dh[static_cast<size_t>(l)](j, m));
  std::vector<Eigen::MatrixXd> gamma(static_cast<size_t>(k), Eigen::MatrixXd(k, k));
  Eigen::VectorXd column(k);
  for (Eigen::Index j = 0; j < k; ++j)
    for (Eigen::Index m = 0; m < k; ++m) {
      for (Eigen::Index l = 0; l < k; ++l) column(l) = lowered[static_cast<size_t>(l)](j, m);
      const Eigen::VectorXd raised = inverse.solve(column);
      for (Eigen::Index i = 0; i < k; ++i) gamma[static_cast<size_t>(i)](j, m) = raised(i);
    }
  return gamma;
}

// Second derivative of q along the rates, q_bc v^b v^c, and the Jacobian, from one nested pass along the
// single direction v (inner and outer both d/ds of q(c + s v)) plus the first-order Jacobian.
Eigen::VectorXd secondDirectionalDerivative(const ChainConstants& bound, const std::vector<int>& axes,
                                            const Eigen::VectorXd& coords, const Eigen::VectorXd& rates) {
  using Inner = Eigen::AutoDiffScalar<Eigen::Matrix<double, 1, 1>>;
  using Outer = Eigen::AutoDiffScalar<Eigen::Matrix<Inner, 1, 1>>;
  const Eigen::Index k = coords.size();
  VectorX<Outer> c(k);
  for (Eigen::Index i = 0; i < k; ++i) {
    Eigen::Matrix<Inner, 1, 1> outerSeed;
    outerSeed(0) = Inner(rates(i), Eigen::Matrix<double, 1, 1>::Zero());
    c(i) = Outer(Inner(coords(i), Eigen::Matrix<double, 1, 1>(rates(i))), outerSeed);
  }
  const HingeMatrix<Outer> hinges = hingePositionsInChart<Outer>(bound, axes, c);
  Eigen::VectorXd w(2 * hinges.cols());
  for (Eigen::Index h = 0; h < hinges.cols(); ++h)
    for (int xy = 0; xy < 2; ++xy) {
      const auto& d = hinges(xy, h).derivatives();
      w(2 * h + xy) = (d.size() && d(0).derivatives().size()) ? d(0).derivatives()(0) : 0.0;
    }
  return w;
}

}  // namespace

std::vector<Eigen::MatrixXd> christoffelSymbols(const ChainConstants& bound, const std::vector<int>& axes,
                                                const Eigen::VectorXd& coords) {
  if (coords.size() == 2) return symbols<2>(bound, axes, coords);
  return symbols<Eigen::Dynamic>(bound, axes, coords);
}

Eigen::VectorXd christoffelAcceleration(const ChainConstants& bound, const std::vector<int>& axes,
                                        const Eigen::VectorXd& coords, const Eigen::VectorXd& rates) {
  const std::vector<Eigen::MatrixXd> gamma = christoffelSymbols(bound, axes, coords);
  Eigen::VectorXd a(coords.size());
  for (Eigen::Index i = 0; i < a.size(); ++i) a(i) = -rates.dot(gamma[static_cast<size_t>(i)] * rates);
  return a;
}

Eigen::VectorXd embeddedAcceleration(const ChainConstants& bound, const std::vector<int>& axes,
                                     const Eigen::VectorXd& coords, const Eigen::VectorXd& rates) {
  const Eigen::MatrixXd J = chartJacobian(bound, axes, coords);
  const Eigen::MatrixXd MJ = bound.stackedMass * J;
  const Eigen::VectorXd w = secondDirectionalDerivative(bound, axes, coords, rates);
  // h a = -<q_a, M q_bc v^b v^c>: the acceleration q'' = J a + w has no tangential (M-orthogonal) part.
  return (J.transpose() * MJ).ldlt().solve(-MJ.transpose() * w);
}

}  // namespace sl
