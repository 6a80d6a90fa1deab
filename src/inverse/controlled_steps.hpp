#pragma once
// The one step loop of the inverse stage's integrations (GeodesicFlow, parallel transport): Runge-Kutta-Fehlberg
// 7(8) from Boost.Odeint with step control at an absolute and relative tolerance, from 0 to `length`, the last step
// landing on `length` exactly. After every accepted step `settle(s, y)` is called: it may change y (a projection back
// onto the constraints, a change of chart) and returns whether to go on. Returns whether the whole length was
// integrated; throws std::runtime_error ("<what>: the step size collapsed at t = ...") after 500 failed tries in a
// row or once the step falls below 1e-12 of the time.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/numeric/odeint.hpp>

namespace sl {

template <class System, class Settle>
bool integrateControlled(System&& system, std::vector<double>& y, double length, double tolerance, Settle&& settle,
                         const char* what) {
  namespace odeint = boost::numeric::odeint;
  using Stepper = odeint::runge_kutta_fehlberg78<std::vector<double>>;
  auto stepper = odeint::make_controlled<Stepper>(tolerance, tolerance);
  double t = 0.0, dt = std::min(0.05, length);
  int failures = 0;
  while (t < length) {
    const bool last = dt >= length - t;
    if (last) dt = length - t;
    const double before = t;
    if (stepper.try_step(system, y, t, dt) == odeint::fail) {
      if (++failures > 500 || dt < 1e-12 * std::max(1.0, t))
        throw std::runtime_error(std::string(what) + ": the step size collapsed at t = " + std::to_string(t));
      continue;
    }
    failures = 0;
    if (last && t - before >= (length - before) * (1 - 1e-15)) t = length;
    if (!settle(t, y)) return t >= length;
  }
  return true;
}

}  // namespace sl
