#include "contracts/time_grid.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "contracts/limits.hpp"

namespace sl {
namespace {

// A grid of duration / step samples must be finite, positive and within limits::kMaxSamplesPerRun: a NaN or a
// step of 1e-300 would otherwise mean no grid at all, or one that never fits in memory.
void checkGrid(double duration, double step, const char* what) {
  std::ostringstream problem;
  if (!(std::isfinite(duration) && duration >= 0)) {
    problem << "time span " << duration << ": expected a finite, non-negative duration";
  } else if (!(std::isfinite(step) && step > 0)) {
    problem << what << " " << step << ": expected a finite, positive number";
  } else if (duration / step > static_cast<double>(limits::kMaxSamplesPerRun)) {
    problem << what << " " << step << " over " << duration << " time units gives " << duration / step
            << " samples; at most " << limits::kMaxSamplesPerRun << " are allowed (a larger " << what << ")";
  } else {
    return;
  }
  throw std::invalid_argument(problem.str());
}

}  // namespace

long frameCount(double duration, int fps) { return static_cast<long>(std::ceil(duration * fps - 1e-9)) + 1; }

std::vector<double> frameTimes(double duration, int fps) {
  std::vector<double> times;
  const long count = frameCount(duration, fps);
  times.reserve(count);
  for (long k = 0; k < count; ++k) times.push_back(frameTime(k, fps));
  return times;
}

long uniformTimeCount(double duration, double dt) { return static_cast<long>(std::floor(duration / dt + 1e-9)) + 1; }

std::vector<double> uniformTimes(double duration, double dt) {
  checkGrid(duration, dt, "step");
  std::vector<double> times;
  const long count = uniformTimeCount(duration, dt);
  for (long k = 0; k < count; ++k) times.push_back(k * dt);
  return times;
}

std::vector<double> gridTimesThrough(double duration, double interval) {
  checkGrid(duration, interval, "interval");
  std::vector<double> times;
  const long count = std::lround(std::floor(duration / interval * (1 + 1e-12)));
  for (long k = 0; k <= count; ++k) times.push_back(k * interval);
  if (duration - times.back() > 1e-9 * interval)
    times.push_back(duration);
  else
    times.back() = duration;
  return times;
}

}  // namespace sl
