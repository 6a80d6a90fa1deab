#include "output/worker_pool.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>

#include "contracts/parallel_for.hpp"

namespace sl {
namespace {

TEST(WorkerPool, ThreadsThatCannotStartLeaveFewerWorkersOrNone) {
  for (long starts : {0L, 1L}) {
    failThreadStartsAfterForTesting(starts);
    std::atomic<int> done{0};
    {
      WorkerPool pool(3, 2);
      for (int k = 0; k < 50; ++k) pool.submit([&] { ++done; });
      pool.wait();
    }
    failThreadStartsAfterForTesting(-1);
    EXPECT_EQ(done.load(), 50) << starts << " threads started";
  }
}

TEST(WorkerPool, AJobsExceptionReachesTheCallerWithOrWithoutThreads) {
  for (long starts : {-1L, 0L}) {
    failThreadStartsAfterForTesting(starts);
    bool thrown = false;
    try {
      WorkerPool pool(2, 2);
      pool.submit([] { throw std::runtime_error("job failed"); });
      for (int k = 0; k < 20; ++k) pool.submit([] {});
      pool.wait();
    } catch (const std::runtime_error&) {
      thrown = true;
    }
    failThreadStartsAfterForTesting(-1);
    EXPECT_TRUE(thrown) << starts;
  }
}

}  // namespace
}  // namespace sl
