// libFuzzer target: any bytes as a scene file. The loader must either accept the scene or throw a
// SceneError with at least one problem; an accepted scene must turn into a finite start of the motion
// (or a clear std::invalid_argument). Anything else — a crash, a sanitizer report, a leak, a hang, an
// escaped exception of another type, a non-finite start — is a finding.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "scene/scene_loader.hpp"
#include "simulation/initial_state.hpp"

namespace {

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "scene_fuzzer: %s\n", what.c_str());
  std::abort();
}

void checkStart(const sl::Scene& scene) {
  try {
    const sl::InitialState start = sl::initialStateFromSpec(scene.chain, scene.initial);
    if (!start.spherePoint.allFinite() || !start.sphereVelocity.allFinite()) {
      finding("an accepted scene gives a non-finite start");
    }
    // What the simulation will refuse (sizes, |x| = 1, x . xdot = 0), the validator must refuse first,
    // naming the JSON path; a bare message from deep inside a run is not enough.
    try {
      sl::validateInitialState(scene.chain, start);
    } catch (const std::invalid_argument& error) {
      finding(std::string("an accepted scene whose start the simulation refuses: ") + error.what());
    }
  } catch (const std::invalid_argument& error) {
    if (std::string(error.what()).empty()) finding("an invalid start without a message");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const sl::Scene scene = sl::parseScene(text, "fuzz.json");
    if (scene.runs.empty()) finding("an accepted scene without runs");
    checkStart(scene);
  } catch (const sl::SceneError& error) {
    if (error.problems().empty()) finding("a SceneError without problems");
  }
  return 0;
}
