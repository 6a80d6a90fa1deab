#pragma once
// PNG files frame_00000.png, frame_00001.png, ... in a folder, each written atomically, encoded on
// worker threads while the caller renders the next frame, and recorded in the folder's manifest
// (frame_manifest.hpp) once renamed into place.

#include <memory>
#include <string>

#include "output/frame_manifest.hpp"
#include "output/frame_sink.hpp"
#include "output/worker_pool.hpp"

namespace sl::output {

// "frame_00042.png" (at least five digits).
std::string frameFileName(int frameIndex);

class PngSequenceSink : public FrameSink {
 public:
  // `manifest` must outlive the sink. Encoding (deflate + SHA-256, ~2x the CPU of rendering a frame)
  // is the critical path, so two encoder threads by default: they use whatever the renderer leaves of
  // two cores (bench_render: 20 against 15 frames/s median on the loaded 2-core machine).
  PngSequenceSink(std::string folder, FrameManifest& manifest, int encoderThreads = 2);
  ~PngSequenceSink() override;

  void consume(int frameIndex, Image image) override;
  void finish() override;

 private:
  std::string folder_;
  FrameManifest& manifest_;
  std::unique_ptr<WorkerPool> workers_;
};

}  // namespace sl::output
