#pragma once
// Scene files for the fault tests, written into a test's temporary folder: small frames (160x90),
// few frames, one fault each (a start on a singular set, a huge speed, L at an edge, n = 3 or 200).

#include <string>
#include <vector>

namespace sl::faults {

struct FaultScene {
  std::string name;
  std::string json;
};

// One scene per numerical fault, each with runs of several methods and bounded watchdogs.
std::vector<FaultScene> numericalFaultScenes();

// A plain scene of `frames` frames at 160x90 (fps 10), for the process-fault tests.
std::string smallRenderScene(int frames, const std::string& folder);

}  // namespace sl::faults
