#include "simulation/steppers.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <boost/numeric/odeint.hpp>

namespace sl {

namespace odeint = boost::numeric::odeint;

namespace {

// Odeint's range algebra, with one change: its norm, which Odeint uses only to reduce the error estimate of a
// step (error checker) to one number, reads the state's first `controlled` components. Every other operation,
// and so every stage and every accepted step, is the range algebra's, component by component: the leading
// components evolve exactly as they would in a state that holds nothing else, and the trailing ones (Jacobi
// fields) follow the steps the leading ones chose.
struct MotionAlgebra : odeint::range_algebra {
  MotionAlgebra() : controlled(constructionDefault) {}
  explicit MotionAlgebra(std::size_t leading) : controlled(leading) {}

  template <class S>
  double norm_inf(const S& s) const {
    using std::abs;
    using std::max;
    double out = 0;  // as odeint::detail::norm_inf, over a prefix
    const std::size_t end = std::min(controlled, static_cast<std::size_t>(s.size()));
    for (std::size_t i = 0; i < end; ++i) out = max(out, abs(s[i]));
    return out;
  }

  std::size_t controlled;
  // For the steppers that build their algebra themselves (Bulirsch-Stoer with dense output takes none from
  // its caller): the value a default-constructed algebra takes, set around their construction only.
  static thread_local std::size_t constructionDefault;
};
thread_local std::size_t MotionAlgebra::constructionDefault = std::numeric_limits<std::size_t>::max();

// Odeint calls systems as f(x, dxdt, t); ours are autonomous.
struct OdeintSystem {
  const GeodesicSystem* system;
  void operator()(const State& y, State& dydt, double) const { system->derivative(y, dydt); }
};

// Fixed-step classical RK4. The derivative at the end of a step is the first stage of the next one, so the
// Hermite data costs nothing extra. Step k ends at start + k h exactly (no accumulated additions).
class Rk4Hermite : public Stepper {
 public:
  explicit Rk4Hermite(double step) : h_(step) {}

  void initialize(const GeodesicSystem& system, const State& y, double t) override {
    origin_ = t, count_ = 0, t0_ = t1_ = t;
    y1_ = y;
    system.derivative(y1_, f1_);
  }
  void doStep(const GeodesicSystem& system) override {
    y0_ = y1_, f0_ = f1_, t0_ = t1_;
    rk4_.do_step(OdeintSystem{&system}, y1_, f0_, t0_, h_);
    t1_ = origin_ + static_cast<double>(++count_) * h_;
    system.derivative(y1_, f1_);
  }
  double startTime() const override { return t0_; }
  double endTime() const override { return t1_; }
  const State& endState() const override { return y1_; }
  void stateAt(double t, State& y) override {
    const double dt = t1_ - t0_;
    if (dt == 0) {
      y = y1_;
      return;
    }
    const double s = (t - t0_) / dt, s2 = s * s, s3 = s2 * s;  // cubic Hermite basis on [0, 1]
    const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
    y.resize(y1_.size());
    for (size_t i = 0; i < y.size(); ++i) y[i] = h00 * y0_[i] + h10 * dt * f0_[i] + h01 * y1_[i] + h11 * dt * f1_[i];
  }

 private:
  odeint::runge_kutta4<State> rk4_;
  double h_, origin_ = 0, t0_ = 0, t1_ = 0;
  long count_ = 0;
  State y0_, y1_, f0_, f1_;
};

// Any Odeint dense-output stepper. The step size it last chose carries over restarts.
template <class Dense>
class DenseOutput : public Stepper {
 public:
  DenseOutput(Dense dense, double firstStep) : dense_(std::move(dense)), suggested_(firstStep) {}
  // Built in place, from Dense's own constructor arguments.
  template <class... Args>
  DenseOutput(double firstStep, std::in_place_t, Args&&... args)
      : dense_(std::forward<Args>(args)...), suggested_(firstStep) {}

  void initialize(const GeodesicSystem&, const State& y, double t) override {
    if (started_) suggested_ = dense_.current_time_step();
    dense_.initialize(y, t, suggested_);
    started_ = true;
    t0_ = t1_ = t;
  }
  void doStep(const GeodesicSystem& system) override {
    const auto interval = dense_.do_step(OdeintSystem{&system});
    t0_ = interval.first, t1_ = interval.second;
  }
  double startTime() const override { return t0_; }
  double endTime() const override { return t1_; }
  const State& endState() const override { return dense_.current_state(); }
  void stateAt(double t, State& y) override {
    y.resize(dense_.current_state().size());
    if (t == t1_)
      y = dense_.current_state();  // exact, also before the first step
    else
      dense_.calc_state(t, y);
  }

 private:
  Dense dense_;
  double suggested_;
  bool started_ = false;
  double t0_ = 0, t1_ = 0;
};

// Adaptive Runge-Kutta-Fehlberg 7(8). Odeint gives it no dense output, so a state inside a step is one
// extra 7(8) step from the step's start: as accurate as the step itself, and it leaves the step sequence
// untouched (13 evaluations per in-between sample).
class Rkf78 : public Stepper {
 public:
  Rkf78(double tolerance, std::size_t motionSize)
      : controlled_(odeint::make_controlled(tolerance, tolerance, Method(MotionAlgebra(motionSize)))) {}

  void initialize(const GeodesicSystem& system, const State& y, double t) override {
    system_ = &system;
    y1_ = y;
    t0_ = t1_ = t;
  }
  void doStep(const GeodesicSystem& system) override {
    system_ = &system;
    y0_ = y1_, t0_ = t1_;
    double t = t1_;
    for (int failures = 0; controlled_.try_step(OdeintSystem{&system}, y1_, t, dt_) == odeint::fail;)
      if (++failures > maxFailures) throw std::runtime_error("rkf78: no acceptable step after 500 reductions");
    t1_ = t;
  }
  double startTime() const override { return t0_; }
  double endTime() const override { return t1_; }
  const State& endState() const override { return y1_; }
  void stateAt(double t, State& y) override {
    if (t == t1_) {
      y = y1_;
    } else {
      y = y0_;
      if (t != t0_) plain_.do_step(OdeintSystem{system_}, y, t0_, t - t0_);
    }
  }

 private:
  using Method = odeint::runge_kutta_fehlberg78<State, double, State, double, MotionAlgebra>;
  static constexpr int maxFailures = 500;
  odeint::controlled_runge_kutta<Method> controlled_;
  Method plain_;
  const GeodesicSystem* system_ = nullptr;
  State y0_, y1_;
  double t0_ = 0, t1_ = 0, dt_ = 0.01;
};

template <class Dense>
std::unique_ptr<Stepper> dense(Dense stepper, double firstStep) {
  return std::make_unique<DenseOutput<Dense>>(std::move(stepper), firstStep);
}

}  // namespace

std::unique_ptr<Stepper> makeStepper(Integrator integrator, double tolerance, double step, std::size_t motionSize) {
  // A cautious first step; the controllers grow it within a few steps.
  const double firstStep = 1e-3;
  switch (integrator) {
    case Integrator::Rk4:
      return std::make_unique<Rk4Hermite>(step);
    case Integrator::Dopri5:
      return dense(odeint::make_dense_output(
                       tolerance, tolerance,
                       odeint::runge_kutta_dopri5<State, double, State, double, MotionAlgebra>(MotionAlgebra(motionSize))),
                   firstStep);
    case Integrator::Rkf78:
      return std::make_unique<Rkf78>(tolerance, motionSize);
    case Integrator::BulirschStoer: {
      // control_interpolation: the error of the dense output itself enters the step control, so that samples
      // between the (long) extrapolation steps are as accurate as the steps.
      struct Scope {
        explicit Scope(std::size_t n) { MotionAlgebra::constructionDefault = n; }
        ~Scope() { MotionAlgebra::constructionDefault = std::numeric_limits<std::size_t>::max(); }
      } scope(motionSize);
      using Extrapolation = odeint::bulirsch_stoer_dense_out<State, double, State, double, MotionAlgebra>;
      return std::make_unique<DenseOutput<Extrapolation>>(firstStep, std::in_place, tolerance, tolerance, 1.0, 1.0, 0.0,
                                                          true);
    }
  }
  throw std::invalid_argument("unknown integrator");
}

}  // namespace sl
