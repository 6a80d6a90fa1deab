#include "contracts/parallel_for.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

namespace sl {
namespace {

// Restores normal thread starts however the test ends.
struct ThreadStartFailure {
  explicit ThreadStartFailure(long starts) { failThreadStartsAfterForTesting(starts); }
  ~ThreadStartFailure() { failThreadStartsAfterForTesting(-1); }
};

TEST(ParallelFor, EveryIndexExactlyOnceWhateverTheThreadCount) {
  for (std::size_t threads : {0u, 1u, 2u, 3u, 8u, 64u}) {
    std::vector<int> hits(1000, 0);
    parallelFor(hits.size(), threads, [&](std::size_t i) { ++hits[i]; });
    for (std::size_t i = 0; i < hits.size(); ++i) ASSERT_EQ(hits[i], 1) << "index " << i << ", " << threads << " threads";
  }
  int calls = 0;
  parallelFor(0, 4, [&](std::size_t) { ++calls; });
  EXPECT_EQ(calls, 0);
}

TEST(ParallelFor, AWorkersExceptionReachesTheCaller) {
  for (std::size_t threads : {1u, 2u, 4u}) {
    std::atomic<int> calls{0};
    try {
      parallelFor(200, threads, [&](std::size_t i) {
        ++calls;
        if (i == 57) throw std::runtime_error("item 57 failed");
      });
      FAIL() << "no exception with " << threads << " threads";
    } catch (const std::runtime_error& error) {
      EXPECT_EQ(std::string(error.what()), "item 57 failed");
    }
    EXPECT_GE(calls.load(), 1);
  }
}

TEST(ParallelFor, AThreadThatCannotStartLeavesFewerThreads) {
  for (long starts : {0L, 1L, 2L}) {
    const ThreadStartFailure failure(starts);
    std::vector<int> hits(500, 0);
    parallelFor(hits.size(), 8, [&](std::size_t i) { ++hits[i]; });
    for (std::size_t i = 0; i < hits.size(); ++i) ASSERT_EQ(hits[i], 1) << "index " << i << ", " << starts << " starts";
  }
}

TEST(ParallelFor, AnExceptionWhileThreadsCannotStartStillReachesTheCaller) {
  const ThreadStartFailure failure(1);
  EXPECT_THROW(parallelFor(100, 4, [](std::size_t i) {
                 if (i == 99) throw std::invalid_argument("last item");
               }),
               std::invalid_argument);
}

TEST(ParallelFor, TheSeamFailsStartsLikeTheSystem) {
  const ThreadStartFailure failure(0);
  EXPECT_THROW(startThread([] {}), std::system_error);
}

}  // namespace
}  // namespace sl
