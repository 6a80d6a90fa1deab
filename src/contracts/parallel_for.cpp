#include "contracts/parallel_for.hpp"

#include <algorithm>
#include <cerrno>
#include <system_error>

namespace sl {

namespace {
std::atomic<long> startsLeft{-1};  // -1: no failure injected
}

std::size_t defaultThreadCount() { return std::max(1u, std::thread::hardware_concurrency()); }

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
