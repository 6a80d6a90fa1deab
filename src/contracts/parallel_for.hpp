#pragma once
// Work spread over threads, for every stage that runs items side by side (a family's members, the rows of a
// curvature grid, the cells of a stability sweep).
//
// parallelFor(count, threads, body) calls body(i) exactly once for every i in [0, count), on the calling
// thread and up to threads - 1 helpers that take the next index as they finish one. Results go where body
// puts them (by index), so the outcome does not depend on the number of threads or on the order.
//
// * A helper that cannot be started (std::thread throws: no memory, no thread left under a limit) is not an
//   error: the items are shared among the threads that did start, down to the calling thread alone.
// * An exception thrown by body stops the hand-out of further items; once every started thread has ended,
//   the first exception is rethrown to the caller. No thread is ever left joinable, so nothing ends in
//   std::terminate.

#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace sl {

// The number of threads meant by "0: as many as the machine has" (at least 1): the cores this process may use.
std::size_t defaultThreadCount();

// Starts a thread running `work`, or throws what std::thread throws. Tests make it fail through
// failThreadStartsAfterForTesting.
std::thread startThread(std::function<void()> work);

// From now on, the first `starts` thread starts succeed and every later one throws std::system_error
// (EAGAIN), as under a process limit; a negative value restores normal starts. For tests only.
void failThreadStartsAfterForTesting(long starts);

template <class Function>
void parallelFor(std::size_t count, std::size_t threads, Function&& body) {
  if (threads == 0) threads = defaultThreadCount();
  if (threads > count) threads = count;
  if (threads <= 1) {
    for (std::size_t i = 0; i < count; ++i) body(i);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr failure;
  std::mutex failureMutex;
  auto work = [&] {
    try {
      for (std::size_t i = next++; i < count && !failed.load(); i = next++) body(i);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(failureMutex);
      if (!failure) failure = std::current_exception();
      failed = true;
    }
  };
  std::vector<std::thread> helpers;
  try {
    helpers.reserve(threads - 1);
    for (std::size_t t = 1; t < threads; ++t) helpers.push_back(startThread(work));
  } catch (...) {
    // Fewer helpers than asked: the ones that started and this thread share the items.
  }
  work();
  for (std::thread& helper : helpers) helper.join();
  if (failure) std::rethrow_exception(failure);
}

// As many threads as the machine has.
template <class Function>
void parallelFor(std::size_t count, Function&& body) {
  parallelFor(count, 0, std::forward<Function>(body));
}

}  // namespace sl
