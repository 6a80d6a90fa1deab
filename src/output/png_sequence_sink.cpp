#include "output/png_sequence_sink.hpp"

#include <cstdio>
#include <memory>

#include "output/atomic_file.hpp"
#include "output/png_encoder.hpp"
#include "output/sha256.hpp"

namespace sl {

std::string frameFileName(int frameIndex) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", frameIndex);
  return name;
}

PngSequenceSink::PngSequenceSink(std::string folder, FrameManifest& manifest, int encoderThreads,
                                 PngCompression compression)
    : folder_(std::move(folder)),
      manifest_(manifest),
      compression_(compression),
      workers_(std::make_unique<WorkerPool>(encoderThreads, 2 * encoderThreads + 1)) {}

PngSequenceSink::~PngSequenceSink() {
  workers_.reset();  // lets queued frames finish
}

void PngSequenceSink::consume(int frameIndex, Image image) {
  auto shared = std::make_shared<Image>(std::move(image));
  workers_->submit([this, frameIndex, shared] {
    thread_local PngEncoder fast(PngCompression::Fast), small(PngCompression::Small);
    const std::vector<std::uint8_t> png = (compression_ == PngCompression::Fast ? fast : small).encode(*shared);
    giveBack(*shared);
    const std::string name = frameFileName(frameIndex);
    writeFileAtomically(folder_ + "/" + name, png);
    manifest_.record({frameIndex, name, "", sha256Hex(png)});
  });
}

void PngSequenceSink::finish() {
  workers_->wait();
  manifest_.flush();
}

}  // namespace sl
