// Long and slack chains from the command line: the shipped rope, its CSV without chart columns,
// the note when a start had to move onto the constraints, and the rod limit of the chart methods.
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

TEST(LongChainsCli, TheRopeSimulatesWithoutChartColumnsAndSaysItsPushWasProjected) {
  TempFolder folder;
  const ProcessResult result =
      runLinkage({"simulate", shippedScene("rope.json"), "--dt", "5", "--csv", "rope.csv"}, folder.path());
  ASSERT_EQ(result.code, 0) << result.err;
  EXPECT_NE(result.err.find("note: the start of run \"rope\" (initial) was moved onto the rod constraints"),
            std::string::npos)
      << result.err;
  std::istringstream csv(readFile(folder / "rope.csv"));
  std::string header, first;
  std::getline(csv, header);
  std::getline(csv, first);
  EXPECT_EQ(header.rfind("run,time,energy,p1x,p1y,p2x,p2y,", 0), 0u) << header.substr(0, 80);
  EXPECT_NE(header.find(",p199x,p199y,status"), std::string::npos);
  EXPECT_EQ(first.rfind("rope,0,", 0), 0u);
  const ProcessResult quiet =
      runLinkage({"simulate", shippedScene("rope.json"), "--dt", "5", "--quiet", "--csv", "q.csv"}, folder.path());
  EXPECT_EQ(quiet.err, "");
  // The same rope at full speed through both kinds of output, and the comparison of two runs of it.
  ASSERT_EQ(runLinkage({"simulate", shippedScene("rope.json"), "--dt", "5", "--quiet", "--csv", "again.csv"},
                       folder.path())
                .code,
            0);
  EXPECT_EQ(runLinkage({"diff", "rope.csv", "again.csv"}, folder.path()).code, 0);
}

TEST(LongChainsCli, ChartMethodsKeepTheirLimitAndSlackChainsTheirStartByHinges) {
  TempFolder folder;
  const ProcessResult chart = runLinkage(
      {"validate", shippedScene("rope.json"), "--set", "runs[0].method=christoffel"}, folder.path());
  EXPECT_EQ(chart.code, 2);
  EXPECT_NE(chart.err.find("runs[0].method: found \"christoffel\" for a slack chain"), std::string::npos) << chart.err;
  const ProcessResult sphere = runLinkage(
      {"validate", shippedScene("rope.json"), "--set", "view.panels=[\"sphere\"]"}, folder.path());
  EXPECT_EQ(sphere.code, 2);
  EXPECT_NE(sphere.err.find("has no configuration sphere to draw"), std::string::npos) << sphere.err;
  // Taut again (n-2 < L < n), 200 rods are a sphere S^198, drawn in the ball.
  const ProcessResult taut = runLinkage({"render", shippedScene("rope.json"), "--set", "linkage.L=199.5", "--set",
                                         "view.panels=[\"sphere\", \"linkage\"]", "--size", "320x180", "--frames",
                                         "0:3", "--out", "out", "--quiet"},
                                        folder.path());
  EXPECT_EQ(taut.code, 0) << taut.err;
}

}  // namespace
}  // namespace sl::testing
