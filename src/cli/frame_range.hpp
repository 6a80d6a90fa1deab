#pragma once
// The --frames option: a half-open range A:B of frame numbers, so that shards [0:200) [200:400) ... split one
// animation ("A:" runs to the end, ":B" starts at 0); or K/N, shard K of N equal contiguous parts (K = 1..N,
// frames floor((K-1) F / N) .. floor(K F / N) - 1 of F), as a job array numbers its tasks. A:B:STEP keeps every
// STEP-th frame from A (0::10: frames 0, 10, 20, ...: golden frames for a regression test, a quick look). A bare
// number K is the one frame K.

#include <string>

namespace sl {

struct FrameRange {
  int first = 0, end = 0;  // frames first..end-1
  int step = 1;            // every step-th of them, from first
  int count() const { return (end - first + step - 1) / step; }
};

// Throws CommandExit(kExitBadInput) naming the option, what was found and the allowed range.
FrameRange parseFrameRange(const std::string& text, int frameCount);

// The --time option: a half-open range A:B of scene seconds, the frames whose time t has A <= t < B ("A:" runs
// through the last frame, ":B" starts at 0), optionally A:B:STEP frames apart as --frames. Throws
// CommandExit(kExitBadInput) naming the option when it is not of that form, outside 0..duration, or holds no frame.
FrameRange parseTimeRange(const std::string& text, double duration, int fps);

// "--size WxH"; throws CommandExit(kExitBadInput) when it is not of that form.
std::pair<int, int> parseImageSize(const std::string& text);

}  // namespace sl
