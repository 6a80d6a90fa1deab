#pragma once
// The --frames option: a half-open range A:B of frame numbers, so that shards [0:200) [200:400) ... split one
// animation ("A:" runs to the end, ":B" starts at 0); or K/N, shard K of N equal contiguous parts (K = 1..N,
// frames floor((K-1) F / N) .. floor(K F / N) - 1 of F), as a job array numbers its tasks.

#include <string>

namespace sl {

struct FrameRange {
  int first = 0, end = 0;  // frames first..end-1
};

// Throws CommandExit(kExitBadInput) naming the option, what was found and the allowed range.
FrameRange parseFrameRange(const std::string& text, int frameCount);

// "--size WxH"; throws CommandExit(kExitBadInput) when it is not of that form.
std::pair<int, int> parseImageSize(const std::string& text);

}  // namespace sl
