// `linkage still` (the frame at one time, opaque or transparent) and `linkage contact-sheet`.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <stb_image.h>

#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

struct Picture {
  int width = 0, height = 0, channels = 0;
  std::vector<unsigned char> pixels;
};

// Decoded as stored: RGB or RGBA.
Picture decode(const fs::path& path) {
  Picture picture;
  unsigned char* data = stbi_load(path.c_str(), &picture.width, &picture.height, &picture.channels, 0);
  if (!data) return picture;
  picture.pixels.assign(data, data + size_t(picture.width) * picture.height * picture.channels);
  stbi_image_free(data);
  return picture;
}

TEST(StillCli, AtAFrameTimeItIsThatFrameOfAFullRender) {
  TempFolder folder;
  ASSERT_EQ(runLinkage({"render", shippedScene("comparison.json"), "--size", "320x180", "--frames", "0:61", "--out",
                        "full", "--quiet"},
                       folder.path())
                .code,
            0);
  // Frame 60 at 30 fps is t = 2; frame 45 is t = 1.5.
  for (const auto& [time, frame] : std::vector<std::pair<std::string, std::string>>{{"2", "00060"}, {"1.5", "00045"}}) {
    const ProcessResult still = runLinkage(
        {"still", shippedScene("comparison.json"), "--time", time, "--size", "320x180", "--out", "still.png"},
        folder.path());
    ASSERT_EQ(still.code, 0) << still.err;
    EXPECT_NE(still.err.find("linkage still: \"comparison\" at t = " + time + ", 320x180 -> still.png"),
              std::string::npos)
        << still.err;
    const Picture a = decode(folder.path() / "still.png"), b = decode(folder.path() / ("full/frame_" + frame + ".png"));
    ASSERT_EQ(a.channels, 3);
    EXPECT_EQ(a.width, 320);
    EXPECT_TRUE(a.pixels == b.pixels) << "t = " << time;
  }
  // Between frames: another picture than both neighbours, the time shown being the one asked for.
  const ProcessResult between = runLinkage(
      {"still", shippedScene("comparison.json"), "--time", "1.51", "--size", "320x180", "--out", "between.png"},
      folder.path());
  ASSERT_EQ(between.code, 0) << between.err;
  EXPECT_NE(between.err.find("at t = 1.51,"), std::string::npos) << between.err;
  const Picture c = decode(folder.path() / "between.png");
  EXPECT_FALSE(c.pixels == decode(folder.path() / "full/frame_00045.png").pixels);
  EXPECT_FALSE(c.pixels == decode(folder.path() / "full/frame_00046.png").pixels);
  // Nothing else was written, and bad requests write nothing.
  EXPECT_FALSE(fs::exists(folder.path() / "renders"));
  const ProcessResult late = runLinkage(
      {"still", shippedScene("comparison.json"), "--time", "1000", "--out", "late.png"}, folder.path());
  EXPECT_EQ(late.code, 2);
  EXPECT_NE(late.err.find("--time: found 1000; expected a time from 0 to the duration"), std::string::npos) << late.err;
  EXPECT_EQ(runLinkage({"still", shippedScene("comparison.json"), "--time", "1", "--out", "x.jpg"}, folder.path()).code,
            2);
  EXPECT_FALSE(fs::exists(folder.path() / "late.png"));
  EXPECT_FALSE(fs::exists(folder.path() / "x.jpg"));
}

// A still renders its one frame alone, in a renderer of its own. The render loop's frames of a range with a step,
// and of a --resume that skips complete frames between the ones it draws (one renderer, one history for them all),
// are those stills pixel for pixel.
TEST(StillCli, SteppedAndResumedRenderFramesAreTheStillsOfThoseFrames) {
  TempFolder folder;
  const std::string scene = shippedScene("comparison.json");
  const std::vector<std::string> render{"render", scene, "--size", "320x180", "--frames", "42:70:9", "--out", "stepped",
                                        "--quiet"};
  ASSERT_EQ(runLinkage(render, folder.path()).code, 0);
  for (const char* frame : {"00051", "00069"}) fs::remove(folder.path() / "stepped" / ("frame_" + std::string(frame) + ".png"));
  std::vector<std::string> resume = render;
  resume.push_back("--resume");
  const ProcessResult resumed = runLinkage(resume, folder.path());
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  // Frame k at 30 fps is t = k / 30.
  std::vector<std::vector<unsigned char>> stills;
  for (const auto& [time, frame] :
       std::vector<std::pair<std::string, std::string>>{{"1.4", "00042"}, {"1.7", "00051"}, {"2", "00060"}, {"2.3", "00069"}}) {
    ASSERT_EQ(runLinkage({"still", scene, "--time", time, "--size", "320x180", "--out", "still.png", "--quiet"},
                         folder.path())
                  .code,
              0);
    const Picture still = decode(folder.path() / "still.png"),
                  rendered = decode(folder.path() / "stepped" / ("frame_" + frame + ".png"));
    ASSERT_EQ(rendered.width, 320) << frame;
    EXPECT_TRUE(still.pixels == rendered.pixels) << "frame " << frame;
    stills.push_back(still.pixels);
  }
  EXPECT_FALSE(stills[0] == stills[1]);  // the comparison can fail
  EXPECT_FALSE(fs::exists(folder.path() / "stepped" / "frame_00043.png"));
}

// Transparent: the background is gone (alpha 0 in a corner), the drawing opaque (the sphere's centre), and laid
// back over the scene's background colour it is the opaque still again, to rounding.
TEST(StillCli, TransparentBackgroundComposesBackToTheOpaqueStill) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  ASSERT_EQ(runLinkage({"still", scene, "--time", "5", "--size", "320x180", "--out", "opaque.png", "--quiet"},
                       folder.path())
                .code,
            0);
  ASSERT_EQ(runLinkage({"still", scene, "--time", "5", "--size", "320x180", "--out", "clear.png", "--transparent",
                        "--quiet"},
                       folder.path())
                .code,
            0);
  const Picture opaque = decode(folder.path() / "opaque.png"), clear = decode(folder.path() / "clear.png");
  ASSERT_EQ(clear.channels, 4);
  ASSERT_EQ(clear.width * clear.height, opaque.width * opaque.height);
  const auto alphaAt = [&](int x, int y) { return clear.pixels[(size_t(y) * clear.width + x) * 4 + 3]; };
  EXPECT_EQ(alphaAt(clear.width - 2, clear.height - 2), 0);
  EXPECT_EQ(alphaAt(clear.width / 4, clear.height / 2), 255);  // the sphere panel's middle
  const unsigned char background[3] = {245, 242, 235};          // view.background (0.96, 0.95, 0.92)
  long off = 0, transparent = 0;
  for (size_t p = 0; p < size_t(opaque.width) * opaque.height; ++p) {
    const int alpha = clear.pixels[4 * p + 3];
    transparent += alpha < 255;
    for (int c = 0; c < 3; ++c) {
      const int composed = (clear.pixels[4 * p + c] * alpha + background[c] * (255 - alpha) + 127) / 255;
      off += std::abs(composed - int(opaque.pixels[3 * p + c])) > 2;
    }
  }
  EXPECT_GT(transparent, long(opaque.width) * opaque.height / 4);
  EXPECT_LT(off, 10) << "channels more than 2 levels off";
}

TEST(StillCli, ContactSheetOfARender) {
  TempFolder folder;
  ASSERT_EQ(runLinkage({"render", shippedScene("seam.json"), "--size", "160x90", "--frames", "0::30", "--out", "r",
                        "--quiet"},
                       folder.path())
                .code,
            0);
  const ProcessResult sheet =
      runLinkage({"contact-sheet", "r", "--count", "6", "--columns", "3", "--tile-width", "100", "--out", "sheet.png"},
                 folder.path());
  ASSERT_EQ(sheet.code, 0) << sheet.err;
  EXPECT_NE(sheet.err.find("linkage contact-sheet: 6 of 11 frames of r in 2 x 3 -> sheet.png"), std::string::npos)
      << sheet.err;
  const Picture picture = decode(folder.path() / "sheet.png");
  // 3 tiles of 100 x 56 (90/160 of 100, rounded) with 8-pixel gaps and a 24-pixel label strip under each.
  EXPECT_EQ(picture.width, 8 + 3 * (100 + 8));
  EXPECT_EQ(picture.height, 8 + 2 * (56 + 24 + 8));
  EXPECT_EQ(runLinkage({"contact-sheet", "nowhere", "--out", "s.png"}, folder.path()).code, 2);
  EXPECT_FALSE(fs::exists(folder.path() / "s.png"));
}

}  // namespace
}  // namespace sl::testing
