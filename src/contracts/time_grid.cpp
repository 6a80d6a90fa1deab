#include "contracts/time_grid.hpp"

#include <cmath>

namespace sl {

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
  std::vector<double> times;
  const long count = uniformTimeCount(duration, dt);
  for (long k = 0; k < count; ++k) times.push_back(k * dt);
  return times;
}

std::vector<double> gridTimesThrough(double duration, double interval) {
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
