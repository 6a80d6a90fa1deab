// The PNG encoder against an independent decoder (stb_image): lossless for every filter, and the
// container is well formed (signature, chunk CRCs checked by the decoder).

#include <gtest/gtest.h>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

#include <random>

#include "output/png_encoder.hpp"
#include "output/sha256.hpp"

namespace sl::output {
namespace {

Image testImage(int w, int h) {
  Image image{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 3)};
  std::mt19937 random(7);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      auto* p = &image.rgb[(std::size_t(y) * w + x) * 3];
      p[0] = std::uint8_t(x * 255 / w), p[1] = std::uint8_t(y * 255 / h), p[2] = std::uint8_t(random() & 0xFF);
    }
  return image;
}

TEST(PngEncoder, RoundTripsThroughAnIndependentDecoder) {
  for (PngFilter filter : {PngFilter::None, PngFilter::Up})
    for (int level : {1, 6}) {
      const Image image = testImage(37, 23);  // odd sizes: no alignment luck
      PngEncoder encoder(level, filter);
      const auto png = encoder.encode(image);
      int w = 0, h = 0, channels = 0;
      stbi_uc* decoded = stbi_load_from_memory(png.data(), int(png.size()), &w, &h, &channels, 3);
      ASSERT_NE(decoded, nullptr) << stbi_failure_reason();
      EXPECT_EQ(w, 37);
      EXPECT_EQ(h, 23);
      EXPECT_EQ(channels, 3);
      EXPECT_TRUE(std::equal(image.rgb.begin(), image.rgb.end(), decoded));
      stbi_image_free(decoded);
    }
}

TEST(PngEncoder, SameImageSameBytes) {
  const Image image = testImage(64, 40);
  PngEncoder a, b;
  const auto first = a.encode(image);
  a.encode(testImage(10, 10));  // reuse of internal buffers must not leak into the next file
  EXPECT_EQ(a.encode(image), first);
  EXPECT_EQ(b.encode(image), first);
}

TEST(PngEncoder, RejectsMismatchedBuffer) {
  Image image = testImage(8, 8);
  image.rgb.pop_back();
  PngEncoder encoder;
  EXPECT_THROW(encoder.encode(image), std::invalid_argument);
}

TEST(Sha256, KnownAnswers) {  // FIPS 180-2 test vectors
  const std::string abc = "abc";
  EXPECT_EQ(sha256Hex(reinterpret_cast<const std::uint8_t*>(abc.data()), abc.size()),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256Hex(nullptr, 0), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

}  // namespace
}  // namespace sl::output
