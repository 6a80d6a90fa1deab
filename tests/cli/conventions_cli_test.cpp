// Command-line conventions: --version, the summary line every command ends with (also when stderr is a pipe,
// as in a cluster job's log), --quiet meaning errors only.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

TEST(ConventionsCli, VersionNamesVersionCommitCompilerAndGlRenderer) {
  TempFolder folder;
  const ProcessResult version = runLinkage({"--version"}, folder.path());
  ASSERT_EQ(version.code, 0) << version.err;
  EXPECT_EQ(version.out.rfind("linkage 0.", 0), 0u) << version.out;
  EXPECT_NE(version.out.find("(commit "), std::string::npos);
  EXPECT_NE(version.out.find("compiler: "), std::string::npos);
  EXPECT_NE(version.out.find("GL renderer: llvmpipe"), std::string::npos) << version.out;
  EXPECT_EQ(runLinkage({}, folder.path()).code, 2);  // no command: a usage error, not a silent success
}

// stderr is a pipe here: the summary line must still be there, and --quiet must leave nothing.
TEST(ConventionsCli, SummaryLineOnAPipeAndQuietMeansErrorsOnly) {
  TempFolder folder;
  const std::string seam = shippedScene("seam.json");  // its published run stops: a report a quiet run hides
  const std::vector<std::string> render{"render", seam, "--size", "160x90", "--out", "out"};
  std::vector<std::string> shard = render;
  shard.insert(shard.end(), {"--frames", "100:103"});
  const ProcessResult loud = runLinkage(shard, folder.path());
  ASSERT_EQ(loud.code, 0) << loud.err;
  EXPECT_NE(loud.err.find("linkage render: 3 frames of 160x90 -> out/ (PNG + manifest.json) in "), std::string::npos)
      << loud.err;
  EXPECT_NE(loud.err.find("run \"published\" stopped at t = 0: pole-fold-back"), std::string::npos) << loud.err;
  EXPECT_NE(loud.err.find("frames/s); \"exact\" ran to t = 3.4; \"published\" stopped at t = 0 (pole-fold-back)"),
            std::string::npos)
      << loud.err;

  shard.push_back("--quiet");
  const ProcessResult quiet = runLinkage(shard, folder.path());
  ASSERT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  EXPECT_EQ(quiet.out, "");

  const ProcessResult geometry = runLinkage({"geometry", shippedScene("default.json"), "--summary"}, folder.path());
  EXPECT_NE(geometry.err.find("geometry: summary"), std::string::npos) << geometry.err;
}

}  // namespace
}  // namespace sl
