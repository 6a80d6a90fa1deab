// The trajectory CSV: columns, exact round trip, the stop row, and reader errors that say where.
#include <gtest/gtest.h>

#include <sstream>

#include "simulation/trajectory_csv.hpp"
#include "support.hpp"

namespace sl {
namespace {

TEST(TrajectoryCsv, ColumnsFollowTheChainSize) {
  EXPECT_EQ(trajectoryCsvHeader(4), "run,time,phi,t,phidot,tdot,energy,p1x,p1y,p2x,p2y,p3x,p3y,status");
  EXPECT_EQ(trajectoryCsvHeader(3), "run,time,c1,v1,energy,p1x,p1y,p2x,p2y,status");
  EXPECT_EQ(trajectoryCsvColumns(6).size(), 2u + 8 + 1 + 10 + 1);
}

TEST(TrajectoryCsv, RoundTripsExactlyAndDeterministically) {
  const Chain chain = Chain::uniform(4, 3.0);
  const std::vector<double> times = testing::evenTimes(2.0, 20);
  std::ostringstream first, second;
  {
    Trajectory run(chain, testing::genericStart(chain), testing::config("ambient"));
    writeTrajectoryCsv(first, "generic", run, times);
    Trajectory again(chain, testing::genericStart(chain), testing::config("ambient"));
    writeTrajectoryCsv(second, "generic", again, times);
  }
  EXPECT_EQ(first.str(), second.str());
  std::istringstream in(first.str());
  const TrajectoryCsv csv = readTrajectoryCsv(in, "first.csv");
  ASSERT_EQ(csv.rows.size(), times.size());
  Trajectory run(chain, testing::genericStart(chain), testing::config("ambient"));
  for (size_t i = 0; i < times.size(); ++i) {
    const Sample s = *run.sampleAt(times[i]);
    EXPECT_EQ(csv.rows[i].run, "generic");
    EXPECT_EQ(csv.rows[i].status, "ok");
    EXPECT_EQ(csv.rows[i].values[csv.valueIndex("time")], times[i]);
    EXPECT_EQ(csv.rows[i].values[csv.valueIndex("phi")], s.coords(0));
    EXPECT_EQ(csv.rows[i].values[csv.valueIndex("tdot")], s.rates(1));
    EXPECT_EQ(csv.rows[i].values[csv.valueIndex("p3y")], s.hinges(1, 2));
    EXPECT_EQ(csv.rows[i].values[csv.valueIndex("energy")], s.energy);
  }
}

TEST(TrajectoryCsv, AStoppedRunEndsWithItsReasonAtTheStopTime) {
  const Chain chain = Chain::uniform(4, 3.0);
  RunConfig c = testing::config("ambient");
  c.maxSteps = 5;
  Trajectory run(chain, testing::genericStart(chain), c);
  std::ostringstream out;
  writeTrajectoryCsv(out, "short", run, testing::evenTimes(10.0, 10));
  std::istringstream in(out.str());
  const TrajectoryCsv csv = readTrajectoryCsv(in, "short.csv");
  ASSERT_GE(csv.rows.size(), 2u);
  EXPECT_EQ(csv.rows.back().status, "max-steps");
  EXPECT_EQ(csv.rows.back().values[0], run.stop()->time);
  for (size_t i = 0; i + 1 < csv.rows.size(); ++i) EXPECT_EQ(csv.rows[i].status, "ok");
}

TEST(TrajectoryCsv, ReaderNamesTheLineAndColumnOfAProblem) {
  auto error = [](const std::string& text) {
    std::istringstream in(text);
    try {
      readTrajectoryCsv(in, "bad.csv");
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("").find("bad.csv: empty"), std::string::npos);
  EXPECT_NE(error("time,phi\n").find("bad.csv:1: expected a header"), std::string::npos);
  EXPECT_EQ(error("run,time,c1,v1,energy,p1x,p1y,p2x,p2y,status\na,0,1,2,3,4,5,6,7,ok\na,1,x,2,3,4,5,6,7,ok\n"),
            "bad.csv:3: column 'c1': expected a number, got 'x'");
  EXPECT_NE(error("run,time,c1,v1,energy,p1x,p1y,p2x,p2y,status\na,0,1,2\n").find("bad.csv:2: expected 10 fields"),
            std::string::npos);
}

}  // namespace
}  // namespace sl
