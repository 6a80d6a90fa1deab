#include "cli/folder_diff.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <stdexcept>

#include <stb_image.h>
#include <nlohmann/json.hpp>

#include "output/atomic_file.hpp"
#include "output/png_encoder.hpp"
#include "output/png_sequence_sink.hpp"
#include "output/sha256.hpp"

namespace sl {

std::map<int, std::string> readPixelHashes(const std::string& folder) {
  const std::string path = folder + "/manifest.json";
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot read (is " + folder + " a render folder?)");
  std::map<int, std::string> hashes;
  try {
    const nlohmann::json manifest = nlohmann::json::parse(in);
    for (const auto& entry : manifest.at("frames")) {
      const int frame = entry.at("frame").get<int>();
      hashes[frame] = entry.at("pixelSha256").get<std::string>();
      // The manifest is only as good as the files: each must still be what was rendered.
      const std::string file = entry.value("file", "");
      if (file.empty()) continue;
      const std::string framePath = folder + "/" + file;
      if (!std::filesystem::is_regular_file(framePath))
        throw std::invalid_argument(framePath + ": listed in " + path + " but missing");
      if (output::sha256OfFile(framePath) != entry.value("fileSha256", ""))
        throw std::invalid_argument(framePath + ": does not match its entry in " + path +
                                    " (changed after the render, or written by another one)");
    }
  } catch (const nlohmann::json::exception& error) {
    throw std::invalid_argument(path + ": not a frame manifest: " + error.what());
  }
  return hashes;
}

std::vector<std::string> readRenderers(const std::string& folder) {
  const std::string path = folder + "/manifest.json";
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot read (is " + folder + " a render folder?)");
  std::vector<std::string> renderers;
  try {
    const nlohmann::json manifest = nlohmann::json::parse(in);
    if (manifest.contains("renderers"))
      for (const auto& renderer : manifest.at("renderers")) renderers.push_back(renderer.get<std::string>());
  } catch (const nlohmann::json::exception& error) {
    throw std::invalid_argument(path + ": not a frame manifest: " + error.what());
  }
  return renderers;
}

FolderDifference compareFolders(const std::map<int, std::string>& before, const std::map<int, std::string>& after) {
  FolderDifference result;
  result.framesBefore = static_cast<int>(before.size());
  result.framesAfter = static_cast<int>(after.size());
  std::set<int> frames;
  for (const auto& [frame, hash] : before) frames.insert(frame);
  for (const auto& [frame, hash] : after) frames.insert(frame);
  for (int frame : frames) {
    const auto a = before.find(frame), b = after.find(frame);
    if (a != before.end() && b != after.end() && a->second == b->second) continue;
    ++result.differing;
    if (!result.firstDiffering) result.firstDiffering = frame;
  }
  return result;
}

namespace {

struct DecodedImage {
  int width = 0, height = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> pixels{nullptr, stbi_image_free};
};

DecodedImage decodePng(const std::string& path) {
  DecodedImage image;
  int channels = 0;
  image.pixels.reset(stbi_load(path.c_str(), &image.width, &image.height, &channels, 3));
  if (!image.pixels) throw std::invalid_argument(path + ": cannot decode PNG: " + stbi_failure_reason());
  return image;
}

}  // namespace

PixelDifference comparePixels(const std::string& before, const std::string& after, int frame, int levels,
                              const std::string& imageFolder) {
  const std::string name = output::frameFileName(frame);
  const DecodedImage a = decodePng(before + "/" + name), b = decodePng(after + "/" + name);
  if (a.width != b.width || a.height != b.height)
    return {1.0, 255, "", "the frames are " + std::to_string(a.width) + "x" + std::to_string(a.height) + " and " +
                         std::to_string(b.width) + "x" + std::to_string(b.height)};
  Image diff{a.width, a.height, std::vector<std::uint8_t>(size_t(a.width) * a.height * 3)};
  long differing = 0;
  int largest = 0;
  for (size_t p = 0; p < size_t(a.width) * a.height; ++p) {
    const unsigned char* x = a.pixels.get() + 3 * p;
    const unsigned char* y = b.pixels.get() + 3 * p;
    int channel = 0;
    for (int c = 0; c < 3; ++c) channel = std::max(channel, std::abs(int(x[c]) - int(y[c])));
    largest = std::max(largest, channel);
    const bool same = channel <= levels;
    differing += same ? 0 : 1;
    const auto grey = static_cast<std::uint8_t>(160 + (y[0] + y[1] + y[2]) / 12);  // faded: 160..223
    diff.rgb[3 * p] = same ? grey : 255;
    diff.rgb[3 * p + 1] = same ? grey : 0;
    diff.rgb[3 * p + 2] = same ? grey : 0;
  }
  std::string path;
  if (!imageFolder.empty()) {
    std::filesystem::create_directories(imageFolder);
    path = imageFolder + "/diff_" + name;
    output::writeFileAtomically(path, output::PngEncoder().encode(diff));
  }
  return {differing / double(size_t(a.width) * a.height), largest, path, ""};
}

}  // namespace sl
