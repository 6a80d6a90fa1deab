#pragma once
// The time grids the program samples motions on, each defined once.

#include <vector>

namespace sl {

// Frames k = 0..ceil(duration * fps), at times k / fps. The small allowance keeps 20 s at 30 fps at 601
// frames despite rounding.
long frameCount(double duration, int fps);
inline double frameTime(long frame, int fps) { return frame / static_cast<double>(fps); }

// The frame times k / fps, k = 0..frameCount - 1.
std::vector<double> frameTimes(double duration, int fps);

// The grids below throw std::invalid_argument for a non-finite or non-positive step or duration, or more than
// limits::kMaxSamplesPerRun samples.
// k * dt for k = 0..floor(duration / dt) (the last time within rounding of the duration included).
long uniformTimeCount(double duration, double dt);
std::vector<double> uniformTimes(double duration, double dt);

// 0, interval, 2 interval, ..., and the duration itself as the last time (a last interval shorter than
// `interval` is kept; one within rounding of the duration is moved onto it).
std::vector<double> gridTimesThrough(double duration, double interval);

}  // namespace sl
