#pragma once
// The intrinsic methods as an ODE on (coords, rates) in a chart of the sphere S^(n-2).
// With an atlas (christoffel, embedded) the system changes chart between steps when the current chart's
// regularity falls below switchBelow, to the best chart at that point (hysteresis: the best chart's
// regularity is always above 1/sqrt(chart count) > switchBelow), converting through x and xdot.
// Without an atlas (the published -fd methods) it stays in chart 0 and reports the pole fold-back.

#include <functional>
#include <memory>

#include "contracts/registry.hpp"
#include "contracts/run_config.hpp"
#include "linkage/chain_constants.hpp"
#include "linkage/method_rules.hpp"
#include "linkage/sphere_coordinates.hpp"  // sphereVelocityInChart, ratesInChart
#include "simulation/geodesic_system.hpp"

namespace sl {

// a = acceleration(axes, coords, rates) in the chart with those axes.
using ChartAcceleration =
    std::function<Eigen::VectorXd(const std::vector<int>&, const Eigen::VectorXd&, const Eigen::VectorXd&)>;

struct ChartMethod {
  ChartAcceleration acceleration;
  bool usesAtlas = true;
};

// Throws std::invalid_argument, in the simulation's words, for the first reason (linkage/method_rules.hpp) the
// request cannot be carried out.
void requireMethodMoves(const MotionRequest& request);

// A chart-based method (every method but ambient); throws std::invalid_argument for the ambient method and for
// chains it does not cover (requireMethodMoves).
ChartMethod chartMethod(Method method, const ChainConstants& bound);

class ChartSystem : public GeodesicSystem {
 public:
  ChartSystem(const ChainConstants& bound, ChartMethod method, const InitialState& start);

  State initialState() const override { return start_; }
  void derivative(const State& y, State& dydt) const override;
  bool settleBetweenSteps(State& y) override;
  std::optional<MethodFailure> methodFailureAt(const State& y) const override;
  PhysicalState physicalState(const State& y) const override;
  StepInvariants stepInvariants(const State& y, double previousT) const override;
  std::string describe(const State& y) const override;

  int chart() const { return chart_; }
  int chartSwitches() const { return switches_; }

 private:
  void enterChart(int chart, const Eigen::VectorXd& x, const Eigen::VectorXd& xdot, State& y);

  ChainConstants bound_;
  ChartMethod method_;
  int chart_ = 0;
  std::vector<int> axes_;
  double switchBelow_ = 0;
  int switches_ = 0;
  State start_;
};

}  // namespace sl
