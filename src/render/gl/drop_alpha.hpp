#pragma once
// RGBA8 pixels to RGB8: the frame is read back as RGBA, which llvmpipe copies row by row, and packed here;
// asking the driver for GL_RGB instead runs its per-pixel format conversion, about 0.9 ms of the rendering core's
// time per 1280x720 frame (docs/rendering.md). Both paths give the same bytes.

#include <cstddef>
#include <cstdint>

namespace sl {

enum class DropAlphaPath {
  automatic,  // SSSE3 where the CPU has it (every x86-64 CPU since about 2008), else portable
  portable
};

void dropAlpha(const std::uint8_t* rgba, std::uint8_t* rgb, std::size_t pixels,
               DropAlphaPath path = DropAlphaPath::automatic);

}  // namespace sl
