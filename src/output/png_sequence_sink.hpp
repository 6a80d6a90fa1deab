#pragma once
// PNG files frame_00000.png, frame_00001.png, ... in a folder, each written atomically, encoded on
// worker threads while the caller renders the next frame, and recorded in the folder's manifest
// (frame_manifest.hpp) once renamed into place.

#include <memory>
#include <string>

#include "contracts/registry.hpp"
#include "output/frame_manifest.hpp"
#include "output/frame_sink.hpp"
#include "output/worker_pool.hpp"

namespace sl {

// "frame_00042.png" (at least five digits).
std::string frameFileName(int frameIndex);

class PngSequenceSink : public FrameSink {
 public:
  // `manifest` must outlive the sink. Each frame is encoded and its file hashed (SHA-256, the manifest's one hash
  // per PNG frame) on a worker, overlapping with the caller's rendering of the next frame; two workers by default
  // use whatever the renderer leaves of two cores.
  PngSequenceSink(std::string folder, FrameManifest& manifest, int encoderThreads = 2,
                  PngCompression compression = PngCompression::Fast);
  ~PngSequenceSink() override;

  void consume(int frameIndex, Image image) override;
  void finish() override;

 private:
  std::string folder_;
  FrameManifest& manifest_;
  PngCompression compression_;
  std::unique_ptr<WorkerPool> workers_;
};

}  // namespace sl
