#pragma once
// Integrators behind one small interface: a step from the current state, and the state anywhere inside
// the last step (dense output), so that sampling never influences the step sequence.
//   rk4            fixed step (the spec's demo); cubic Hermite between steps from the stored derivatives.
//   dopri5         Boost.Odeint's adaptive Dormand-Prince 5(4) with its 4th-order dense output.
//   rkf78          Boost.Odeint's adaptive Runge-Kutta-Fehlberg 7(8); in-between states by one extra 7(8)
//                  step from the step's start.
//   bulirsch-stoer Boost.Odeint's adaptive extrapolation method with dense output, for tight tolerances.

#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "contracts/registry.hpp"
#include "simulation/geodesic_system.hpp"

namespace sl {

class Stepper {
 public:
  virtual ~Stepper() = default;
  // Start (or restart, after the system adjusted the state) from y at time t.
  virtual void initialize(const GeodesicSystem& system, const State& y, double t) = 0;
  virtual void doStep(const GeodesicSystem& system) = 0;
  virtual double startTime() const = 0;  // of the last step
  virtual double endTime() const = 0;
  virtual const State& endState() const = 0;
  // The state at t in [startTime(), endTime()]; deterministic, independent of earlier calls.
  virtual void stateAt(double t, State& y) = 0;
};

// tolerance: absolute and relative (adaptive integrators); step: rk4's step. motionSize: how many leading
// components of the state the adaptive integrators' error control reads (GeodesicSystem::motionSize); the rest
// are integrated by the same steps and stages without being watched.
std::unique_ptr<Stepper> makeStepper(Integrator integrator, double tolerance, double step,
                                     std::size_t motionSize = std::numeric_limits<std::size_t>::max());

}  // namespace sl
