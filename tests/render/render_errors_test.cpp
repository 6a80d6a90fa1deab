// Bad settings fail with a clear message, never a crash or a black frame.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "reference_frames.hpp"
#include "render/synthetic_frame.hpp"

namespace sl {
namespace {

std::string messageOf(const RenderSettings& settings) {
  try {
    Renderer renderer(settings);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(RenderErrors, MissingShaderFolderIsNamed) {
  RenderSettings settings = testing::smallSettings();
  settings.resourceDir = "/nonexistent/resources";
  EXPECT_NE(messageOf(settings).find("/nonexistent/resources/shaders/"), std::string::npos) << messageOf(settings);
}

TEST(RenderErrors, FrameSizeOutOfRange) {
  RenderSettings settings = testing::smallSettings();
  settings.width = Renderer::maxSize() + 1;
  EXPECT_NE(messageOf(settings).find("frame size"), std::string::npos);
  settings.width = 0;
  EXPECT_NE(messageOf(settings).find("frame size"), std::string::npos);
}

TEST(RenderErrors, ReportsTheGlRenderer) {
  Renderer renderer(testing::smallSettings());
  EXPECT_FALSE(renderer.glRenderer().empty());
  EXPECT_NE(renderer.glVersion().find("Core"), std::string::npos) << renderer.glVersion();
}

// Non-finite and non-positive plot values, empty runs and a NaN path point render without trouble.
TEST(RenderErrors, HostileFrameContentsStillRender) {
  Renderer renderer(testing::smallSettings());
  FrameState frame = syntheticFrame(3.0, 180);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (auto& plot : frame.plots)
    for (auto& series : plot.series) {
      series.values[3] = nan;
      series.values[5] = -1;
      series.values[7] = 0;
      series.values[9] = std::numeric_limits<double>::infinity();
    }
  frame.runs[0].path[10] = {nan, 0, 0};
  frame.runs[1].hinges.clear();
  const Image image = renderer.render(frame);
  EXPECT_EQ(image.rgb.size(), std::size_t(testing::kWidth * testing::kHeight * 3));
  frame.runs.clear();
  frame.plots.clear();
  EXPECT_EQ(renderer.render(frame).rgb.size(), image.rgb.size());
}

}  // namespace
}  // namespace sl
