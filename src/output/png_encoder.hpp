#pragma once
// RGB8 images to PNG bytes, in one of two ways (contracts/registry.hpp, PngCompression):
// - fast (the default): this program's own writer (fast_png.hpp): "up" filter, run-length deflate with a
//   Huffman code per image; about ten times faster than libdeflate level 1 on rendered frames, files somewhat
//   larger (docs/rendering.md has the figures).
// - small: libdeflate level 1 over rows filtered "none", which on rendered frames (large flat areas that deflate
//   matches along the row) was both faster and smaller than "up" (720p: 14.7 ms / 237 kB against
//   22.3 ms / 252 kB at level 1, same loaded machine).
// The same image gives the same bytes in each mode, on every CPU. One encoder per thread (it keeps buffers and,
// for small, the compressor's state).

#include <cstdint>
#include <string>
#include <vector>

#include "contracts/image.hpp"
#include "contracts/registry.hpp"
#include "output/fast_png.hpp"

namespace sl {

class PngEncoder {
 public:
  explicit PngEncoder(PngCompression compression = PngCompression::Fast);
  ~PngEncoder();
  PngEncoder(const PngEncoder&) = delete;
  PngEncoder& operator=(const PngEncoder&) = delete;

  std::vector<std::uint8_t> encode(const Image& image);

  // Names the encoder and its version ("sphere-linkages fast 1", "libdeflate 1.14 level 1"): two files of the
  // same pixels are the same bytes exactly when this is the same. A render's manifest records it.
  static std::string identity(PngCompression compression);

 private:
  PngCompression compression_;
  void* compressor_ = nullptr;  // libdeflate_compressor, for small
  FastPngScratch scratch_;      // for fast
  std::vector<std::uint8_t> filtered_;  // for small; reused between frames
};

}  // namespace sl
