#pragma once
// RGB8 images to PNG bytes. libdeflate (level 1) does the compression: on a 720p frame it was the
// fastest encoder measured and gave the smallest files (see docs/rendering.md); the PNG container
// around it is four chunks. Every row uses the "up" filter, which suits smooth rendered images.
// One encoder per thread (the compressor keeps state).

#include <cstdint>
#include <vector>

#include "render/renderer.hpp"

namespace sl::output {

class PngEncoder {
 public:
  explicit PngEncoder(int level = 1);
  ~PngEncoder();
  PngEncoder(const PngEncoder&) = delete;
  PngEncoder& operator=(const PngEncoder&) = delete;

  std::vector<std::uint8_t> encode(const Image& image);

 private:
  void* compressor_;                    // libdeflate_compressor
  std::vector<std::uint8_t> filtered_;  // reused between frames
};

}  // namespace sl::output
