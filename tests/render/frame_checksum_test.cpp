// Frame checksum regression against tests/data/frames/reference.json and its PNGs.
// On the GL renderer that made the references (same GL_RENDERER and GL_VERSION) the raw-pixel
// SHA-256 must match exactly; on any other renderer the frames are compared with a tolerance (at most
// 1% of pixels may differ by more than 8 levels in a channel). A failure writes
// <name>_actual.png and <name>_diff.png into the test's working directory.
//
// Regenerate on purpose (after a deliberate change of the look), then review the PNGs and commit:
//   SL_REGENERATE_FRAMES=1 ./test_render --gtest_filter='FrameChecksum.*'

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include <nlohmann/json.hpp>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

#include "output/atomic_file.hpp"
#include "output/png_encoder.hpp"
#include "output/sha256.hpp"
#include "reference_frames.hpp"

namespace sl {
namespace {

const std::string kFolder = std::string(SL_SOURCE_DIR) + "/tests/data/frames";

Image decodePng(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 3);
  Image image;
  if (!data) return image;
  image.width = w;
  image.height = h;
  image.rgb.assign(data, data + std::size_t(w) * h * 3);
  stbi_image_free(data);
  return image;
}

// Fraction of pixels where some channel differs by more than `levels`; writes a diff image.
double differingFraction(const Image& a, const Image& b, int levels, Image& diff) {
  diff = a;
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.rgb.size(); i += 3) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a.rgb[i + c]) - int(b.rgb[i + c])));
    differing += worst > levels;
    const std::uint8_t shade = std::uint8_t(255 - std::min(255, worst * 8));
    diff.rgb[i] = 255, diff.rgb[i + 1] = shade, diff.rgb[i + 2] = shade;
  }
  return double(differing) / double(a.rgb.size() / 3);
}

void regenerate(Renderer& renderer) {
  nlohmann::json reference{
      {"glRenderer", renderer.glRenderer()}, {"glVersion", renderer.glVersion()}, {"frames", nlohmann::json::array()}};
  PngEncoder encoder;
  for (const auto& [name, state] : testing::referenceFrames()) {
    const Image image = renderer.render(state);
    writeFileAtomically(kFolder + "/" + name + ".png", encoder.encode(image));
    reference["frames"].push_back({{"name", name}, {"pixelSha256", sha256Hex(image.rgb)}});
  }
  writeFileAtomically(kFolder + "/reference.json", reference.dump(1) + "\n");
}

TEST(FrameChecksum, ReferenceFramesMatch) {
  Renderer renderer(testing::smallSettings(), testing::kSmallSize);
  if (std::getenv("SL_REGENERATE_FRAMES")) {
    regenerate(renderer);
    GTEST_SKIP() << "regenerated the reference frames in " << kFolder;
  }
  std::ifstream in(kFolder + "/reference.json");
  ASSERT_TRUE(in) << "missing " << kFolder << "/reference.json (see the comment at the top of this test)";
  const nlohmann::json reference = nlohmann::json::parse(in);
  const bool sameRenderer =
      reference.at("glRenderer") == renderer.glRenderer() && reference.at("glVersion") == renderer.glVersion();
  const auto frames = testing::referenceFrames();
  ASSERT_EQ(reference.at("frames").size(), frames.size());
  PngEncoder encoder;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const auto& entry = reference.at("frames")[k];
    ASSERT_EQ(entry.at("name"), frames[k].name);
    const Image image = renderer.render(frames[k].state);
    const Image expected = decodePng(kFolder + "/" + frames[k].name + ".png");
    ASSERT_EQ(expected.rgb.size(), image.rgb.size()) << frames[k].name << ".png unreadable or of another size";
    // The stored PNG is lossless: its pixels must hash to the recorded checksum.
    ASSERT_EQ(sha256Hex(expected.rgb), entry.at("pixelSha256")) << frames[k].name << ".png was edited";
    Image diff;
    const double fraction = differingFraction(image, expected, 8, diff);
    const bool ok = sameRenderer ? sha256Hex(image.rgb) == entry.at("pixelSha256") : fraction <= 0.01;
    if (!ok) {
      writeFileAtomically(frames[k].name + "_actual.png", encoder.encode(image));
      writeFileAtomically(frames[k].name + "_diff.png", encoder.encode(diff));
    }
    EXPECT_TRUE(ok) << frames[k].name << ": " << (sameRenderer ? "raw-pixel SHA-256 differs" : "too many pixels differ")
                    << " (" << 100 * fraction << "% beyond 8 levels); wrote " << frames[k].name << "_diff.png";
  }
}

}  // namespace
}  // namespace sl
