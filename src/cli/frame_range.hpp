#pragma once
// The --frames A:B option: a half-open range of frame numbers, so that shards [0:200) [200:400) ...
// split one animation. "A:" runs to the end, ":B" starts at 0.

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
