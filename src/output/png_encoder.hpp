#pragma once
// RGB8 images to PNG bytes. libdeflate (level 1) does the compression: on a 720p frame it was the
// fastest encoder measured and gave the smallest files (see docs/rendering.md); the PNG container
// around it is four chunks. One filter for every row: "none" by default, which on rendered frames
// (large flat areas that deflate matches along the row) was both faster and smaller than "up"
// (720p: 14.7 ms / 237 kB against 22.3 ms / 252 kB at level 1, same loaded machine).
// One encoder per thread (the compressor keeps state).

#include <cstdint>
#include <vector>

#include "contracts/image.hpp"

namespace sl::output {

// PNG row filters used here (one for the whole image; PNG specification, section 9).
enum class PngFilter { None = 0, Up = 2 };

class PngEncoder {
 public:
  explicit PngEncoder(int level = 1, PngFilter filter = PngFilter::None);
  ~PngEncoder();
  PngEncoder(const PngEncoder&) = delete;
  PngEncoder& operator=(const PngEncoder&) = delete;

  std::vector<std::uint8_t> encode(const Image& image);

 private:
  void* compressor_;  // libdeflate_compressor
  PngFilter filter_;
  std::vector<std::uint8_t> filtered_;  // reused between frames
};

}  // namespace sl::output
