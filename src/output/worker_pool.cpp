#include "output/worker_pool.hpp"

#include <algorithm>

#include "contracts/parallel_for.hpp"

namespace sl {

WorkerPool::WorkerPool(int threads, int capacity) : capacity_(static_cast<std::size_t>(std::max(1, capacity))) {
  // A thread that cannot start (a process limit, no memory) leaves fewer workers; with none, submit() runs
  // each job itself.
  try {
    for (int i = 0; i < std::max(1, threads); ++i) threads_.push_back(startThread([this] { run(); }));
  } catch (...) {
  }
}

WorkerPool::~WorkerPool() {
  {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return jobs_.empty() && busy_ == 0; });
    stopping_ = true;
  }
  changed_.notify_all();
  for (auto& t : threads_) t.join();
}

void WorkerPool::rethrow() {
  if (error_) std::rethrow_exception(error_);
}

void WorkerPool::submit(std::function<void()> job) {
  std::unique_lock lock(mutex_);
  if (threads_.empty()) {
    rethrow();
    lock.unlock();
    try {
      job();
    } catch (...) {
      lock.lock();
      error_ = std::current_exception();
      rethrow();
    }
    return;
  }
  changed_.wait(lock, [&] { return jobs_.size() < capacity_ || error_; });
  rethrow();
  jobs_.push_back(std::move(job));
  changed_.notify_all();
}

void WorkerPool::wait() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return jobs_.empty() && busy_ == 0; });
  rethrow();
}

void WorkerPool::run() {
  std::unique_lock lock(mutex_);
  while (true) {
    changed_.wait(lock, [&] { return stopping_ || !jobs_.empty(); });
    if (jobs_.empty()) return;
    auto job = std::move(jobs_.front());
    jobs_.pop_front();
    ++busy_;
    const bool skip = static_cast<bool>(error_);
    lock.unlock();
    std::exception_ptr failure;
    if (!skip) {
      try {
        job();
      } catch (...) {
        failure = std::current_exception();
      }
    }
    lock.lock();
    if (failure && !error_) error_ = failure;
    --busy_;
    changed_.notify_all();
  }
}

}  // namespace sl
