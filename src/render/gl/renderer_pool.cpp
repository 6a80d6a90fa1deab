#include "render/renderer_pool.hpp"

#include <cstdlib>
#include <optional>
#include <stdexcept>

#include "contracts/parallel_for.hpp"
#include "render/renderer.hpp"

namespace sl {

// Mesa reads LP_NUM_THREADS once, when the process's first context is made: set before any renderer exists, it
// applies to all of them (set after one, it changes nothing, which costs speed, never bytes).
void rasteriseOnTheDrawingThread() { ::setenv("LP_NUM_THREADS", "0", /*overwrite=*/0); }

RendererPool::RendererPool(const ViewSettings& view, ImageSize size, const std::string& shaderFolder,
                           int renderers) {
  if (renderers > 1) rasteriseOnTheDrawingThread();
  try {
    for (int i = 0; i < std::max(1, renderers); ++i)
      threads_.push_back(startThread([this, view, size, shaderFolder] { run(view, size, shaderFolder); }));
  } catch (...) {
    if (threads_.empty()) throw;  // not even one thread: nothing can be drawn
  }
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return ready_ == static_cast<int>(threads_.size()); });
  if (startError_) {
    stopping_ = true;
    lock.unlock();
    changed_.notify_all();
    for (std::thread& thread : threads_) thread.join();
    std::rethrow_exception(startError_);
  }
}

RendererPool::~RendererPool() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    queue_.clear();
  }
  changed_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

void RendererPool::run(const ViewSettings& view, ImageSize size, const std::string& shaderFolder) {
  std::optional<Renderer> renderer;
  {
    // One at a time: making a context is Mesa's process-wide set-up the first time, and a few milliseconds after.
    static std::mutex making;
    std::lock_guard made(making);
    std::exception_ptr error;
    try {
      renderer.emplace(view, size, shaderFolder);
    } catch (...) {
      error = std::current_exception();
    }
    std::lock_guard lock(mutex_);
    if (error && !startError_) startError_ = error;
    if (renderer && glRenderer_.empty()) glRenderer_ = renderer->glRenderer(), glVersion_ = renderer->glVersion();
    ++ready_;
  }
  changed_.notify_all();
  if (!renderer) return;
  while (true) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
    if (queue_.empty()) return;
    Job job = std::move(queue_.front());
    queue_.pop_front();
    lock.unlock();
    changed_.notify_all();
    try {
      renderer->render(job.frame, job.image);
      job.drawn.set_value(std::move(job.image));
    } catch (...) {
      job.drawn.set_exception(std::current_exception());
    }
  }
}

void RendererPool::submit(FrameState frame, Image buffer) {
  if (inFlight() >= capacity()) throw std::logic_error("RendererPool::submit: take the oldest frame first");
  Job job{std::move(frame), std::move(buffer), {}};
  order_.push_back(job.drawn.get_future());
  {
    std::lock_guard lock(mutex_);
    queue_.push_back(std::move(job));
  }
  changed_.notify_all();
}

Image RendererPool::takeOldest() {
  if (order_.empty()) throw std::logic_error("RendererPool::takeOldest: no frame in flight");
  std::future<Image> oldest = std::move(order_.front());
  order_.pop_front();
  return oldest.get();
}

}  // namespace sl
