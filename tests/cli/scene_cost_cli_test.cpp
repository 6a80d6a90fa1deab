// Long chains and families at the documented maxima: their set-up is bounded in memory and answers signals.
#include <cstdio>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "support/child_process.hpp"
#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

// AddressSanitizer reserves terabytes of address space: an address-space limit says nothing there.
#if defined(__SANITIZE_ADDRESS__)
#define SKIP_UNDER_ADDRESS_SANITIZER() GTEST_SKIP() << "ulimit -v does not apply under AddressSanitizer"
#else
#define SKIP_UNDER_ADDRESS_SANITIZER() (void)0
#endif

// A 1000-rod chain started by chart coordinates, by a drag, and with a fan of 256 members.
std::string longChainScene(const std::string& initial, const std::string& extra = "", double duration = 2) {
  return R"({"name": "long", "linkage": {"rods": 1000, "L": 998.5}, "initial": )" + initial +
         R"(, "duration": )" + std::to_string(duration) +
         R"(, "runs": [{"name": "r", "method": "ambient")" + extra +
         R"(}], "output": {"fps": 10, "width": 320, "height": 180}, "view": {"panels": ["linkage", "text"]}})";
}

std::string list(int size, double first, double rest) {
  std::string text = "[";
  for (int i = 0; i < size; ++i) {
    char number[32];
    std::snprintf(number, sizeof number, "%g", i == 0 ? first : rest);
    text += (i ? ", " : "") + std::string(number);
  }
  return text + "]";
}

// The set-up of a 1000-rod start by coords, velocity or drag built dense n^3 things: over 5 GB and 100 s. Under
// a 1.5 GB address-space limit each now validates.
TEST(SceneCostCli, LongChainStartsValidateWithinAMemoryLimit) {
  SKIP_UNDER_ADDRESS_SANITIZER();
  TempFolder folder;
  writeFile(folder.path() / "coords.json",
            longChainScene(R"({"coords": )" + list(998, 0.1, 0.1) + R"(, "velocity": )" + list(998, 1, 0) +
                           R"(, "unit_speed": true})"));
  writeFile(folder.path() / "drag.json", longChainScene(R"({"drag": {"point": )" + list(999, 1, 0) +
                                                        R"(, "direction": )" + list(999, 0, 0.5) + "}}"));
  writeFile(folder.path() / "fan.json",
            longChainScene(R"({"drag": {"point": )" + list(999, 1, 0) + R"(, "direction": )" + list(999, 0, 0.5) +
                               "}}",
                           R"(, "family": {"kind": "fan", "count": 256, "spread": 0.1})"));
  for (const char* scene : {"coords.json", "drag.json", "fan.json"}) {
    const ProcessResult result =
        runShell("ulimit -v 1500000; " + shellQuoted(linkageBinary()) + " validate " + scene, folder.path(), 120);
    EXPECT_EQ(result.code, 0) << scene << ": " << result.err;
  }
}

// simulate of a 1000-rod chain with a fan of 256 members answers SIGTERM, also while the family is being set up
// (a signal as soon as the handlers are installed) and while it runs (once the CSV has its header). Nothing is
// timed: the run is hours long, so the exit by the signal is the event.
TEST(SceneCostCli, ALongChainWithAFamilyAnswersSigterm) {
  TempFolder folder;
  writeFile(folder.path() / "fan.json",
            longChainScene(R"({"drag": {"point": )" + list(999, 1, 0) + R"(, "direction": )" + list(999, 0, 0.5) +
                               "}}",
                           R"(, "family": {"kind": "fan", "count": 256, "spread": 0.1})", 1000));
  const std::string running = "; for i in $(seq 600); do [ -s out.txt ] && break; sleep 0.1; done";
  for (const std::string& moment : {std::string(), running}) {
    const ProcessResult result =
        runShell(shellQuoted(linkageBinary()) + " simulate fan.json > out.txt 2> err.txt & pid=$!; " +
                     awaitSignalHandlers() + moment + "; kill -TERM $pid; wait $pid; echo $?",
                 folder.path(), 120);
    EXPECT_EQ(result.out, "130\n") << result.err << readFile(folder.path() / "err.txt");
  }
}

// geometry --grid held every sample and the whole CSV text (4.2 GB at 4096); it writes block by block now: a
// 1024 x 1024 grid (1M samples) fits a 450 MB address-space limit (before: std::bad_alloc), with the same bytes
// on standard output as in the file.
TEST(SceneCostCli, AGeometryGridIsWrittenInBoundedMemory) {
  SKIP_UNDER_ADDRESS_SANITIZER();
  TempFolder folder;
  const std::string geometry = shellQuoted(linkageBinary()) + " geometry " + shellQuoted(sourcePath("scenes/default.json"));
  const ProcessResult result =
      runShell("ulimit -v 450000; " + geometry + " --grid 1024 --csv grid.csv --quiet", folder.path(), 300);
  EXPECT_EQ(result.code, 0) << result.err;
  const ProcessResult small = runShell(geometry + " --grid 40 --csv small.csv --quiet && " + geometry +
                                           " --grid 40 --quiet > printed.csv", folder.path(), 60);
  ASSERT_EQ(small.code, 0) << small.err;
  EXPECT_EQ(readFile(folder.path() / "small.csv"), readFile(folder.path() / "printed.csv"));
  EXPECT_EQ(readFile(folder.path() / "small.csv").substr(0, 6), "phi,t,");
}

}  // namespace
}  // namespace sl::testing
