// `linkage diff`: 0 when the two sides match, 1 when they differ, 2 when they cannot be compared.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

// Changes one hinge coordinate (p2x) of the row of `run` at `time` by `delta`.
void perturb(const std::string& path, const std::string& rowPrefix, double delta) {
  std::string text = readFile(path);
  const size_t row = text.find("\n" + rowPrefix);
  ASSERT_NE(row, std::string::npos);
  const size_t end = text.find('\n', row + 1);
  std::string line = text.substr(row + 1, end - row - 1);
  std::vector<std::string> fields;
  for (size_t start = 0, comma;; start = comma + 1) {
    comma = line.find(',', start);
    fields.push_back(line.substr(start, comma - start));
    if (comma == std::string::npos) break;
  }
  const size_t p2x = 9;  // run,time,phi,t,phidot,tdot,energy,p1x,p1y,p2x
  char number[32];
  std::snprintf(number, sizeof number, "%.17g", std::stod(fields[p2x]) + delta);
  fields[p2x] = number;
  std::string changed;
  for (const std::string& field : fields) changed.append(changed.empty() ? "" : ",").append(field);
  text.replace(row + 1, line.size(), changed);
  writeFile(path, text);
}

TEST(DiffCli, TrajectoryCsvs) {
  TempFolder folder;
  const std::string scene = shippedScene("comparison.json");
  ASSERT_EQ(runLinkage({"simulate", scene, "--csv", "a.csv"}, folder.path()).code, 0);
  ASSERT_EQ(runLinkage({"simulate", scene, "--csv", "b.csv"}, folder.path()).code, 0);
  const ProcessResult same = runLinkage({"diff", "a.csv", "b.csv"}, folder.path());
  EXPECT_EQ(same.code, 0) << same.out << same.err;
  EXPECT_NE(same.out.find("within --tol"), std::string::npos);

  perturb(folder / "b.csv", "embedded (published),1,", 1e-6);
  const ProcessResult changed = runLinkage({"diff", "a.csv", "b.csv", "--tol", "1e-9"}, folder.path());
  EXPECT_EQ(changed.code, 1);
  EXPECT_NE(
      changed.out.find(
          "run \"embedded (published)\": worst hinge difference 1e-06 at t = 1; first exceeds --tol 1e-09 at t = 1"),
      std::string::npos)
      << changed.out;
  EXPECT_NE(changed.out.find("run \"christoffel (published)\": worst hinge difference 0"), std::string::npos);
  EXPECT_EQ(runLinkage({"diff", "a.csv", "b.csv", "--tol", "1e-5"}, folder.path()).code, 0);
  EXPECT_EQ(runLinkage({"diff", "a.csv", "missing.csv"}, folder.path()).code, 2);
  writeFile(folder / "junk.csv", "not,a,trajectory\n");
  EXPECT_EQ(runLinkage({"diff", "a.csv", "junk.csv"}, folder.path()).code, 2);
}

TEST(DiffCli, RenderFolders) {
  TempFolder folder;
  // A small render of `scene` into `out`: frames 0..frames-1 at 160x90.
  const auto render = [&](const std::string& scene, const std::string& out, const std::string& frames = "0:4") {
    return runLinkage({"render", shippedScene(scene), "--out", out, "--size", "160x90", "--frames", frames, "--quiet"},
                      folder.path());
  };
  ASSERT_EQ(render("seam.json", "a").code, 0);
  ASSERT_EQ(render("seam.json", "b").code, 0);
  ASSERT_EQ(render("comparison.json", "c").code, 0);
  const ProcessResult same = runLinkage({"diff", "a", "b"}, folder.path());
  EXPECT_EQ(same.code, 0) << same.out << same.err;
  EXPECT_NE(same.out.find("4 frames vs 4; 0 differ"), std::string::npos) << same.out;
  const ProcessResult other = runLinkage({"diff", "a", "c", "--images", "--image-dir", "pictures"}, folder.path());
  EXPECT_EQ(other.code, 1);
  EXPECT_NE(other.out.find("4 frames vs 4; 4 differ; first differing frame 0"), std::string::npos) << other.out;
  EXPECT_NE(other.out.find("% of pixels differ"), std::string::npos);
  EXPECT_TRUE(fs::exists(folder.path() / "pictures" / "diff_frame_00000.png"));
  ASSERT_EQ(render("seam.json", "d", "0:3").code, 0);
  const ProcessResult fewer = runLinkage({"diff", "a", "d"}, folder.path());
  EXPECT_EQ(fewer.code, 1);
  EXPECT_NE(fewer.out.find("first differing frame 3"), std::string::npos) << fewer.out;
  EXPECT_EQ(runLinkage({"diff", "a", "nowhere"}, folder.path()).code, 2);
}

}  // namespace
}  // namespace sl::testing
