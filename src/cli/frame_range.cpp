#include "cli/frame_range.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "cli/exit_codes.hpp"
#include "contracts/csv_format.hpp"
#include "contracts/time_grid.hpp"

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

FrameRange parseTimeRange(const std::string& text, double duration, int fps) {
  const int frameCount = static_cast<int>(sl::frameCount(duration, fps));
  const std::string allowed = "expected A:B in seconds with 0 <= A < B <= " + shortest(duration) +
                              " (the scene's duration; A: or :B allowed, A:B:STEP every STEP-th frame), holding at "
                              "least one frame at " + std::to_string(fps) + " frames per second";
  const auto refuse = [&] { return CommandExit(kExitBadInput, "--time: found \"" + text + "\"; " + allowed); };
  const size_t colon = text.find(':');
  if (colon == std::string::npos) throw refuse();
  const size_t second = text.find(':', colon + 1);
  const std::string left = text.substr(0, colon);
  const std::string right = text.substr(colon + 1, second == std::string::npos ? std::string::npos : second - colon - 1);
  const auto seconds = [&](const std::string& word, double fallback) {
    if (word.empty()) return fallback;
    double value = NAN;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (error != std::errc() || end != word.data() + word.size() || !std::isfinite(value)) throw refuse();
    return value;
  };
  const double from = seconds(left, 0), to = seconds(right, INFINITY);
  const long step = second == std::string::npos ? 1 : parseCount(text.substr(second + 1));
  if (!(from >= 0 && from < to && (std::isinf(to) || to <= duration * (1 + 1e-12))) || step < 1 || step > frameCount)
    throw refuse();
  // Frame k shows t = k / fps (frameTime): the first at or after A, the last before B.
  const long first = static_cast<long>(std::ceil(from * fps - 1e-9));
  const long end = std::isinf(to) ? frameCount : std::min<long>(frameCount, static_cast<long>(std::ceil(to * fps - 1e-9)));
  if (first >= end) throw refuse();
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
