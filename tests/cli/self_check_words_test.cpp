// A list of found results with some unconfirmed: each is named in a warning, the summary counts them, and a list
// with none confirmed ends the command with exit 3 (cli/self_check_words.hpp).
#include <gtest/gtest.h>

#include "cli/exit_codes.hpp"
#include "cli/self_check_words.hpp"

namespace sl {
namespace {

TEST(SelfCheckWords, UnconfirmedResultsAreWarnedOfAndAListOfNoneConfirmedFails) {
  testing::internal::CaptureStderr();
  EXPECT_EQ(reportUnconfirmed("periodic", "closed geodesic",
                              {SelfCheck::confirmed, SelfCheck::routesDisagree, SelfCheck::confirmed}, false),
            " (1 unconfirmed)");
  const std::string warned = testing::internal::GetCapturedStderr();
  EXPECT_NE(warned.find("linkage periodic: warning: closed geodesic 1 is unconfirmed: its independent route's length "
                        "differs by more than 1e-08"),
            std::string::npos)
      << warned;
  EXPECT_EQ(reportUnconfirmed("connect", "geodesic", {SelfCheck::confirmed}, false), "");
  EXPECT_EQ(reportUnconfirmed("connect", "geodesic", {}, false), "");  // nothing found is not a failed check
  testing::internal::CaptureStderr();
  try {
    reportUnconfirmed("connect", "geodesic", {SelfCheck::missedTarget, SelfCheck::notFinite}, true);
    ADD_FAILURE() << "a list with none confirmed did not fail";
  } catch (const CommandExit& exit) {
    EXPECT_EQ(exit.code(), kExitFailure);
    EXPECT_NE(std::string(exit.what()).find("no geodesic passed its own check (2 found, all unconfirmed)"),
              std::string::npos)
        << exit.what();
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "") << "--quiet leaves only errors";
  for (SelfCheck check : {SelfCheck::confirmed, SelfCheck::notFinite, SelfCheck::openClosure, SelfCheck::missedTarget,
                          SelfCheck::routesDisagree, SelfCheck::radiiDisagree}) {
    EXPECT_NE(selfCheckName(check), "unknown");
    EXPECT_NE(selfCheckReason(check), "unknown check");
  }
}

}  // namespace
}  // namespace sl
