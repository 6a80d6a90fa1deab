// Regression checks that survive another machine: `linkage diff` holds frames to a pixel tolerance, names the GL
// renderers, cuts its per-frame lines visibly, reports runs it could not compare without a figure, and the
// recipe of docs/guide.md ("Regression tests in your CI") runs as printed.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <stb_image.h>
#include <nlohmann/json.hpp>

#include "output/png_encoder.hpp"
#include "output/sha256.hpp"
#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

// What another Mesa build does to a render: a few pixels of every frame off by one or two levels in one channel.
// The PNGs are rewritten and the manifest updated to match (pixel and file hashes, the renderer's name), as if
// the folder had been rendered there.
void simulateAnotherRenderer(const fs::path& folder) {
  nlohmann::json manifest = nlohmann::json::parse(readFile(folder / "manifest.json"));
  for (auto& entry : manifest.at("frames")) {
    const fs::path file = folder / entry.at("file").get<std::string>();
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(file.c_str(), &width, &height, &channels, 3);
    ASSERT_NE(pixels, nullptr) << file;
    Image image{width, height, std::vector<std::uint8_t>(pixels, pixels + size_t(width) * height * 3)};
    stbi_image_free(pixels);
    for (int i = 0; i < 20; ++i) {  // 20 pixels spread over the frame, +-1 or +-2 in one channel
      const size_t p = (size_t(i) * 7919 + 13) % (size_t(width) * height);
      const int channel = i % 3, delta = (i % 2 ? 1 : -1) * (1 + (i / 2) % 2);  // half of them by 2 levels
      std::uint8_t& value = image.rgb[3 * p + size_t(channel)];
      value = static_cast<std::uint8_t>(value + delta >= 0 && value + delta <= 255 ? value + delta : value - delta);
    }
    const std::vector<std::uint8_t> png = PngEncoder().encode(image);
    writeFile(file, std::string(png.begin(), png.end()));
    entry["pixelSha256"] = sha256Hex(image.rgb);
    entry["fileSha256"] = sha256Hex(png);
  }
  manifest["renderers"] = {"simulated other renderer | 4.5 (Core Profile) Mesa 99.0"};
  writeFile(folder / "manifest.json", manifest.dump(1));
}

ProcessResult renderSmall(const TempFolder& folder, const std::string& out) {
  return runLinkage({"render", shippedScene("comparison.json"), "--out", out, "--size", "160x90", "--frames", "0:30:10",
                     "--quiet"},
                    folder.path());
}

TEST(RegressionCli, PixelToleranceAcceptsAnotherRendererOnly) {
  TempFolder folder;
  ASSERT_EQ(renderSmall(folder, "golden").code, 0);
  ASSERT_EQ(renderSmall(folder, "here").code, 0);
  const ProcessResult same = runLinkage({"diff", "golden", "here"}, folder.path());
  EXPECT_EQ(same.code, 0) << same.out << same.err;
  EXPECT_EQ(same.err.find("warning"), std::string::npos) << same.err;
  EXPECT_NE(same.out.find("GL renderer: golden: llvmpipe"), std::string::npos) << same.out;

  simulateAnotherRenderer(folder.path() / "here");
  const ProcessResult exact = runLinkage({"diff", "golden", "here"}, folder.path());
  EXPECT_EQ(exact.code, 1) << exact.out << exact.err;
  EXPECT_NE(exact.out.find("3 frames vs 3; 3 differ"), std::string::npos) << exact.out;
  EXPECT_NE(exact.out.find("here: simulated other renderer"), std::string::npos) << exact.out;
  EXPECT_NE(exact.err.find("warning: the two renders name different GL renderers"), std::string::npos) << exact.err;

  const ProcessResult levels = runLinkage({"diff", "golden", "here", "--pixel-tol", "2"}, folder.path());
  EXPECT_EQ(levels.code, 0) << levels.out << levels.err;
  EXPECT_NE(levels.out.find("0 differ beyond --pixel-tol 2 --max-differing 0% (3 by pixel hash)"), std::string::npos)
      << levels.out;
  // One level is not enough: some pixels are two off. A share of differing pixels is, when it covers them.
  EXPECT_EQ(runLinkage({"diff", "golden", "here", "--pixel-tol", "1"}, folder.path()).code, 1);
  // (160x90 frames: 10 of 14400 pixels two levels off is 0.069%, all 20 changed pixels 0.139%.)
  EXPECT_EQ(runLinkage({"diff", "golden", "here", "--pixel-tol", "1", "--max-differing", "0.05"}, folder.path()).code, 1);
  EXPECT_EQ(runLinkage({"diff", "golden", "here", "--pixel-tol", "1", "--max-differing", "0.1"}, folder.path()).code, 0);
  EXPECT_EQ(runLinkage({"diff", "golden", "here", "--max-differing", "0.1"}, folder.path()).code, 1);
  EXPECT_EQ(runLinkage({"diff", "golden", "here", "--max-differing", "0.5"}, folder.path()).code, 0);

  // A real change is not hidden by the tolerance: another scene's frames differ in far more pixels.
  ASSERT_EQ(runLinkage({"render", shippedScene("seam.json"), "--out", "other", "--size", "160x90", "--frames",
                        "0:30:10", "--quiet"},
                       folder.path())
                .code,
            0);
  EXPECT_EQ(runLinkage({"diff", "golden", "other", "--pixel-tol", "2", "--max-differing", "0.5"}, folder.path()).code,
            1);
}

TEST(RegressionCli, PerFrameLinesSayHowManyAreShownAndImagesGoWhereAsked) {
  TempFolder folder;
  ASSERT_EQ(renderSmall(folder, "golden").code, 0);
  ASSERT_EQ(renderSmall(folder, "here").code, 0);
  simulateAnotherRenderer(folder.path() / "here");
  const ProcessResult cut = runLinkage({"diff", "golden", "here", "--images", "--max-images", "2"}, folder.path());
  EXPECT_EQ(cut.code, 1);
  EXPECT_NE(cut.out.find("2 of 3 frames with other pixels shown"), std::string::npos) << cut.out;
  EXPECT_NE(cut.out.find("no diff images written"), std::string::npos) << cut.out;
  EXPECT_EQ(folderContents(folder.path()).count("diff-images"), 0u);
  for (const auto& entry : fs::directory_iterator(folder.path()))  // nothing new in the working folder
    EXPECT_TRUE(entry.path().filename() == "golden" || entry.path().filename() == "here") << entry.path();

  const ProcessResult images =
      runLinkage({"diff", "golden", "here", "--images", "--image-dir", "out/diffs", "--quiet"}, folder.path());
  EXPECT_EQ(images.code, 1);
  EXPECT_EQ(images.err, "");
  EXPECT_NE(images.out.find("frame 10: "), std::string::npos) << images.out;
  EXPECT_TRUE(fs::exists(folder.path() / "out/diffs/diff_frame_00010.png"));
  EXPECT_EQ(images.out.find(" of 3 frames"), std::string::npos) << images.out;  // all shown: no count
}

TEST(RegressionCli, CsvRunsThatCannotBeComparedHaveNoFigure) {
  TempFolder folder;
  const std::string scene = shippedScene("comparison.json");
  ASSERT_EQ(runLinkage({"simulate", scene, "--csv", "a.csv"}, folder.path()).code, 0);
  ASSERT_EQ(runLinkage({"simulate", scene, "--csv", "fine.csv", "--dt", "0.01"}, folder.path()).code, 0);
  // b.csv: a.csv without the run "embedded (published)".
  std::ifstream in(folder.path() / "a.csv");
  std::string line, kept;
  while (std::getline(in, line))
    if (line.rfind("embedded (published),", 0) != 0) kept += line + "\n";
  writeFile(folder.path() / "b.csv", kept);

  const ProcessResult missing = runLinkage({"diff", "a.csv", "b.csv"}, folder.path());
  EXPECT_EQ(missing.code, 1);
  EXPECT_NE(missing.out.find("run \"embedded (published)\": not compared: missing from the second file\n"),
            std::string::npos)
      << missing.out;
  EXPECT_NE(missing.out.find("run \"christoffel (published)\": worst hinge difference 0"), std::string::npos);
  EXPECT_NE(missing.err.find("1 not compared"), std::string::npos) << missing.err;

  const ProcessResult times = runLinkage({"diff", "a.csv", "fine.csv"}, folder.path());
  EXPECT_EQ(times.code, 1);
  EXPECT_EQ(times.out.find("worst"), std::string::npos) << times.out;
  EXPECT_NE(times.out.find("not compared: sample times differ from row 2 of the run on"), std::string::npos)
      << times.out;
}

// The fenced sh block that follows `marker` in docs/guide.md.
std::string guideBlock(const std::string& marker) {
  const std::string guide = readFile(sourcePath("docs/guide.md"));
  const size_t at = guide.find(marker);
  if (at == std::string::npos) return "";
  const size_t start = guide.find("```sh\n", at);
  const size_t end = guide.find("```\n", start + 6);
  return guide.substr(start + 6, end - start - 6);
}

TEST(RegressionCli, GuideRecipeRunsAsPrinted) {
  const std::string golden = guideBlock("<!-- recipe: golden files -->");
  const std::string check = guideBlock("<!-- recipe: the check in CI -->");
  ASSERT_FALSE(golden.empty() || check.empty()) << "docs/guide.md lost its regression recipe";
  TempFolder folder;
  fs::copy_file(shippedScene("default.json"), folder.path() / "my-scene.json");
  const std::string path = "PATH=" + shellQuoted(fs::path(linkageBinary()).parent_path().string()) + ":\"$PATH\"; set -e; ";
  const ProcessResult made = runShell(path + golden, folder.path());
  ASSERT_EQ(made.code, 0) << made.out << made.err;
  const ProcessResult passes = runShell(path + check, folder.path());
  EXPECT_EQ(passes.code, 0) << passes.out << passes.err;

  simulateAnotherRenderer(folder.path() / "golden/frames");  // golden files made on another machine
  const ProcessResult elsewhere = runShell(path + check, folder.path());
  EXPECT_EQ(elsewhere.code, 0) << elsewhere.out << elsewhere.err;

  // A change to the motion fails the check (at its first step, the trajectory), and so do the frames alone.
  std::string scene = readFile(folder.path() / "my-scene.json");
  writeFile(folder.path() / "my-scene.json", scene.replace(scene.find("\"L\": 3.0"), 8, "\"L\": 3.001"));
  const ProcessResult changed = runShell(path + check, folder.path());
  EXPECT_EQ(changed.code, 1) << changed.out << changed.err;
  EXPECT_NE(changed.out.find("first exceeds --tol"), std::string::npos) << changed.out;
  const std::string framesOnly = check.substr(check.find("linkage render"));
  const ProcessResult frames = runShell(path + framesOnly, folder.path());
  EXPECT_EQ(frames.code, 1) << frames.out << frames.err;
}

}  // namespace
}  // namespace sl::testing
