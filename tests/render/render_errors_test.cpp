// Bad settings fail with a clear message, never a crash or a black frame.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>

#include "contracts/limits.hpp"
#include "fixtures/synthetic_frame.hpp"
#include "reference_frames.hpp"

namespace sl {
namespace {

std::string messageOf(const ViewSettings& settings, ImageSize size = testing::kSmallSize,
                      const std::string& shaderFolder = "") {
  try {
    Renderer renderer(settings, size, shaderFolder);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// The shaders are built into the program; a shader folder (the command line's SL_SHADER_DIR) is read instead.
TEST(RenderErrors, MissingShaderFolderIsNamed) {
  const std::string message = messageOf(testing::smallSettings(), testing::kSmallSize, "/nonexistent/shaders");
  EXPECT_NE(message.find("/nonexistent/shaders/"), std::string::npos) << message;
}

TEST(RenderErrors, ShadersNeedNoSourceTree) {
  ::setenv("SL_SHADER_DIR", "/nonexistent/shaders", 1);  // the stages read no environment: only the folder given
  EXPECT_EQ(messageOf(testing::smallSettings()), "");
  ::unsetenv("SL_SHADER_DIR");
}

TEST(RenderErrors, FrameSizeOutOfRange) {
  const ViewSettings settings = testing::smallSettings();
  EXPECT_NE(messageOf(settings, {limits::kMaxImageSide + 1, 100}).find("frame size"), std::string::npos);
  EXPECT_NE(messageOf(settings, {0, 100}).find("frame size"), std::string::npos);
  EXPECT_NE(messageOf(settings, {100, limits::kMinImageSide - 1}).find("frame size"), std::string::npos);
}

TEST(RenderErrors, ReportsTheGlRenderer) {
  Renderer renderer(testing::smallSettings(), testing::kSmallSize);
  EXPECT_FALSE(renderer.glRenderer().empty());
  EXPECT_NE(renderer.glVersion().find("Core"), std::string::npos) << renderer.glVersion();
}

// Non-finite and non-positive plot values, empty runs and a NaN path point render without trouble.
TEST(RenderErrors, HostileFrameContentsStillRender) {
  Renderer renderer(testing::smallSettings(), testing::kSmallSize);
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
