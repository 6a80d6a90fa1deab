#pragma once
// A render whose frames cannot fit in their folder's free space is refused before its first frame is
// written, with the numbers in the message. The size of a frame is measured, not guessed: the first frame
// the render draws is encoded once more and its bytes stand for every frame still to write.

#include <cstdint>
#include <string>

namespace sl {

struct FrameSpaceNeed {
  std::string folder;
  int framesToWrite = 0;             // frames in the range whose file does not exist yet
  int measuredFrame = 0;             // the frame whose encoded size was measured
  std::uintmax_t bytesPerFrame = 0;  // its PNG size
  int width = 0, height = 0;
};

// Throws CommandExit(kExitBadInput) if framesToWrite x bytesPerFrame exceeds the space available to this
// user in `folder`. Frames with longer paths and trails are somewhat larger than the measured one, so a
// render that barely fits may still fill the disk: that is reported when it happens, completed frames kept.
// Each shard checks its own range against the whole free space, so shards started together can overcommit
// it in the same way.
void refuseIfFramesCannotFit(const FrameSpaceNeed& need);

// "248.4 kB", "1.5 GB": decimal units, as df -H prints them.
std::string formatBytes(std::uintmax_t bytes);

}  // namespace sl
