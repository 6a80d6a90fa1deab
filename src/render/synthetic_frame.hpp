#pragma once
// Synthetic FrameStates for tests and benchmarks: two 4-rod runs (L = 3) following closed-form paths
// (phi, t)(s) on the sphere, with hinges from the chart Psi (linkage/chart.hpp), trails, and two plots.
// Not a simulation: only a realistic, reproducible load for the renderer.

#include "frames/frame_state.hpp"

namespace sl {

struct SyntheticOptions {
  int runs = 2;
  double duration = 10;  // seconds of simulated time
  double samplesPerSecond = 60;
  bool stopSecondRun = false;  // the second run stops at half time with a reason
  ViewSpace viewSpace = ViewSpace::Sphere;
};

FrameState syntheticFrame(double time, int index, const SyntheticOptions& options = {});

}  // namespace sl
