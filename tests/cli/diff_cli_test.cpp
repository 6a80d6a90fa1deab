// `linkage diff`: 0 when the two sides match, 1 when they differ, 2 when they cannot be compared.
#include <cstdio>
#include <fstream>

#include <gtest/gtest.h>

#include "cli_support.hpp"

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
  std::ofstream(path, std::ios::binary) << text;
}

TEST(DiffCli, TrajectoryCsvs) {
  TempFolder folder;
  const std::string scene = quoted(shippedScene("comparison.json"));
  ASSERT_EQ(runLinkage("simulate " + scene + " --csv a.csv", folder.path()).status, 0);
  ASSERT_EQ(runLinkage("simulate " + scene + " --csv b.csv", folder.path()).status, 0);
  const CommandResult same = runLinkage("diff a.csv b.csv", folder.path());
  EXPECT_EQ(same.status, 0) << same.out << same.err;
  EXPECT_NE(same.out.find("within --tol"), std::string::npos);

  perturb(folder / "b.csv", "embedded (published),1,", 1e-6);
  const CommandResult changed = runLinkage("diff a.csv b.csv --tol 1e-9", folder.path());
  EXPECT_EQ(changed.status, 1);
  EXPECT_NE(
      changed.out.find(
          "run \"embedded (published)\": worst hinge difference 1e-06 at t = 1; first exceeds --tol 1e-09 at t = 1"),
      std::string::npos)
      << changed.out;
  EXPECT_NE(changed.out.find("run \"christoffel (published)\": worst hinge difference 0"), std::string::npos);
  EXPECT_EQ(runLinkage("diff a.csv b.csv --tol 1e-5", folder.path()).status, 0);
  EXPECT_EQ(runLinkage("diff a.csv missing.csv", folder.path()).status, 2);
  std::ofstream(folder / "junk.csv") << "not,a,trajectory\n";
  EXPECT_EQ(runLinkage("diff a.csv junk.csv", folder.path()).status, 2);
}

TEST(DiffCli, RenderFolders) {
  TempFolder folder;
  const std::string options = " --size 160x90 --frames 0:4 --quiet";
  ASSERT_EQ(runLinkage("render " + quoted(shippedScene("seam.json")) + " --out a" + options, folder.path()).status, 0);
  ASSERT_EQ(runLinkage("render " + quoted(shippedScene("seam.json")) + " --out b" + options, folder.path()).status, 0);
  ASSERT_EQ(
      runLinkage("render " + quoted(shippedScene("comparison.json")) + " --out c" + options, folder.path()).status, 0);
  const CommandResult same = runLinkage("diff a b", folder.path());
  EXPECT_EQ(same.status, 0) << same.out << same.err;
  EXPECT_NE(same.out.find("4 frames vs 4; 0 differ"), std::string::npos) << same.out;
  const CommandResult other = runLinkage("diff a c --images --image-dir pictures", folder.path());
  EXPECT_EQ(other.status, 1);
  EXPECT_NE(other.out.find("4 frames vs 4; 4 differ; first differing frame 0"), std::string::npos) << other.out;
  EXPECT_NE(other.out.find("% of pixels differ"), std::string::npos);
  EXPECT_TRUE(fs::exists(folder.path() / "pictures" / "diff_frame_00000.png"));
  ASSERT_EQ(runLinkage("render " + quoted(shippedScene("seam.json")) + " --out d --size 160x90 --frames 0:3 --quiet",
                       folder.path())
                .status,
            0);
  const CommandResult fewer = runLinkage("diff a d", folder.path());
  EXPECT_EQ(fewer.status, 1);
  EXPECT_NE(fewer.out.find("first differing frame 3"), std::string::npos) << fewer.out;
  EXPECT_EQ(runLinkage("diff a nowhere", folder.path()).status, 2);
}

}  // namespace
}  // namespace sl::testing
