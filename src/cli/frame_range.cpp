#include "cli/frame_range.hpp"

#include <charconv>

#include "cli/exit_codes.hpp"

namespace sl {

namespace {

// A whole decimal number filling the text, or -1.
long parseCount(const std::string& text) {
  long value = -1;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < 0) return -1;
  return value;
}

}  // namespace

FrameRange parseFrameRange(const std::string& text, int frameCount) {
  const std::string allowed = "expected A:B with 0 <= A < B <= " + std::to_string(frameCount) +
                              " (the scene has frames 0.." + std::to_string(frameCount - 1) +
                              "), A:B:STEP with STEP >= 1, one frame K, or K/N with 1 <= K <= N <= " + std::to_string(frameCount);
  if (const size_t slash = text.find('/'); slash != std::string::npos) {
    const long shard = parseCount(text.substr(0, slash)), shards = parseCount(text.substr(slash + 1));
    if (shard < 1 || shards < shard || shards > frameCount)
      throw CommandExit(kExitBadInput, "--frames: found \"" + text + "\"; " + allowed);
    const auto boundary = [&](long k) { return static_cast<int>(k * static_cast<long>(frameCount) / shards); };
    return {boundary(shard - 1), boundary(shard)};
  }
  const size_t colon = text.find(':');
  if (colon == std::string::npos) {  // one frame K: K:K+1
    const long frame = parseCount(text);
    if (frame < 0 || frame >= frameCount) throw CommandExit(kExitBadInput, "--frames: found \"" + text + "\"; " + allowed);
    return {static_cast<int>(frame), static_cast<int>(frame) + 1};
  }
  const size_t second = text.find(':', colon + 1);
  const std::string left = text.substr(0, colon);
  const std::string right = text.substr(colon + 1, second == std::string::npos ? std::string::npos : second - colon - 1);
  const long step = second == std::string::npos ? 1 : parseCount(text.substr(second + 1));
  if (step < 1 || step > frameCount) throw CommandExit(kExitBadInput, "--frames: found \"" + text + "\"; " + allowed);
  const long first = left.empty() ? 0 : parseCount(left);
  const long end = right.empty() ? frameCount : parseCount(right);
  if (first < 0 || end < 0 || first >= end || end > frameCount) {
    throw CommandExit(kExitBadInput, "--frames: found \"" + text + "\"; " + allowed);
  }
  return {static_cast<int>(first), static_cast<int>(end), static_cast<int>(step)};
}

std::pair<int, int> parseImageSize(const std::string& text) {
  const size_t x = text.find('x');
  const long width = x == std::string::npos ? -1 : parseCount(text.substr(0, x));
  const long height = x == std::string::npos ? -1 : parseCount(text.substr(x + 1));
  if (width < 0 || height < 0 || width > (1 << 30) || height > (1 << 30)) {
    throw CommandExit(kExitBadInput, "--size: found \"" + text + "\"; expected WIDTHxHEIGHT, e.g. 1280x720");
  }
  return {static_cast<int>(width), static_cast<int>(height)};
}

}  // namespace sl
