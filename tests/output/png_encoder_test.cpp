// The PNG encoders against two independent decoders (stb_image and libpng, which also checks every CRC and the
// zlib stream's Adler-32): lossless at odd sizes, for flat, noisy and rendered-like images, in both compression
// modes; the fast writer's portable and AVX2 paths give the same bytes.

#include <gtest/gtest.h>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

#include <png.h>

#include <cstring>
#include <random>
#include <string>
#include <utility>

#include "output/fast_png.hpp"
#include "output/png_encoder.hpp"
#include "output/sha256.hpp"

namespace sl {
namespace {

Image gradientWithNoise(int w, int h) {
  Image image{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 3)};
  std::mt19937 random(7);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      auto* p = &image.rgb[(std::size_t(y) * w + x) * 3];
      p[0] = std::uint8_t(x * 255 / w), p[1] = std::uint8_t(y * 255 / h), p[2] = std::uint8_t(random() & 0xFF);
    }
  return image;
}

Image flat(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  Image image{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 3)};
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) image.rgb[i] = r, image.rgb[i + 1] = g, image.rgb[i + 2] = b;
  return image;
}

Image noise(int w, int h, unsigned seed) {
  Image image{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 3)};
  std::mt19937 random(seed);
  for (auto& byte : image.rgb) byte = std::uint8_t(random());
  return image;
}

// Like a rendered frame: a flat background, filled discs with a soft edge, thin lines, a few noisy patches;
// long runs of every length (and of 258 and more) next to literals.
Image scene(int w, int h) {
  Image image = flat(w, h, 250, 250, 247);
  std::mt19937 random(3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      auto* p = &image.rgb[(std::size_t(y) * w + x) * 3];
      const double dx = x - 0.4 * w, dy = y - 0.5 * h, r = std::sqrt(dx * dx + dy * dy), edge = 0.3 * h;
      if (r < edge + 1) {
        const double cover = std::min(1.0, edge + 1 - r);
        p[0] = std::uint8_t(250 - cover * 180), p[1] = std::uint8_t(250 - cover * 90), p[2] = std::uint8_t(247 - cover * 20);
      }
      if ((x + 2 * y) % 97 == 0) p[0] = p[1] = p[2] = 40;
      if (x > w * 3 / 4 && y < h / 5) p[2] = std::uint8_t(random());
    }
  return image;
}

struct Decoded {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  std::string error;
};

Decoded decodeWithStb(const std::vector<std::uint8_t>& png) {
  Decoded d;
  int channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(png.data(), int(png.size()), &d.width, &d.height, &channels, 3);
  if (!pixels) {
    d.error = stbi_failure_reason();
    return d;
  }
  d.rgb.assign(pixels, pixels + std::size_t(d.width) * d.height * 3);
  stbi_image_free(pixels);
  return d;
}

Decoded decodeWithLibpng(const std::vector<std::uint8_t>& png) {
  Decoded d;
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, png.data(), png.size())) {
    d.error = image.message;
    return d;
  }
  image.format = PNG_FORMAT_RGB;
  d.rgb.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, d.rgb.data(), 0, nullptr)) {
    d.error = image.message;
    png_image_free(&image);
    return d;
  }
  d.width = int(image.width), d.height = int(image.height);
  return d;
}

void expectDecodesTo(const std::vector<std::uint8_t>& png, const Image& image, const std::string& what) {
  for (const auto& [decoder, decoded] : {std::pair{"stb_image", decodeWithStb(png)}, std::pair{"libpng", decodeWithLibpng(png)}}) {
    ASSERT_TRUE(decoded.error.empty()) << what << ": " << decoder << ": " << decoded.error;
    EXPECT_EQ(decoded.width, image.width) << what << ": " << decoder;
    EXPECT_EQ(decoded.height, image.height) << what << ": " << decoder;
    EXPECT_TRUE(decoded.rgb == image.rgb) << what << ": " << decoder << " decodes other pixels";
  }
}

struct Case {
  std::string name;
  Image image;
};

std::vector<Case> cases() {
  std::vector<Case> all;
  for (auto [w, h] : {std::pair{1, 1}, {3, 7}, {37, 23}, {1281, 721}}) {
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    all.push_back({"flat " + size, flat(w, h, 0, 0, 0)});
    all.push_back({"flat grey " + size, flat(w, h, 200, 201, 202)});
    all.push_back({"noise " + size, noise(w, h, unsigned(w * 131 + h))});
    all.push_back({"gradient " + size, gradientWithNoise(w, h)});
    all.push_back({"scene " + size, scene(w, h)});
  }
  return all;
}

TEST(PngEncoder, BothModesDecodeToTheSamePixelsWithTwoDecoders) {
  for (PngCompression compression : {PngCompression::Fast, PngCompression::Small}) {
    PngEncoder encoder(compression);
    for (const Case& c : cases()) expectDecodesTo(encoder.encode(c.image), c.image, c.name);
  }
}

TEST(PngEncoder, FastWritesUpFilteredRowsAndOneIdat) {
  // The layout this writer promises: IHDR, one IDAT, IEND; zlib header 78 01; every row's filter byte 2 (up)
  // when the data is stored (noise: larger under Huffman coding, so stored blocks show the filter bytes).
  const Image image = noise(5, 4, 1);
  const auto png = PngEncoder(PngCompression::Fast).encode(image);
  ASSERT_GT(png.size(), 33u + 12u);
  EXPECT_EQ(std::string(png.begin() + 37, png.begin() + 41), "IDAT");
  EXPECT_EQ(png[41], 0x78);
  EXPECT_EQ(png[42], 0x01);
  EXPECT_EQ(png[43], 0x01) << "a single stored block (final)";
  const std::size_t data = 48, rowBytes = 1 + 5 * 3;
  for (int y = 0; y < 4; ++y) EXPECT_EQ(png[data + y * rowBytes], 2) << "row " << y;
  EXPECT_EQ(std::string(png.end() - 8, png.end() - 4), "IEND");
}

TEST(PngEncoder, FastIsMuchSmallerThanStoredOnFlatAndRenderedImages) {
  PngEncoder encoder(PngCompression::Fast);
  const Image blank = flat(1280, 720, 250, 250, 247), drawn = scene(1280, 720);
  EXPECT_LT(encoder.encode(blank).size(), 8000u);  // 2.7 MB of pixels: runs of 258 at a few bits each
  EXPECT_LT(encoder.encode(drawn).size(), drawn.rgb.size() / 5);
}

TEST(PngEncoder, PortableAndAvx2PathsGiveTheSameBytes) {
  if (!fastPngHasAvx2()) GTEST_SKIP() << "this CPU has no AVX2: only the portable path runs here";
  FastPngScratch a, b;
  for (const Case& c : cases()) {
    const auto simd = encodeFastPng(c.image, a, FastPngPath::automatic);
    const auto portable = encodeFastPng(c.image, b, FastPngPath::portable);
    EXPECT_TRUE(simd == portable) << c.name;
    expectDecodesTo(portable, c.image, c.name + " (portable)");
  }
}

TEST(PngEncoder, TheBandsTheStreamIsCutIntoChangeNoByte) {
  // One row a band puts band ends at every residue of the runs of 258 that cross them (a run that reaches past a
  // band is sent in whole runs of 258 as far as known, its rest later); rows of every width from 1 to 40 pixels.
  FastPngScratch scratch;
  std::vector<Case> all = cases();
  for (int w = 1; w <= 40; ++w) all.push_back({"scene " + std::to_string(w) + "x301", scene(w, 301)});
  // Rows of 259 bytes: each row's run of zeros is 257 bytes long, and the one of row 63 ends where a band's repeat
  // bits end (64 * 259 is a multiple of 64): its end is not known there, and no run of 258 may be sent for it.
  all.push_back({"flat 86x70", flat(86, 70, 9, 9, 9)});
  for (const Case& c : all) {
    const auto whole = encodeFastPng(c.image, scratch, FastPngPath::automatic, std::size_t{1} << 40);
    for (std::size_t band : {std::size_t(1), std::size_t(200), std::size_t(5000), kFastPngBandBytes})
      ASSERT_TRUE(encodeFastPng(c.image, scratch, FastPngPath::automatic, band) == whole) << c.name << ", " << band;
  }
}

TEST(PngEncoder, SameImageSameBytes) {
  for (PngCompression compression : {PngCompression::Fast, PngCompression::Small}) {
    const Image image = scene(64, 40);
    PngEncoder a(compression), b(compression);
    const auto first = a.encode(image);
    a.encode(noise(10, 10, 2));  // reuse of internal buffers must not leak into the next file
    EXPECT_EQ(a.encode(image), first);
    EXPECT_EQ(b.encode(image), first);
  }
}

TEST(PngEncoder, PinnedBytes) {
  // The fast writer's output is part of what shards on different machines agree on: a change to it must be on
  // purpose (a new PngEncoder::identity, so that older folders are not joined).
  const auto png = PngEncoder(PngCompression::Fast).encode(scene(97, 61));
  EXPECT_EQ(sha256Hex(png), "b454327ea8f55b90b134ba33885f9837b393507d3308f2bf56eb3b02b9c7efef") << "size " << png.size();
}

TEST(PngEncoder, PinnedBytesAcrossBands) {
  // Larger images are filtered and deflated in bands of rows: runs that cross bands (a flat frame is one run), rows
  // longer than a band, bands of thousands of one-pixel rows, noise (stored blocks). These are the bytes the writer
  // gave when it filtered the whole frame before deflating it (sphere-linkages fast 1).
  const std::pair<Image, const char*> pinned[] = {
      {scene(1281, 721), "4eb4b20620487ee4980b200ea13b11f0a739a6a6c1c2991e22a4d5c59f0313a0"},
      {flat(1281, 721, 200, 201, 202), "31dc5e044039a083292c74d205e0bb96713445f56f8561487135505fb93c0a29"},
      {gradientWithNoise(1281, 721), "f008986a267ea529b19daaecad71a7cab51de6e7b3b29f990f862f2aca4a95bd"},
      {noise(640, 360, 5), "6ef669e39631f4592feb04bedefb07b3830e7eb906d19aabf2dd08f2e8407c51"},
      {scene(1, 3001), "18e84221e4b03cf165138cda9abc2ee09165e3893c43a9cff5e8385685bdd885"},
      {scene(4001, 9), "71435dd0cc9651dff5bef1c2807af5db3d5cceafdaf0bfd289ef6c831f1d4132"},
      {scene(3840, 2160), "1f829c1b9cbd97e39d83cd7a4e44c60edf0beee6b35f8c151bc8639e8ea06a37"}};
  PngEncoder encoder(PngCompression::Fast);
  for (const auto& [image, digest] : pinned) {
    const auto png = encoder.encode(image);
    EXPECT_EQ(sha256Hex(png), digest) << image.width << "x" << image.height << ", " << png.size() << " bytes";
  }
}

TEST(PngEncoder, RejectsMismatchedBuffer) {
  Image image = gradientWithNoise(8, 8);
  image.rgb.pop_back();
  for (PngCompression compression : {PngCompression::Fast, PngCompression::Small}) {
    PngEncoder encoder(compression);
    EXPECT_THROW(encoder.encode(image), std::invalid_argument);
  }
}

TEST(Sha256, KnownDigests) {
  const std::string abc = "abc";
  EXPECT_EQ(sha256Hex(reinterpret_cast<const std::uint8_t*>(abc.data()), abc.size()),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256Hex(nullptr, 0), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

}  // namespace
}  // namespace sl
