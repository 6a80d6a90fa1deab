#pragma once
// Anti-aliased text from a TrueType font (DejaVu Sans), rasterised once into a coverage atlas with
// stb_truetype (2x2 oversampled, so glyphs placed at fractional pixels stay sharp) and drawn as
// textured quads of a ShapeBatch. CPU only: the renderer uploads bitmap() as a texture.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "render/shape_batch.hpp"

namespace sl {

enum class TextSize { Small = 0, Normal = 1, Title = 2 };

// The font every frame's text is set in: DejaVu Sans, from Debian's fonts-dejavu-core.
inline constexpr const char* kFramesFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

class FontAtlas {
 public:
  // Pixel heights for Small, Normal, Title. Baselines are put on whole multiples of `baselineGrain` pixels (a whole
  // number: the frame's pixels per 720p pixel, so that text sits at the same place of the picture at 720p and at
  // 4K). Throws std::runtime_error naming the file if the font cannot be read or is damaged (cut short, zeroed).
  FontAtlas(const std::string& ttfPath, const std::array<float, 3>& pixelHeights, int baselineGrain = 1);
  ~FontAtlas();
  FontAtlas(const FontAtlas&) = delete;
  FontAtlas& operator=(const FontAtlas&) = delete;

  float width(const std::string& utf8, TextSize size) const;
  // The text as it fits in maxWidth pixels: whole, or cut at a code point with an ellipsis (U+2026) added;
  // empty if not even the ellipsis fits.
  std::string fitted(const std::string& utf8, TextSize size, float maxWidth) const;
  // The text word-wrapped into lines of at most maxWidth pixels, at most maxLines of them (the last fitted with
  // an ellipsis if the words do not all fit; a word wider than a line is fitted too).
  std::vector<std::string> wrapped(const std::string& utf8, TextSize size, float maxWidth, std::size_t maxLines) const;
  float ascent(TextSize size) const;  // pixels above the baseline
  float lineHeight(TextSize size) const;
  // Draws UTF-8 text with its baseline at y, starting at x; returns the x after the last glyph.
  float draw(ShapeBatch& batch, const std::string& utf8, TextSize size, float x, float y, Rgba color) const;

  int atlasSize() const { return atlasSize_; }
  const std::vector<std::uint8_t>& bitmap() const { return bitmap_; }

 private:
  struct Packed;
  static constexpr int kMaxAtlasSize = 8192;
  int glyphIndex(std::uint32_t codepoint) const;
  bool pack(const std::array<float, 3>& pixelHeights);  // into an atlas of atlasSize_; false if it does not fit
  int atlasSize_ = 1024;
  float baselineGrain_ = 1;
  std::vector<std::uint8_t> bitmap_;
  std::vector<std::uint8_t> fontData_;
  Packed* packed_;
};

// UTF-8 to code points; malformed bytes become U+FFFD.
std::vector<std::uint32_t> decodeUtf8(const std::string& text);

}  // namespace sl
