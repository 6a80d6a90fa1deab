#include "contracts/parallel_for.hpp"

#include <algorithm>
#include <cerrno>
#include <system_error>

#ifdef __linux__
#include <sched.h>
#endif

namespace sl {

namespace {
std::atomic<long> startsLeft{-1};  // -1: no failure injected
}

// The cores this process may run on: a cluster's scheduler (Slurm's --cpus-per-task) or taskset pins a process to
// some of the machine's cores, which std::thread::hardware_concurrency() does not see.
std::size_t defaultThreadCount() {
#ifdef __linux__
  cpu_set_t cores;
  if (::sched_getaffinity(0, sizeof cores, &cores) == 0) return std::max(1, CPU_COUNT(&cores));
#endif
  return std::max(1u, std::thread::hardware_concurrency());
}

std::thread startThread(std::function<void()> work) {
  long left = startsLeft.load();
  while (left >= 0) {
    if (left == 0) throw std::system_error(EAGAIN, std::generic_category(), "cannot start a thread (test)");
    if (startsLeft.compare_exchange_weak(left, left - 1)) break;
  }
  return std::thread(std::move(work));
}

void failThreadStartsAfterForTesting(long starts) { startsLeft = starts < 0 ? -1 : starts; }

}  // namespace sl
