// The numerical faults as scene files, through the frames stage and the `linkage` binary: no frame is
// built from a non-finite state, no CSV holds a NaN, and a run that stops is reported, not fatal.
#include <cmath>
#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>

#include "cli/scene_input.hpp"
#include "contracts/registry.hpp"
#include "fault_scenes.hpp"
#include "frames/frame_builder.hpp"
#include "scene/scene_loader.hpp"
#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/temp_folder.hpp"

namespace sl {
namespace {

using faults::numericalFaultScenes;
using testing::ProcessResult;
using testing::readFile;
using testing::runLinkage;
using testing::TempFolder;
using testing::writeFile;

bool finite(const Vec2& p) { return std::isfinite(p.x) && std::isfinite(p.y); }
bool finite(const Vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

void expectDrawable(const FrameState& frame) {
  SCOPED_TRACE("frame " + std::to_string(frame.index));
  EXPECT_TRUE(std::isfinite(frame.time));
  for (const RunFrame& run : frame.runs) {
    SCOPED_TRACE(run.name);
    EXPECT_EQ(run.hinges.size(), static_cast<size_t>(frame.rods - 1));
    for (const Vec2& hinge : run.hinges) EXPECT_TRUE(finite(hinge));
    for (const auto& trail : run.trails) {
      for (const Vec2& point : trail) EXPECT_TRUE(finite(point));
    }
    for (const Vec3& point : run.path) EXPECT_TRUE(finite(point));
    for (const double t : run.pathTimes) EXPECT_TRUE(std::isfinite(t));
    EXPECT_TRUE(finite(run.current));
    if (run.stopped) {
      EXPECT_TRUE(std::isfinite(run.stopTime));
      EXPECT_LE(run.stopTime, frame.time);  // stopped at or before this frame (the reason is typed)
    }
  }
  // Plot values may be non-finite (they are skipped when drawn); their times may not.
  for (const PlotFrame& plot : frame.plots) {
    for (const PlotSeries& series : plot.series) {
      for (const double t : series.times) EXPECT_TRUE(std::isfinite(t));
    }
  }
}

// The frames worth building: all of a short animation, a spread of a long one.
std::vector<int> framesToBuild(int count) {
  if (count <= 50) {
    std::vector<int> all(count);
    for (int k = 0; k < count; ++k) all[k] = k;
    return all;
  }
  return {0, 1, 2, 10, 100, 1000, count - 1};
}

TEST(SceneFaults, NoFrameIsBuiltFromANonFiniteState) {
  for (const faults::FaultScene& fault : numericalFaultScenes()) {
    SCOPED_TRACE(fault.name);
    const Scene scene = parseScene(fault.json, fault.name + ".json");
    // The start and runs as the commands set them up.
    const std::vector<InitialState> starts = runStarts(scene);
    FrameBuilder builder(scene, starts, startRuns(scene, starts), startFamilies(scene, starts));
    for (const int k : framesToBuild(builder.frameCount())) expectDrawable(builder.frame(k));
  }
}

// The scenes run every method the program has (on 4 rods; the generic ones on other chains too).
TEST(FaultScenes, RunEveryMethod) {
  for (const MethodTraits& method : kMethods) {
    bool used = false;
    for (const faults::FaultScene& fault : numericalFaultScenes())
      used = used || fault.json.find("\"method\": \"" + std::string(method.name) + "\"") != std::string::npos;
    EXPECT_TRUE(used) << method.name << " is in no fault scene (tests/faults/fault_scenes.cpp)";
  }
}

// Splits a CSV line at commas (the fault scenes' run names hold no commas).
std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> result;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) result.push_back(field);
  return result;
}

TEST(SceneFaults, SimulateWritesNoNonFiniteNumber) {
  TempFolder folder;
  for (const faults::FaultScene& fault : numericalFaultScenes()) {
    SCOPED_TRACE(fault.name);
    writeFile(folder / (fault.name + ".json"), fault.json);
    const ProcessResult simulate =
        runLinkage({"simulate", fault.name + ".json", "--csv", fault.name + ".csv"}, folder.path(), 300);
    ASSERT_EQ(simulate.code, 0) << simulate.err;
    std::stringstream csv(readFile(folder / (fault.name + ".csv")));
    std::string line;
    std::getline(csv, line);
    const size_t columns = fields(line).size();
    int rows = 0;
    while (std::getline(csv, line)) {
      const std::vector<std::string> row = fields(line);
      ASSERT_EQ(row.size(), columns) << line;
      for (size_t i = 1; i + 1 < row.size(); ++i) {
        char* end = nullptr;
        const double value = std::strtod(row[i].c_str(), &end);
        EXPECT_TRUE(*end == '\0' && !row[i].empty() && std::isfinite(value)) << "column " << i << ": " << line;
      }
      ++rows;
    }
    EXPECT_GT(rows, 0);
  }
}

// A short render of each fault scene: every run stopping is a result (exit 0), and frames are written.
TEST(SceneFaults, RenderDrawsStoppedRuns) {
  TempFolder folder;
  for (const faults::FaultScene& fault : numericalFaultScenes()) {
    SCOPED_TRACE(fault.name);
    writeFile(folder / (fault.name + ".json"), fault.json);
    const ProcessResult render = runLinkage(
        {"render", fault.name + ".json", "--quiet", "--frames", "0:3", "--out", fault.name}, folder.path(), 300);
    ASSERT_EQ(render.code, 0) << render.err;
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(std::filesystem::exists(folder.path() / fault.name / ("frame_0000" + std::to_string(k) + ".png")));
    }
  }
}

}  // namespace
}  // namespace sl
