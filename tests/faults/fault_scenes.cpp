#include "fault_scenes.hpp"

#include <sstream>

namespace sl::faults {

namespace {

// Runs of every method: the published ones with fixed steps, the exact and ambient ones adaptive.
const char* kEveryMethod = R"([
    { "name": "christoffel-fd", "method": "christoffel-fd", "integrator": "rk4", "step": 0.01, "watchdog": { "max_steps": 20000 } },
    { "name": "embedded-fd", "method": "embedded-fd", "integrator": "rk4", "step": 0.01, "watchdog": { "max_steps": 20000 } },
    { "name": "christoffel", "method": "christoffel", "integrator": "dopri5", "tolerance": 1e-9, "watchdog": { "max_steps": 20000 } },
    { "name": "embedded", "method": "embedded", "integrator": "dopri5", "tolerance": 1e-9, "watchdog": { "max_steps": 20000 } },
    { "name": "ambient", "method": "ambient", "integrator": "rkf78", "tolerance": 1e-10, "watchdog": { "max_steps": 20000 } }
  ])";

// The generic methods only: the published (-fd) methods are defined for 4 rods.
const char* kGenericMethods = R"([
    { "name": "christoffel", "method": "christoffel", "integrator": "dopri5", "tolerance": 1e-9, "watchdog": { "max_steps": 20000 } },
    { "name": "embedded", "method": "embedded", "integrator": "rk4", "step": 0.01, "watchdog": { "max_steps": 20000 } },
    { "name": "ambient", "method": "ambient", "integrator": "rkf78", "tolerance": 1e-10, "watchdog": { "max_steps": 20000 } }
  ])";

std::string scene(const std::string& name, int rods, const std::string& baseLength, const std::string& initial,
                  double duration, int fps, const std::string& runs = kEveryMethod) {
  std::ostringstream text;
  text << "{ \"name\": \"" << name << "\", \"linkage\": { \"rods\": " << rods << ", \"L\": " << baseLength << " },\n"
       << "  \"initial\": " << initial << ",\n  \"duration\": " << duration << ",\n  \"runs\": " << runs << ",\n"
       << "  \"output\": { \"fps\": " << fps << ", \"width\": 160, \"height\": 90 },\n"
       << "  \"view\": { \"panels\": [\"sphere\", \"linkage\", { \"panel\": \"plot\", \"plot\": \"energy\" }, "
          "\"text\"], \"trails\": [1] } }\n";
  return text.str();
}

std::string zeros(int count, const std::string& value) {
  std::string text = "[";
  for (int i = 0; i < count; ++i) text += (i ? ", " : "") + value;
  return text + "]";
}

}  // namespace

std::vector<FaultScene> numericalFaultScenes() {
  const std::string pole = "1.5707963267948966";
  const std::string coords4 = R"({ "coords": [0.3, 0.2], "velocity": [0.5, 0.7] })";
  std::vector<FaultScene> scenes = {
      {"pole", scene("pole", 4, "3.0", R"({ "coords": [)" + pole + R"(, 0], "velocity": [0.3, 0.5] })", 4, 5)},
      {"seam-plus",
       scene("seam-plus", 4, "3.0", R"({ "coords": [0.3, )" + pole + R"(], "velocity": [0.2, 0.7] })", 4, 5)},
      {"seam-minus",
       scene("seam-minus", 4, "3.0", R"({ "coords": [0.3, -)" + pole + R"(], "velocity": [0.2, 0.7] })", 4, 5)},
      // Fast, but within limits::kMaxHingeTravel (faster starts are refused up front: hostile_outputs_cli_test.cpp).
      {"huge-velocity", scene("huge-velocity", 4, "3.0", R"({ "coords": [0.3, 0.2], "velocity": [5e4, 7e4] })", 2, 5)},
      {"L-near-n-minus-2", scene("L-near-n-minus-2", 4, "2.000000000001", coords4, 2, 5)},
      {"L-near-n", scene("L-near-n", 4, "3.999999999999", coords4, 2, 5)},
      {"three-rods", scene("three-rods", 3, "1.5", R"({ "coords": [0.4], "velocity": [1] })", 4, 5, kGenericMethods)},
      {"long-duration", scene("long-duration", 4, "3.0", coords4, 1e5, 1,
                              R"([{ "name": "big-steps", "method": "christoffel-fd", "integrator": "rk4", "step": 1e4 },
                                  { "name": "bounded", "method": "ambient", "integrator": "dopri5", "watchdog": { "max_steps": 3000 } }])")},
  };
  // n = 12 is the scene format's largest chain (limits::kMaxRods); n = 200 is covered through the
  // simulation API in numerical_faults_test.cpp.
  scenes.push_back(
      {"twelve-rods", scene("twelve-rods", 12, "10.5",
                            "{ \"coords\": " + zeros(10, "0.2") + ", \"velocity\": " + zeros(10, "0.3") + " }", 1, 5,
                            kGenericMethods)});
  return scenes;
}

std::string smallRenderScene(int frames, const std::string& folder) {
  std::ostringstream text;
  text << R"({ "name": "small", "linkage": { "rods": 4, "L": 3.0 },
  "initial": { "drag": { "point": [0.936, 0.190, 0.296], "direction": [-0.35, 0.55, 0.75] }, "unit_speed": true },
  "duration": )"
       << (frames - 1) / 10.0 << R"(,
  "runs": [ { "name": "geodesic", "method": "ambient", "integrator": "dopri5", "tolerance": 1e-9 } ],
  "output": { "fps": 10, "width": 160, "height": 90, "folder": ")"
       << folder << R"(" },
  "view": { "panels": ["sphere", "linkage"], "trails": [2] } })";
  return text.str();
}

}  // namespace sl::faults
