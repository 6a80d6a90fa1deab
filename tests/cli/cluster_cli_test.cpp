// Sweeps sized for a cluster: `stability --plan N` prints the shard jobs; run as printed, they and
// the merge equal a single sweep byte for byte; a missing shard is named; rerunning one shard replaces only it.
#include <filesystem>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "support/child_process.hpp"
#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

TEST(ClusterCli, APlannedSweepRunAsPrintedEqualsASingleSweep) {
  TempFolder folder;
  const std::vector<std::string> sweep = {"stability", "--kind", "pole", "--grid", "4", "--no-reference",
                                          "--no-charts", "--out", "sharded"};
  std::vector<std::string> plan = sweep;
  plan.insert(plan.end(), {"--plan", "3"});
  const ProcessResult planned = runLinkage(plan, folder.path());
  ASSERT_EQ(planned.code, 0) << planned.err;
  EXPECT_NE(planned.out.find("sbatch --array=1-3 scripts/slurm/stability-array.sbatch --kind pole --grid 4"),
            std::string::npos)
      << planned.out;
  std::istringstream lines(planned.out);
  std::string script;
  int shardCommands = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("linkage stability", 0) != 0 || line.find("--merge") != std::string::npos) continue;
    ++shardCommands;
    script += shellQuoted(linkageBinary()) + line.substr(std::string("linkage").size()) + " --quiet\n";
  }
  EXPECT_EQ(shardCommands, 3);
  // Shard 2 first and alone: the merge names what is missing.
  std::istringstream commands(script);
  std::vector<std::string> each;
  for (std::string line; std::getline(commands, line);) each.push_back(line);
  ASSERT_EQ(each.size(), 3u);
  ASSERT_EQ(runShell(each[1], folder.path()).code, 0);
  std::vector<std::string> merge = sweep;
  merge.push_back("--merge");
  const ProcessResult early = runLinkage(merge, folder.path());
  EXPECT_EQ(early.code, 2);
  EXPECT_NE(early.err.find("stability-pole.shard-1-of-3.csv"), std::string::npos) << early.err;
  EXPECT_NE(early.err.find("stability-pole.shard-3-of-3.csv"), std::string::npos) << early.err;
  EXPECT_EQ(early.err.find("shard-2-of-3"), std::string::npos) << early.err;
  const std::string shard2 = readFile(folder.path() / "sharded" / "stability-pole.shard-2-of-3.csv");
  ASSERT_EQ(runShell(each[0] + " && " + each[2], folder.path()).code, 0);  // the last one merges
  // Rerunning one shard rewrites only its own file, with the same bytes.
  ASSERT_EQ(runShell(each[1], folder.path()).code, 0);
  EXPECT_EQ(readFile(folder.path() / "sharded" / "stability-pole.shard-2-of-3.csv"), shard2);
  std::vector<std::string> single = sweep;
  single.back() = "single";
  single.push_back("--quiet");
  ASSERT_EQ(runLinkage(single, folder.path()).code, 0);
  for (const char* name : {"stability-pole.csv", "stability-pole-summary.csv"})
    EXPECT_EQ(readFile(folder.path() / "sharded" / name), readFile(folder.path() / "single" / name)) << name;
}

}  // namespace
}  // namespace sl::testing
