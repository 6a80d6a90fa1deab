#pragma once
// A bounded queue drained by worker threads: the producer blocks when `capacity` jobs wait, so a fast
// renderer cannot pile up frames in memory. The first exception a job throws is kept and rethrown by
// submit() or wait(); later jobs are skipped. Threads that cannot start leave fewer workers; with none at
// all, submit() runs each job on the caller's thread.

#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace sl {

class WorkerPool {
 public:
  WorkerPool(int threads, int capacity);
  ~WorkerPool();  // waits; swallows errors (call wait() to see them)
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  void submit(std::function<void()> job);
  void wait();  // all submitted jobs done; rethrows the first error

 private:
  void run();
  void rethrow();
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::function<void()>> jobs_;
  std::size_t capacity_;
  int busy_ = 0;
  bool stopping_ = false;
  std::exception_ptr error_;
  std::vector<std::thread> threads_;
};

}  // namespace sl
