#include "simulation/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "contracts/stop_reading.hpp"
#include "linkage/sphere_coordinates.hpp"
#include "simulation/ambient_system.hpp"
#include "simulation/chart_system.hpp"
#include "simulation/constraint_solver.hpp"
#include "simulation/initial_state.hpp"
#include "simulation/jacobi_system.hpp"
#include "simulation/steppers.hpp"

namespace sl {

namespace {

// Steps shorter than this, measured in arc length (step x speed, relative to max(1, the length covered so far)),
// mean the integrator is fighting a singularity or a non-smooth field (the published metric near the seam): stop
// instead of crawling. In arc length, because a geodesic run k times faster takes k times shorter steps in time
// and is not crawling.
constexpr double minimumRelativeStep = 1e-9;

// Counts vector-field evaluations of the wrapped system.
class CountingSystem : public GeodesicSystem {
 public:
  explicit CountingSystem(std::unique_ptr<GeodesicSystem> inner) : inner_(std::move(inner)) {}
  State initialState() const override { return inner_->initialState(); }
  void derivative(const State& y, State& dydt) const override {
    ++evaluations;
    inner_->derivative(y, dydt);
  }
  bool settleBetweenSteps(State& y) override { return inner_->settleBetweenSteps(y); }
  std::optional<MethodFailure> methodFailureAt(const State& y) const override { return inner_->methodFailureAt(y); }
  PhysicalState physicalState(const State& y) const override { return inner_->physicalState(y); }
  StepInvariants stepInvariants(const State& y, double previousT) const override {
    return inner_->stepInvariants(y, previousT);
  }
  std::string describe(const State& y) const override { return inner_->describe(y); }
  std::size_t motionSize(const State& y) const override { return inner_->motionSize(y); }
  mutable long evaluations = 0;

 private:
  std::unique_ptr<GeodesicSystem> inner_;
};

std::unique_ptr<GeodesicSystem> makeSystem(const ChainConstants& bound, const InitialState& start,
                                           const RunConfig& config) {
  requireMethodMoves({config.method, &bound.chain, start.byHinges(), config.jacobi});
  if (config.method == Method::Ambient) {
    // Project once the rods drift past a tenth of the tolerance (never below rounding level).
    const double projectBeyond = std::max(1e-14, 0.1 * std::min(config.tolerance, config.maxRodLengthError));
    if (config.jacobi) return std::make_unique<JacobiSystem>(bound.chain, start, projectBeyond);
    return std::make_unique<AmbientSystem>(bound.chain, start, projectBeyond);
  }
  return std::make_unique<ChartSystem>(bound, chartMethod(config.method, bound), start);
}

void validateConfig(const RunConfig& config) {
  if (!(config.tolerance > 0) || !std::isfinite(config.tolerance))
    throw std::invalid_argument("tolerance must be positive and finite");
  if (!(config.step > 0) || !std::isfinite(config.step))
    throw std::invalid_argument("step must be positive and finite");
  if (!(config.maxRelativeEnergyDrift > 0) || !(config.maxRodLengthError > 0))
    throw std::invalid_argument("watchdog limits must be positive");
  if (config.maxSteps <= 0) throw std::invalid_argument("maxSteps must be positive");
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();

bool allFinite(const State& y) {
  return std::all_of(y.begin(), y.end(), [](double v) { return std::isfinite(v); });
}

std::string formatTime(double t) {
  std::ostringstream out;
  out.precision(17);
  out << t;
  return out.str();
}


}  // namespace

std::string StopInfo::detail() const {
  switch (reason) {  // every reason, no default
    case StopReason::NonFinite:
      return "state became non-finite in the step from t = " + formatTime(time) + "; last good state " + cause;
    case StopReason::PoleFoldBack:  // a method's own failures
    case StopReason::FieldBlowUp:
      return cause + " at t = " + formatTime(checkedAt);
    case StopReason::EnergyBlowUp:
      return "relative energy drift " + formatTime(measured) + " at t = " + formatTime(checkedAt);
    case StopReason::StepSizeCollapse:
      return std::isnan(measured) ? "integrator gave up: " + cause
                                  : "step size " + formatTime(measured) + " at t = " + formatTime(time);
    case StopReason::RodLength:
      return "rod-length error " + formatTime(measured) + " at t = " + formatTime(checkedAt);
    case StopReason::MaxSteps:
      return "reached maxSteps = " + std::to_string(static_cast<long>(limit));
    case StopReason::ConstraintRankLoss:
      return cause + " in the step from t = " + formatTime(time);
  }
  return cause;
}

std::string StopInfo::reading() const { return stopReading(reason, measured, limit); }

struct Trajectory::Impl {
  explicit Impl(const Chain& chain) : bound(chain) {}
  ChainConstants bound;  // the chain and what every step uses of it, computed once here
  RunConfig config;
  std::unique_ptr<CountingSystem> system;
  std::unique_ptr<Stepper> stepper;
  State start;
  double initialEnergy = 0;
  double speed = 1;  // sqrt(2 x initialEnergy): a geodesic's speed, constant along it
  double chartZeroTAtStart = 0, chartZeroTAtEnd = 0;  // of the current step, for unwrapping t
  long steps = 0;
  double lastSampleTime = 0;
  std::optional<StopInfo> stop;
  InvariantExtremes extremes;
  std::function<bool()> cancelled;
  // Jacobi fields (RunConfig::jacobi): the system, the Gram determinant's rate at the last step's end, the
  // largest mean eigenvalue of the Gram matrix so far, and the conjugate points found.
  const JacobiSystem* jacobi = nullptr;
  double lastGramRate = 0, maxGramMean = 0;
  std::vector<double> conjugateTimes;

  // A conjugate point is a zero of det G: there its rate goes from negative to positive (a minimum) and G is
  // singular to rounding, its smallest eigenvalue far below the fields' size elsewhere (a dip that stays away
  // from zero is not one). Located by bisection on the rate over the last step's dense output.
  void findConjugatePoint(double t0, double t1, double rate1, double mean1) {
    maxGramMean = std::max(maxGramMean, mean1);
    const bool minimumInside = lastGramRate < 0 && rate1 >= 0;
    lastGramRate = rate1;
    if (!minimumInside) return;
    State y;
    double low = t0, high = t1;
    for (int iteration = 0; iteration < 200 && high - low > 1e-14 * std::max(1.0, high); ++iteration) {
      const double middle = 0.5 * (low + high);
      stepper->stateAt(middle, y);
      (jacobi->jacobiAt(y).gramRate < 0 ? low : high) = middle;
    }
    const double time = 0.5 * (low + high);
    stepper->stateAt(time, y);
    if (isConjugateMinimum(jacobi->smallestGramEigenvalue(y), maxGramMean)) conjugateTimes.push_back(time);
  }

  void halt(const StopInfo& info) { stop = info; }

  // One integration step with every watchdog; on failure the run stops at the step's start time.
  void advance() {
    const double t0 = stepper->endTime();
    if (steps >= config.maxSteps) {
      StopInfo info;
      info.reason = StopReason::MaxSteps;
      info.time = t0;
      info.limit = double(config.maxSteps);
      return halt(info);
    }
    State y = stepper->endState();
    if (system->settleBetweenSteps(y)) stepper->initialize(*system, y, t0);
    // A failed step is rolled back: the run ends on its last good state, which stays sampleable at the
    // stop time (never the failed step's non-finite data).
    auto haltAtLastGoodState = [&](StopInfo info) {
      stepper->initialize(*system, y, t0);
      info.time = t0;
      halt(info);
    };
    const auto because = [](StopReason reason, std::string cause) {
      StopInfo info;
      info.reason = reason;
      info.cause = std::move(cause);
      return info;
    };
    const auto reading = [](StopReason reason, double at, double measured, double limit) {
      StopInfo info;
      info.reason = reason;
      info.checkedAt = at;
      info.measured = measured;
      info.limit = limit;
      return info;
    };
    try {
      stepper->doStep(*system);
    } catch (const ConstraintRankLoss& e) {
      return haltAtLastGoodState(because(StopReason::ConstraintRankLoss, e.what()));
    } catch (const NonFiniteConstraintData& e) {
      return haltAtLastGoodState(because(StopReason::NonFinite, e.what()));
    } catch (const std::exception& e) {
      return haltAtLastGoodState(because(StopReason::StepSizeCollapse, e.what()));
    }
    ++steps;
    const State& end = stepper->endState();
    const double t1 = stepper->endTime();
    if (!allFinite(end) || !std::isfinite(t1))
      return haltAtLastGoodState(because(StopReason::NonFinite, system->describe(y)));
    if (!((t1 - t0) * speed > minimumRelativeStep * std::max(1.0, std::abs(t0) * speed)))
      return haltAtLastGoodState(reading(StopReason::StepSizeCollapse, t1, t1 - t0, kNaN));
    if (const auto failure = system->methodFailureAt(end)) {
      StopInfo info = because(failure->reason, failure->detail);
      info.checkedAt = t1;
      return haltAtLastGoodState(info);
    }
    const StepInvariants summary = system->stepInvariants(end, chartZeroTAtEnd);
    const double drift = std::abs(summary.energy - initialEnergy) / initialEnergy;
    if (!(drift <= config.maxRelativeEnergyDrift))
      return haltAtLastGoodState(reading(StopReason::EnergyBlowUp, t1, drift, config.maxRelativeEnergyDrift));
    if (!(summary.rodLengthError <= config.maxRodLengthError))
      return haltAtLastGoodState(
          reading(StopReason::RodLength, t1, summary.rodLengthError, config.maxRodLengthError));
    if (jacobi) {
      const JacobiState field = jacobi->jacobiAt(end);
      findConjugatePoint(t0, t1, field.gramRate, field.gramMean);
    }
    extremes.maxRelativeEnergyDrift = std::max(extremes.maxRelativeEnergyDrift, drift);
    extremes.maxRodLengthError = std::max(extremes.maxRodLengthError, summary.rodLengthError);
    chartZeroTAtStart = chartZeroTAtEnd;
    chartZeroTAtEnd = summary.chartZeroT;
  }

  Sample sample(double t, const State& y) const {
    const PhysicalState o = system->physicalState(y);
    Sample s;
    s.time = t;
    s.spherePoint = o.spherePoint;
    s.sphereVelocity = o.sphereVelocity;
    s.hinges = o.hinges;
    s.hingeVelocities = o.hingeVelocities;
    if (o.spherePoint.size() > 0) {  // a slack chain has no sphere, no chart: hinges only
      s.coords =
          o.chartZeroCoords ? *o.chartZeroCoords : coordinatesFromSpherePoint(o.spherePoint, chartZeroTAtStart);
      s.rates = o.chartZeroRates ? *o.chartZeroRates : coordinateRatesFromSphereVelocity(s.coords, o.sphereVelocity);
      if (!s.rates.allFinite()) s.rates.setZero();  // chart 0's singular set: no rates there (never NaN)
    }
    s.energy = kineticEnergy(bound.mass, s.hingeVelocities);
    s.relativeEnergyDrift = std::abs(s.energy - initialEnergy) / initialEnergy;
    s.rodLengthError = rodLengthError(bound.chain, s.hinges);
    if (jacobi) s.jacobi = jacobi->jacobiAt(y).size;
    return s;
  }
};

Trajectory::Trajectory(const Chain& chain, const InitialState& start, const RunConfig& config)
    : impl_(std::make_unique<Impl>(chain)) {
  validateConfig(config);
  validateInitialState(chain, start);
  Impl& run = *impl_;
  run.config = config;
  std::unique_ptr<GeodesicSystem> system = makeSystem(run.bound, start, config);
  run.jacobi = dynamic_cast<const JacobiSystem*>(system.get());
  run.system = std::make_unique<CountingSystem>(std::move(system));
  run.start = run.system->initialState();
  run.stepper = makeStepper(config.integrator, config.tolerance, config.step, run.system->motionSize(run.start));
  const StepInvariants summary = run.system->stepInvariants(
      run.start, start.spherePoint.size() >= 2 ? std::atan2(start.spherePoint(1), start.spherePoint(0)) : 0.0);
  run.initialEnergy = summary.energy;
  run.speed = std::sqrt(2 * summary.energy);
  if (!(run.initialEnergy > 0)) throw std::invalid_argument("the initial velocity is zero: nothing moves");
  run.chartZeroTAtStart = run.chartZeroTAtEnd = summary.chartZeroT;
  run.stepper->initialize(*run.system, run.start, 0.0);
}

Trajectory::~Trajectory() = default;
Trajectory::Trajectory(Trajectory&&) noexcept = default;
Trajectory& Trajectory::operator=(Trajectory&&) noexcept = default;

bool Trajectory::reaches(double t) {
  Impl& run = *impl_;
  if (!std::isfinite(t) || t < 0) throw std::invalid_argument("sample time must be finite and >= 0");
  if (t < run.lastSampleTime) throw std::invalid_argument("sample times must be non-decreasing");
  while (!run.stop && t > run.stepper->endTime()) {
    if (run.cancelled && run.cancelled()) throw RunCancelled();
    run.advance();
  }
  if (run.stop && t > run.stop->time) return false;  // the stop time itself can still be sampled
  run.lastSampleTime = t;
  return true;
}

std::optional<Sample> Trajectory::sampleAt(double t) {
  Impl& run = *impl_;
  if (!reaches(t)) return std::nullopt;
  State y;
  run.stepper->stateAt(t, y);
  return run.sample(t, y);
}

void Trajectory::setCancellation(std::function<bool()> cancelled) { impl_->cancelled = std::move(cancelled); }
const std::optional<StopInfo>& Trajectory::stop() const { return impl_->stop; }
const std::vector<double>& Trajectory::conjugateTimes() const { return impl_->conjugateTimes; }
const InvariantExtremes& Trajectory::invariantExtremes() const { return impl_->extremes; }
long Trajectory::vectorFieldEvaluations() const { return impl_->system->evaluations; }
long Trajectory::steps() const { return impl_->steps; }

}  // namespace sl
