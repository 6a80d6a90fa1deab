// Sectional curvature against the Jacobi equation (issue: holonomy and the curvature of S^3). Along a motion of 5 rods
// a Jacobi field J (a variation of the motion, GeodesicFlow's dq with dq(0) = 0) obeys D^2 J + R(J, v) v = 0, so
//   K(J, v) (|J|^2 |v|^2 - <J, v>^2) = -<D^2 J, J> = -<J'', J>_M - |(J')_normal|_M^2,
// where J'' and J' are the ambient derivatives the linearised flow integrates. The left side comes from
// geometry/sectional_curvature.hpp (the Gauss equation and the Riemann tensor), the right from the flow: no
// formula is shared.

#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "geometry/sectional_curvature.hpp"
#include "inverse/geodesic_flow.hpp"
#include "linkage/chain_constants.hpp"
#include "linkage/chart.hpp"
#include "simulation/ambient_system.hpp"
#include "simulation/initial_state.hpp"

namespace sl {
namespace {

struct Motion {
  Chain chain;
  Eigen::VectorXd coords, rates;
};

std::vector<Motion> motions() {
  Chain heavy = Chain::uniform(5, 3.6);
  heavy.rodMasses.setConstant(2.0);
  Chain mixed = Chain::uniform(5, 4.5);
  mixed.hingeMasses << 0.5, 2.0, 1.0, 3.0;
  mixed.rodMasses << 0.0, 1.5, 0.25, 3.0, 0.5;
  return {{Chain::uniform(5, 4.0), Eigen::Vector3d(0.3, -0.2, 0.5), Eigen::Vector3d(0.4, 0.3, -0.6)},
          {heavy, Eigen::Vector3d(-0.6, 0.9, 2.0), Eigen::Vector3d(0.2, -0.5, 0.3)},
          {mixed, Eigen::Vector3d(1.1, 0.1, -1.0), Eigen::Vector3d(-0.3, 0.2, 0.7)}};
}

TEST(JacobiCurvature, FieldsObeyTheJacobiEquationWithTheSectionalCurvatureAlongThreeRuns) {
  double worst = 0;
  int checked = 0;
  for (const Motion& run : motions()) {
    const ChainConstants bound(run.chain);
    const ConstrainedModel model = ConstrainedModel::fromChain(run.chain);
    const GeodesicFlow flow(model, 1e-13);
    const InitialState start = initialStateFromChart(run.chain, run.coords, run.rates);
    const Eigen::VectorXd q0 = ConstrainedModel::stack(hingePositionsAt(run.chain, start.spherePoint));
    const Eigen::VectorXd v0 = ConstrainedModel::stack(hingeVelocitiesOnSphere(run.chain, start.spherePoint, start.sphereVelocity));
    // Fields through the start in two directions: J(0) = 0, J'(0) = e.
    const Eigen::MatrixXd basis = model.tangentBasis(q0);
    FlowState s{q0, v0, Eigen::MatrixXd::Zero(q0.size(), 2), basis.leftCols(2)};
    model.projectVariations(s.q, s.v, s.dq, s.dv);
    double at = 0;
    for (double t = 0.5; t <= 6.0; t += 0.5) {
      ASSERT_TRUE(flow.advance(s, t - at));
      at = t;
      std::vector<double> y, dydt;
      const Eigen::Index n = s.q.size();
      y.resize(static_cast<std::size_t>(2 * n * 3));
      Eigen::Map<Eigen::VectorXd>(y.data(), n) = s.q;
      Eigen::Map<Eigen::VectorXd>(y.data() + n, n) = s.v;
      Eigen::Map<Eigen::MatrixXd>(y.data() + 2 * n, n, 2) = s.dq;
      Eigen::Map<Eigen::MatrixXd>(y.data() + 4 * n, n, 2) = s.dv;
      flow.derivative(y, dydt, 2);
      const Eigen::VectorXd x = spherePointFromHinges(run.chain, ConstrainedModel::unstack(s.q));
      const Eigen::VectorXd xdot = sphereVelocityFromHingeVelocities(run.chain, x, ConstrainedModel::unstack(s.v));
      for (int j = 0; j < 2; ++j) {
        const Eigen::VectorXd J = s.dq.col(j), Jdot = s.dv.col(j);
        const Eigen::VectorXd Jddot = Eigen::Map<const Eigen::VectorXd>(dydt.data() + 4 * n + n * j, n);
        const double area2 = model.inner(J, J) * model.inner(s.v, s.v) - std::pow(model.inner(J, s.v), 2);
        if (area2 < 1e-6 * model.inner(J, J) * model.inner(s.v, s.v)) continue;  // J along v: no plane
        const Eigen::VectorXd normal = Jdot - model.projectVelocity(s.q, Jdot);
        const double jacobi = (-model.inner(Jddot, J) - model.inner(normal, normal)) / area2;
        const Eigen::VectorXd Jsphere = sphereVelocityFromHingeVelocities(run.chain, x, ConstrainedModel::unstack(J));
        const double gauss = sectionalCurvature(bound, x, Jsphere, xdot);
        const double intrinsic = sectionalCurvatureIntrinsic(bound, x, Jsphere, xdot);
        const double scale = std::max(1.0, std::abs(gauss));
        worst = std::max({worst, std::abs(jacobi - gauss) / scale, std::abs(jacobi - intrinsic) / scale});
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 50);
  RecordProperty("worst_relative_difference", (std::ostringstream() << std::scientific << worst).str());
  EXPECT_LT(worst, 1e-8);
}

}  // namespace
}  // namespace sl
