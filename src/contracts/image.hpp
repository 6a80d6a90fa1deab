#pragma once
// A frame's pixels: what the renderer produces and the frame sinks consume.

#include <cstdint>
#include <vector>

namespace sl {

struct ImageSize {
  int width = 1280, height = 720;
};

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // width*height*3 bytes, rows top-down
};

}  // namespace sl
