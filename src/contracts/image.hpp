#pragma once
// A frame's pixels: what the renderer produces and the frame sinks consume.

#include <cstdint>
#include <mutex>
#include <utility>
#include <vector>

namespace sl {

struct ImageSize {
  int width = 1280, height = 720;
};

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // width*height*3 bytes, rows top-down
};

// Pixel buffers handed back by the sinks done with them, for the render loop's next frames: a fresh buffer per
// frame costs its zero fill and its page faults (2.7 MB at 1280x720, 25 MB at 3840x2160) on the core that
// renders. Thread-safe: sinks give back from their worker threads.
class ImageRecycler {
 public:
  // A buffer given back (its pixels are stale: the renderer overwrites all of them), or an empty image.
  Image take() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (spare_.empty()) return {};
    Image image = std::move(spare_.back());
    spare_.pop_back();
    return image;
  }
  // Keeps at most as many buffers as frames can be in flight (the sinks' queues bound them).
  void give(Image image) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (spare_.size() < kKept) spare_.push_back(std::move(image));
  }

 private:
  static constexpr std::size_t kKept = 8;
  std::mutex mutex_;
  std::vector<Image> spare_;
};

}  // namespace sl
