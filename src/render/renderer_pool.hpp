#pragma once
// Several renderers drawing frames side by side, each on its own thread with its own OpenGL context, handing the
// frames back in the order they were given (so a video encoder, which needs them in order, can take them).
//
// Why threads of whole renderers rather than llvmpipe's own rasteriser threads: a frame is mostly serial work on
// the thread that draws it (the panels' draw lists, vertex and triangle set-up in Mesa, the read-back); llvmpipe
// spreads only the rasterisation over its threads, so one renderer leaves a core idle a third of the time. With
// several renderers, llvmpipe is told (LP_NUM_THREADS=0, unless the environment already says) to rasterise on the
// drawing thread itself: its rasteriser threads would only contend with the renderers for the same cores. Frames
// are byte-identical either way (Renderer::render is deterministic, whichever renderer draws a frame).
//
//   RendererPool pool(view, size, shaderFolder, 2);
//   pool.submit(builder.frame(k), buffers.take());   // blocks while pool.capacity() frames are in flight
//   Image image = pool.takeOldest();                  // frame k, once drawn; rethrows what drawing it threw

#include <condition_variable>
#include <deque>
#include <exception>
#include <future>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "contracts/frame_state.hpp"
#include "contracts/image.hpp"
#include "contracts/view_settings.hpp"

namespace sl {

// llvmpipe rasterises on the thread that draws (its own rasteriser threads would contend with other renderers, on
// threads here or in other processes, for the same cores), unless the environment already says how. Call before the
// process makes its first renderer; a pool of several renderers calls it itself.
void rasteriseOnTheDrawingThread();

class RendererPool {
 public:
  // `renderers` threads (at least 1; fewer if threads cannot start, at least one always does). Every renderer is
  // made before the constructor returns; what a Renderer constructor throws (a size out of range, a shader folder
  // without the shaders) is thrown here.
  RendererPool(const ViewSettings& view, ImageSize size, const std::string& shaderFolder, int renderers);
  ~RendererPool();  // frames being drawn are finished and dropped, the others dropped
  RendererPool(const RendererPool&) = delete;
  RendererPool& operator=(const RendererPool&) = delete;

  int renderers() const { return static_cast<int>(threads_.size()); }
  // Frames in flight at most: two per renderer, so a renderer always finds its next frame waiting.
  int capacity() const { return 2 * renderers(); }
  int inFlight() const { return static_cast<int>(order_.size()); }
  std::string glRenderer() const { return glRenderer_; }  // GL_RENDERER of the first renderer
  std::string glVersion() const { return glVersion_; }

  // submit() and takeOldest() are called from one thread (the one that builds the frames).
  // Hands `frame` to the next free renderer, to be drawn into `buffer` (reused where it has the size). With
  // capacity() frames in flight, take the oldest first (std::logic_error otherwise: memory stays bounded).
  void submit(FrameState frame, Image buffer = {});
  // The oldest frame given and not yet taken, waiting until it is drawn; rethrows what drawing it threw.
  // std::logic_error with none in flight.
  Image takeOldest();

 private:
  struct Job {
    FrameState frame;
    Image image;
    std::promise<Image> drawn;
  };
  void run(const ViewSettings& view, ImageSize size, const std::string& shaderFolder);

  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Job> queue_;              // given, not yet picked up by a renderer
  std::deque<std::future<Image>> order_;  // every frame in flight, oldest first
  bool stopping_ = false;
  int ready_ = 0;                      // renderers made, or failed to be made
  std::exception_ptr startError_;      // the first renderer that could not be made
  std::string glRenderer_, glVersion_;
  std::vector<std::thread> threads_;
};

}  // namespace sl
