#include "render/font_atlas.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>

#define STB_TRUETYPE_IMPLEMENTATION
#define STBTT_STATIC
#include <stb/stb_truetype.h>

namespace sl {
namespace {

// Printable ASCII, Greek (phi, theta, pi, ...), and the symbols labels use: degree, plus-minus, minus (U+2212),
// square root (U+221A), perpendicular (U+22A5), integral (U+222B), superscript digits and minus, subscript zero, the
// ellipsis.
std::vector<int> charset() {
  std::vector<int> codepoints;
  for (int c = 32; c < 127; ++c) codepoints.push_back(c);
  for (int c = 0x391; c <= 0x3C9; ++c) codepoints.push_back(c);
  for (int c : {0xB0,   0xB1,   0xB7,   0xD7,   0x2013, 0x2014, 0x2026, 0x2212, 0x2248, 0x2192, 0x221E, 0x2070, 0x221A,
                0x22A5, 0x222B, 0xB9,   0xB2,   0xB3, 0x2074, 0x2075, 0x2076, 0x2077, 0x2078, 0x2079, 0x207B, 0x2080, 0xFFFD})
    codepoints.push_back(c);
  return codepoints;
}

}  // namespace

struct FontAtlas::Packed {
  stbtt_fontinfo info;
  std::vector<int> codepoints;
  std::vector<stbtt_packedchar> chars[3];
  float heights[3];
  float ascent[3];
  float lineHeight[3];
};

std::string FontAtlas::fitted(const std::string& utf8, TextSize size, float maxWidth) const {
  if (width(utf8, size) <= maxWidth) return utf8;
  const std::string ellipsis = "\u2026";
  std::string cut = utf8;
  while (!cut.empty()) {
    // Drop the last code point (and any trailing spaces), never half of one.
    std::size_t end = cut.size() - 1;
    while (end > 0 && (static_cast<unsigned char>(cut[end]) & 0xC0) == 0x80) --end;
    cut.erase(end);
    while (!cut.empty() && cut.back() == ' ') cut.pop_back();
    if (width(cut + ellipsis, size) > maxWidth) continue;
    // Whole words where the text has any: "K, Gaussian curvature" becomes "K, …", never "K, Gau…".
    const std::size_t space = cut.find_last_of(' ');
    if (space != std::string::npos && cut.size() < utf8.size() && utf8[cut.size()] != ' ') {
      cut.erase(space);
      while (!cut.empty() && (cut.back() == ' ' || cut.back() == ',' || cut.back() == ';' || cut.back() == ':'))
        cut.pop_back();
    }
    return cut + ellipsis;
  }
  return width(ellipsis, size) <= maxWidth ? ellipsis : "";
}

std::vector<std::string> FontAtlas::wrapped(const std::string& utf8, TextSize size, float maxWidth,
                                            std::size_t maxLines) const {
  std::vector<std::string> lines;
  std::istringstream words(utf8);
  for (std::string word; words >> word;) {
    if (!lines.empty() && (lines.size() == maxLines || width(lines.back() + " " + word, size) <= maxWidth))
      lines.back() += " " + word;  // the last allowed line takes the rest, fitted below
    else if (maxLines > 0)
      lines.push_back(word);
  }
  for (std::string& line : lines) line = fitted(line, size, maxWidth);
  return lines;
}

std::vector<std::uint32_t> decodeUtf8(const std::string& text) {
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i < text.size();) {
    const auto byte = static_cast<unsigned char>(text[i]);
    const int extra = byte < 0x80 ? 0 : (byte >> 5) == 6 ? 1 : (byte >> 4) == 14 ? 2 : (byte >> 3) == 30 ? 3 : -1;
    if (extra < 0 || i + extra >= text.size()) {
      out.push_back(0xFFFD);
      ++i;
      continue;
    }
    std::uint32_t cp = extra == 0 ? byte : byte & (0x3F >> extra);
    bool ok = true;
    for (int k = 1; k <= extra; ++k) {
      const auto next = static_cast<unsigned char>(text[i + k]);
      ok = ok && (next & 0xC0) == 0x80;
      cp = (cp << 6) | (next & 0x3F);
    }
    out.push_back(ok ? cp : 0xFFFD);
    i += ok ? extra + 1 : 1;
  }
  return out;
}

namespace {

// stb_truetype trusts the file it is given (a cut-short or zeroed font file crashed the renderer): the table
// directory, the tables the atlas reads and every glyph's place in `glyf` are checked to lie inside the file first.
// Returns what is wrong, or empty.
std::string damageOf(const std::vector<unsigned char>& font) {
  const auto u16 = [&](std::size_t at) { return std::uint32_t(font[at]) << 8 | font[at + 1]; };
  const auto u32 = [&](std::size_t at) { return u16(at) << 16 | u16(at + 2); };
  if (font.size() < 12) return "shorter than a font's header";
  const std::uint32_t version = u32(0);
  if (version != 0x00010000 && version != 0x74727565 /* 'true' */) return "not a TrueType font (no sfnt header)";
  const std::size_t tables = u16(4);
  if (12 + 16 * tables > font.size()) return "its table directory runs past the end of the file";
  std::map<std::string, std::pair<std::size_t, std::size_t>> found;  // tag -> offset, length
  for (std::size_t t = 0; t < tables; ++t) {
    const std::size_t record = 12 + 16 * t;
    const std::size_t offset = u32(record + 8), length = u32(record + 12);
    if (offset > font.size() || length > font.size() - offset)
      return "table " + std::string(font.begin() + long(record), font.begin() + long(record) + 4) +
             " runs past the end of the file (cut short?)";
    found[std::string(font.begin() + long(record), font.begin() + long(record) + 4)] = {offset, length};
  }
  for (const char* tag : {"cmap", "head", "hhea", "hmtx", "loca", "glyf", "maxp"})
    if (!found.count(tag)) return std::string("no ") + tag + " table";
  const auto [head, headLength] = found["head"];
  const auto [maxp, maxpLength] = found["maxp"];
  const auto [loca, locaLength] = found["loca"];
  const std::size_t glyfLength = found["glyf"].second;
  if (headLength < 54 || maxpLength < 6) return "head or maxp table too short";
  const bool longOffsets = u16(head + 50) != 0;
  const std::size_t glyphs = u16(maxp + 4);
  if ((glyphs + 1) * (longOffsets ? 4 : 2) > locaLength) return "its glyph index (loca) is too short";
  for (std::size_t g = 0; g <= glyphs; ++g) {
    const std::size_t at = longOffsets ? u32(loca + 4 * g) : 2 * std::size_t(u16(loca + 2 * g));
    if (at > glyfLength) return "glyph " + std::to_string(g) + " lies past the end of its table";
  }
  return "";
}

}  // namespace

FontAtlas::FontAtlas(const std::string& ttfPath, const std::array<float, 3>& pixelHeights, int baselineGrain)
    : baselineGrain_(float(std::max(1, baselineGrain))), packed_(new Packed) {
  std::ifstream in(ttfPath, std::ios::binary);
  if (!in) {
    delete packed_;
    throw std::runtime_error("cannot read font " + ttfPath + " (install fonts-dejavu-core)");
  }
  fontData_.assign(std::istreambuf_iterator<char>(in), {});
  if (const std::string damage = damageOf(fontData_); !damage.empty()) {
    delete packed_;
    throw std::runtime_error("font " + ttfPath + " is damaged: " + damage +
                             " (reinstall fonts-dejavu-core: apt-get install --reinstall fonts-dejavu-core)");
  }
  if (!stbtt_InitFont(&packed_->info, fontData_.data(), stbtt_GetFontOffsetForIndex(fontData_.data(), 0))) {
    delete packed_;
    throw std::runtime_error("not a TrueType font: " + ttfPath);
  }
  packed_->codepoints = charset();
  int ascent, descent, gap;
  stbtt_GetFontVMetrics(&packed_->info, &ascent, &descent, &gap);
  for (int s = 0; s < 3; ++s) {
    packed_->heights[s] = pixelHeights[s];
    const float scale = stbtt_ScaleForPixelHeight(&packed_->info, pixelHeights[s]);
    packed_->ascent[s] = scale * ascent;
    packed_->lineHeight[s] = scale * (ascent - descent + gap);
  }
  // The atlas grows with the text: 1024 px holds the three sizes up to frames about 1250 px tall; taller
  // frames (up to limits::kMaxImageSide) need up to 8192 px, still below llvmpipe's largest texture.
  for (atlasSize_ = 1024; atlasSize_ <= kMaxAtlasSize; atlasSize_ *= 2)
    if (pack(pixelHeights)) return;
  delete packed_;
  throw std::runtime_error("font atlas of " + std::to_string(kMaxAtlasSize) + " px too small for text of " +
                           std::to_string(pixelHeights[2]) + " px");
}

bool FontAtlas::pack(const std::array<float, 3>& pixelHeights) {
  bitmap_.assign(static_cast<std::size_t>(atlasSize_) * atlasSize_, 0);
  stbtt_pack_context context{};
  stbtt_PackBegin(&context, bitmap_.data(), atlasSize_, atlasSize_, 0, 1, nullptr);
  stbtt_PackSetOversampling(&context, 2, 2);
  bool packed = true;
  for (int s = 0; s < 3 && packed; ++s) {
    packed_->chars[s].assign(packed_->codepoints.size(), stbtt_packedchar{});
    stbtt_pack_range range{};
    range.font_size = pixelHeights[s];
    range.array_of_unicode_codepoints = packed_->codepoints.data();
    range.num_chars = static_cast<int>(packed_->codepoints.size());
    range.chardata_for_range = packed_->chars[s].data();
    packed = stbtt_PackFontRanges(&context, fontData_.data(), 0, &range, 1) != 0;
  }
  stbtt_PackEnd(&context);
  return packed;
}

FontAtlas::~FontAtlas() { delete packed_; }

int FontAtlas::glyphIndex(std::uint32_t codepoint) const {
  const auto& cps = packed_->codepoints;
  auto found = std::find(cps.begin(), cps.end(), static_cast<int>(codepoint));
  if (found == cps.end()) found = std::find(cps.begin(), cps.end(), 0xFFFD);
  return static_cast<int>(found - cps.begin());
}

float FontAtlas::width(const std::string& utf8, TextSize size) const {
  float x = 0, y = 0;
  for (std::uint32_t cp : decodeUtf8(utf8)) {
    stbtt_aligned_quad q;
    stbtt_GetPackedQuad(packed_->chars[int(size)].data(), atlasSize_, atlasSize_, glyphIndex(cp), &x, &y, &q, 0);
  }
  return x;
}

float FontAtlas::ascent(TextSize size) const { return packed_->ascent[int(size)]; }
float FontAtlas::lineHeight(TextSize size) const { return packed_->lineHeight[int(size)]; }

float FontAtlas::draw(ShapeBatch& batch, const std::string& utf8, TextSize size, float x, float y, Rgba color) const {
  // Baselines on pixel rows keep horizontal stems crisp; on rows of the grain, at the same place at every size.
  y = std::round(y / baselineGrain_) * baselineGrain_;
  for (std::uint32_t cp : decodeUtf8(utf8)) {
    stbtt_aligned_quad q;
    stbtt_GetPackedQuad(packed_->chars[int(size)].data(), atlasSize_, atlasSize_, glyphIndex(cp), &x, &y, &q, 0);
    if (q.x1 > q.x0) batch.glyph(q.x0, q.y0, q.x1, q.y1, q.s0, q.t0, q.s1, q.t1, color);
  }
  return x;
}

}  // namespace sl
