// Families and Jacobi fields from the command line: simulate's member and jacobi columns, its
// --events file, diff of such files, and the shipped scenes that show them.
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

TEST(FamiliesCli, SimulateWritesConjugatePointsAsEventsAndTheJacobiColumn) {
  TempFolder folder;
  const ProcessResult result = runLinkage(
      {"simulate", shippedScene("jacobi.json"), "--dt", "0.25", "--csv", "j.csv", "--events", "events.csv"},
      folder.path());
  ASSERT_EQ(result.code, 0) << result.err;
  const std::vector<std::string> csv = lines(readFile(folder / "j.csv"));
  EXPECT_EQ(csv.front(), "run,time,phi,t,phidot,tdot,energy,p1x,p1y,p2x,p2y,p3x,p3y,jacobi,status");
  EXPECT_EQ(csv.size(), 1u + 33u);  // t = 0, 0.25, ..., 8
  const std::vector<std::string> events = lines(readFile(folder / "events.csv"));
  ASSERT_EQ(events.size(), 3u) << readFile(folder / "events.csv");  // the first two conjugate points within 8 s
  EXPECT_EQ(events[0], "run,member,event,time");
  EXPECT_EQ(events[1].rfind("geodesic,0,conjugate-point,3.3435", 0), 0u) << events[1];
  EXPECT_EQ(events[2].rfind("geodesic,0,conjugate-point,6.7917", 0), 0u) << events[2];
}

TEST(FamiliesCli, SimulateWritesAFamilyAsRowGroupsThatDiffComparesMemberByMember) {
  TempFolder folder;
  const std::string scene = shippedScene("fan.json");
  ASSERT_EQ(runLinkage({"simulate", scene, "--dt", "1", "--csv", "a.csv"}, folder.path()).code, 0);
  const std::vector<std::string> csv = lines(readFile(folder / "a.csv"));
  EXPECT_EQ(csv.front().rfind("run,member,time,", 0), 0u);
  EXPECT_EQ(csv.size(), 1u + 33u * 11u);  // the run and its 32 members, t = 0..10
  EXPECT_EQ(csv[1].rfind("fan of 32,0,0,", 0), 0u);
  EXPECT_EQ(csv[1 + 11].rfind("fan of 32,1,0,", 0), 0u);
  EXPECT_EQ(csv.back().rfind("fan of 32,32,10,", 0), 0u);
  ASSERT_EQ(runLinkage({"simulate", scene, "--dt", "1", "--csv", "b.csv", "--set", "runs[0].family.spread=0.8"},
                       folder.path())
                .code,
            0);
  const ProcessResult same = runLinkage({"diff", "a.csv", "a.csv"}, folder.path());
  EXPECT_EQ(same.code, 0) << same.out;
  const ProcessResult changed = runLinkage({"diff", "a.csv", "b.csv"}, folder.path());
  EXPECT_EQ(changed.code, 1);
  EXPECT_NE(changed.out.find("run \"fan of 32\": worst hinge difference 0 "), std::string::npos) << changed.out;
  EXPECT_NE(changed.out.find("run \"fan of 32 [member 1]\": worst hinge difference"), std::string::npos);
}

TEST(FamiliesCli, ValidateNamesTheFamilyAndRefusesJacobiWithAChartMethod) {
  TempFolder folder;
  const ProcessResult ok = runLinkage({"validate", shippedScene("fan.json")}, folder.path());
  EXPECT_EQ(ok.code, 0);
  EXPECT_NE(ok.out.find("fan of 32"), std::string::npos) << ok.out;
  const ProcessResult refused =
      runLinkage({"validate", shippedScene("jacobi.json"), "--set", "runs[0].method=christoffel"}, folder.path());
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.err.find("runs[0].jacobi: needs the ambient method"), std::string::npos) << refused.err;
}

}  // namespace
}  // namespace sl::testing
