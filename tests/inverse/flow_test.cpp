#include <cmath>

#include <gtest/gtest.h>

#include "support.hpp"

#include "inverse/constrained_model.hpp"
#include "inverse/geodesic_flow.hpp"
#include "linkage/chart.hpp"
#include "simulation/initial_state.hpp"
#include "simulation/trajectory.hpp"

namespace sl {
namespace {

// The constraints of the chain model are the rods: a configuration from the chart satisfies them.
TEST(ConstrainedModel, ChainConstraintsVanishOnTheChart) {
  Chain chain = Chain::uniform(4, 3.0);
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  EXPECT_EQ(model.freedom(), 2);
  EXPECT_LT(model.values(pointOf(chain, 0.3, -1.1)).cwiseAbs().maxCoeff(), 1e-15);
  Eigen::VectorXd off = pointOf(chain, 0.3, -1.1);
  off(0) += 1e-3;
  EXPECT_GT(model.values(off).cwiseAbs().maxCoeff(), 1e-4);
}

// The flow's geodesic is the ambient method's (an independent integrator and solver).
TEST(GeodesicFlow, AgreesWithTheAmbientMethod) {
  Chain chain = Chain::uniform(5, 3.6);
  chain.hingeMasses << 1.0, 2.0, 0.5, 1.5;
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  Eigen::VectorXd x(4), xdot(4);
  x << 0.3, -0.5, 0.4, 0.7;
  x.normalize();
  xdot << 0.2, 0.9, -0.3, 0.1;
  xdot -= x.dot(xdot) * x;
  Trajectory run(chain, InitialState(x, xdot), RunConfig{});
  const auto end = run.sampleAt(2.0);
  ASSERT_TRUE(end.has_value());
  const auto startSample = Trajectory(chain, InitialState(x, xdot), RunConfig{}).sampleAt(0.0);
  FlowState s{ConstrainedModel::stack(startSample->hinges), ConstrainedModel::stack(startSample->hingeVelocities),
              Eigen::MatrixXd(8, 0), Eigen::MatrixXd(8, 0)};
  GeodesicFlow(model, 1e-13).advance(s, 2.0);
  EXPECT_LT((s.q - ConstrainedModel::stack(end->hinges)).cwiseAbs().maxCoeff(), 1e-10);
}

// The variations are the derivative of the flow: against central differences of the end state.
TEST(GeodesicFlow, VariationsAreTheDerivativeOfTheFlow) {
  for (const ConstrainedModel& model :
       {ConstrainedModel::fromChain(Chain::uniform(4, 2.5)), ConstrainedModel::ellipsoid(1.0, 1.6, 2.1)}) {
    Eigen::VectorXd q = model.dimension() == 6 ? pointOf(Chain::uniform(4, 2.5), 0.4, 0.9)
                                               : Eigen::VectorXd(Eigen::Vector3d(0.5, 0.8, 1.2));
    ASSERT_TRUE(model.projectPosition(q));
    const Eigen::MatrixXd basis = model.tangentBasis(q);
    const Eigen::VectorXd v = 1.3 * basis.col(0) + 0.4 * basis.col(1);
    const GeodesicFlow flow(model, 1e-13);
    FlowState s{q, v, Eigen::MatrixXd::Zero(q.size(), 2), basis};
    flow.advance(s, 1.5);
    for (int j = 0; j < 2; ++j) {
      const double h = 1e-5;
      FlowState plus{q, v + h * basis.col(j), Eigen::MatrixXd(q.size(), 0), Eigen::MatrixXd(q.size(), 0)};
      FlowState minus{q, v - h * basis.col(j), Eigen::MatrixXd(q.size(), 0), Eigen::MatrixXd(q.size(), 0)};
      flow.advance(plus, 1.5);
      flow.advance(minus, 1.5);
      const Eigen::VectorXd difference = (plus.q - minus.q) / (2 * h);
      EXPECT_LT((difference - s.dq.col(j)).cwiseAbs().maxCoeff(), 1e-6) << "column " << j;
      EXPECT_GT(s.dq.col(j).norm(), 1e-2);
    }
  }
}

}  // namespace
}  // namespace sl
