#include "simulation/chart_system.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "contracts/limits.hpp"
#include "linkage/chart.hpp"
#include "linkage/sphere_coordinates.hpp"
#include "simulation/exact_fields.hpp"
#include "simulation/published_fields.hpp"

namespace sl {

void requireMethodMoves(const MotionRequest& request) {
  const std::vector<MethodRefusal> refusals = methodRefusals(request);
  if (refusals.empty()) return;
  const std::string name = nameOf(request.method);
  const int rods = request.chain != nullptr ? request.chain->rods : 0;
  switch (refusals.front()) {
    case MethodRefusal::JacobiNeedsAmbient:
      throw std::invalid_argument("Jacobi fields are computed with the ambient method only");
    case MethodRefusal::SlackChainHasNoChart:
    case MethodRefusal::HingeStartHasNoChart:
      throw std::invalid_argument("a slack chain or a start by hinges has no chart: only the ambient method moves it");
    case MethodRefusal::TooManyRodsForCharts:
      throw std::invalid_argument("method '" + name + "' works in charts, limited to " +
                                  std::to_string(limits::kMaxRods) + " rods (they stay well conditioned there); the " +
                                  "chain has " + std::to_string(rods) + " rods: use ambient");
    case MethodRefusal::JacobiNeedsSpherePoint:
      throw std::invalid_argument("Jacobi fields start from a point of the configuration sphere (coords or drag)");
    case MethodRefusal::JacobiNeedsFourRods:
      throw std::invalid_argument("Jacobi fields need at least 4 rods (a direction across the motion)");
    case MethodRefusal::PublishedNeedsFourRods:
      throw std::invalid_argument("method '" + name + "' is the spec's 4-rod method (chart (phi, t)); the chain has " +
                                  std::to_string(rods) + " rods: use christoffel, embedded or ambient");
    case MethodRefusal::PublishedNeedsSpecMasses:
      throw std::invalid_argument("method '" + name +
                                  "' assumes unit hinge masses and massless rods (spec section 1): use christoffel, "
                                  "embedded or ambient for other masses");
  }
}

namespace {

template <class Field>
ChartAcceleration published(const PublishedChain& chain, Field field) {
  return [chain, field](const std::vector<int>&, const Eigen::VectorXd& c, const Eigen::VectorXd& v) {
    return Eigen::VectorXd(field(chain, Eigen::Vector2d(c), Eigen::Vector2d(v)));
  };
}

}  // namespace

ChartMethod chartMethod(Method method, const ChainConstants& bound) {
  const MethodTraits& properties = traits(method);
  const Chain& chain = bound.chain;
  requireMethodMoves({method, &chain, false, false});
  ChartAcceleration acceleration;
  switch (method) {
    case Method::ChristoffelFd:
      acceleration = published(PublishedChain(chain.baseLength), christoffelFdAcceleration);
      break;
    case Method::EmbeddedFd:
      acceleration = published(PublishedChain(chain.baseLength), embeddedFdAcceleration);
      break;
    case Method::Christoffel:
      acceleration = [bound](const std::vector<int>& axes, const Eigen::VectorXd& c, const Eigen::VectorXd& v) {
        return christoffelAcceleration(bound, axes, c, v);
      };
      break;
    case Method::Embedded:
      acceleration = [bound](const std::vector<int>& axes, const Eigen::VectorXd& c, const Eigen::VectorXd& v) {
        return embeddedAcceleration(bound, axes, c, v);
      };
      break;
    case Method::Ambient:
      throw std::invalid_argument("the ambient method is chart-free: it has no chart acceleration");
  }
  return {acceleration, properties.usesAtlas};
}

ChartSystem::ChartSystem(const ChainConstants& bound, ChartMethod method, const InitialState& start)
    : bound_(bound), method_(std::move(method)) {
  const int ambient = bound_.chain.rods - 1;
  switchBelow_ = 0.7 / std::sqrt(static_cast<double>(sphereChartCount(ambient)));
  const int first = method_.usesAtlas ? bestSphereChart(start.spherePoint) : 0;
  enterChart(first, start.spherePoint, start.sphereVelocity, start_);
  switches_ = 0;
}

void ChartSystem::enterChart(int chart, const Eigen::VectorXd& x, const Eigen::VectorXd& xdot, State& y) {
  chart_ = chart;
  axes_ = sphereChartAxes(bound_.chain.rods - 1, chart);
  const Eigen::VectorXd c = coordinatesInChart(axes_, x);
  const Eigen::VectorXd v = ratesInChart(axes_, c, xdot);
  const Eigen::Index k = c.size();
  y.resize(static_cast<size_t>(2 * k));
  Eigen::Map<Eigen::VectorXd>(y.data(), k) = c;
  Eigen::Map<Eigen::VectorXd>(y.data() + k, k) = v;
  ++switches_;
}

void ChartSystem::derivative(const State& y, State& dydt) const {
  const Eigen::Index k = static_cast<Eigen::Index>(y.size() / 2);
  const Eigen::Map<const Eigen::VectorXd> c(y.data(), k), v(y.data() + k, k);
  dydt.resize(y.size());
  Eigen::Map<Eigen::VectorXd>(dydt.data(), k) = v;
  Eigen::Map<Eigen::VectorXd>(dydt.data() + k, k) = method_.acceleration(axes_, c, v);
}

bool ChartSystem::settleBetweenSteps(State& y) {
  if (!method_.usesAtlas) return false;
  const Eigen::Index k = static_cast<Eigen::Index>(y.size() / 2);
  const Eigen::VectorXd c = Eigen::Map<const Eigen::VectorXd>(y.data(), k);
  const Eigen::VectorXd x = spherePointInChart<double>(axes_, c);
  if (sphereChartRegularity(x, chart_) >= switchBelow_) return false;
  const Eigen::VectorXd xdot = sphereVelocityInChart(axes_, c, Eigen::Map<const Eigen::VectorXd>(y.data() + k, k));
  enterChart(bestSphereChart(x), x, xdot, y);
  return true;
}

std::optional<MethodFailure> ChartSystem::methodFailureAt(const State& y) const {
  if (method_.usesAtlas) return std::nullopt;
  // Chart 0's latitudes live in [-pi/2, pi/2]; at the pole the chart folds back over itself and a run
  // continues on the mirror image, silently retracing its path (spec section 4's caveat). Stop on reaching
  // |cos phi| < poleMargin (the fields are garbage there anyway) or on crossing pi/2.
  constexpr double poleMargin = 1e-3;
  // A step ending this far past the pole did not cross it: it jumped there (a latitude moves by at most a
  // step's worth of a bounded velocity). That is the vector field blowing up, e.g. the printed metric's 0/0 on
  // the seam t = +-pi/2, and is reported as such rather than as a pole passage.
  constexpr double jumpPastPole = 0.25;
  const Eigen::Index k = static_cast<Eigen::Index>(y.size() / 2);
  for (Eigen::Index level = 0; level + 1 < k; ++level) {
    const double latitude = y[static_cast<size_t>(level)];
    if (std::abs(latitude) >= M_PI / 2 || std::abs(std::cos(latitude)) < poleMargin) {
      std::ostringstream detail;
      detail.precision(17);
      detail << "single chart (phi, t): c" << level + 1 << " = " << latitude;
      if (std::abs(latitude) >= M_PI / 2 + jumpPastPole) {
        detail << " after one step: the vector field blew up";
        if (k == 2 && std::abs(std::cos(y[1])) < 0.05)
          detail << " next to the seam t = +-pi/2 (t = " << y[1] << "), where the published metric divides 0 by 0";
        return MethodFailure{StopReason::FieldBlowUp, detail.str()};
      }
      if (std::abs(latitude) >= M_PI / 2)
        detail << " is past +-pi/2, where the chart folds back over itself";
      else
        detail << " is within |cos| = " << std::abs(std::cos(latitude)) << " < " << poleMargin
               << " of the pole, where the chart folds back";
      return MethodFailure{StopReason::PoleFoldBack, detail.str()};
    }
  }
  return std::nullopt;
}

PhysicalState ChartSystem::physicalState(const State& y) const {
  const Eigen::Index k = static_cast<Eigen::Index>(y.size() / 2);
  const Eigen::VectorXd c = Eigen::Map<const Eigen::VectorXd>(y.data(), k);
  const Eigen::VectorXd v = Eigen::Map<const Eigen::VectorXd>(y.data() + k, k);
  PhysicalState o;
  o.spherePoint = spherePointInChart<double>(axes_, c);
  o.sphereVelocity = sphereVelocityInChart(axes_, c, v);
  o.hinges = hingePositionsInChart<double>(bound_, axes_, c);
  const Eigen::VectorXd stacked = chartJacobian(bound_, axes_, c) * v;
  o.hingeVelocities = Eigen::Map<const Eigen::Matrix2Xd>(stacked.data(), 2, bound_.chain.hingeCount());
  if (chart_ == 0) {
    o.chartZeroCoords = c;
    o.chartZeroRates = v;
  }
  return o;
}

std::string ChartSystem::describe(const State& y) const {
  std::ostringstream out;
  out.precision(17);
  out << "chart " << chart_ << ", coords (";
  for (size_t i = 0; i < y.size() / 2; ++i) out << (i ? ", " : "") << y[i];
  out << "), rates (";
  for (size_t i = y.size() / 2; i < y.size(); ++i) out << (i > y.size() / 2 ? ", " : "") << y[i];
  out << ")";
  return out.str();
}

}  // namespace sl

namespace sl {

StepInvariants ChartSystem::stepInvariants(const State& y, double previousT) const {
  const Eigen::Index k = static_cast<Eigen::Index>(y.size() / 2);
  const Eigen::VectorXd c = Eigen::Map<const Eigen::VectorXd>(y.data(), k);
  const Eigen::VectorXd v = Eigen::Map<const Eigen::VectorXd>(y.data() + k, k);
  const Eigen::VectorXd stacked = chartJacobian(bound_, axes_, c) * v;
  StepInvariants summary;
  summary.energy =
      kineticEnergy(bound_.mass, Eigen::Map<const Eigen::Matrix2Xd>(stacked.data(), 2, bound_.chain.hingeCount()));
  summary.rodLengthError = rodLengthError(bound_.chain, hingePositionsInChart<double>(bound_, axes_, c));
  summary.chartZeroT =
      chart_ == 0 ? c(k - 1) : coordinatesFromSpherePoint(spherePointInChart<double>(axes_, c), previousT)(k - 1);
  return summary;
}

}  // namespace sl
