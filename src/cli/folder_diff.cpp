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

FolderFrames readFolderFrames(const std::string& folder) {
  const std::string path = folder + "/manifest.json";
  if (!std::filesystem::exists(path)) throw std::invalid_argument(path + ": cannot read (is " + folder + " a render folder?)");
  const ManifestContents manifest = readManifestFile(path);
  FolderFrames result;
  result.folder = folder;
  if (manifest.format >= 2 && manifest.info.is_object() && manifest.info.contains("png") && manifest.info["png"].is_string())
    result.encoder = manifest.info["png"].get<std::string>();
  for (const auto& [frame, entry] : manifest.frames) {
    if (entry.file.empty())
      throw std::invalid_argument(path + ": frame " + std::to_string(frame) +
                                  " is listed without its file (not written whole); render it again with --resume");
    // The manifest is only as good as the files: each must still be what was rendered.
    const std::string framePath = folder + "/" + entry.file;
    if (!std::filesystem::is_regular_file(framePath))
      throw std::invalid_argument(framePath + ": listed in " + path + " but missing");
    if (sha256OfFile(framePath) != entry.fileSha256)
      throw std::invalid_argument(framePath + ": does not match its entry in " + path +
                                  " (changed after the render, or written by another one)");
    result.fileHashes[frame] = entry.fileSha256;
    result.files[frame] = entry.file;
    if (!entry.pixelSha256.empty()) result.pixelHashes[frame] = entry.pixelSha256;
  }
  return result;
}

DrawnBy readDrawnBy(const std::string& folder) {
  const std::string path = folder + "/manifest.json";
  if (!std::filesystem::exists(path)) throw std::invalid_argument(path + ": cannot read (is " + folder + " a render folder?)");
  ManifestContents contents = readManifestFile(path);
  const auto scene = contents.info.find("sceneSha256");
  return {std::move(contents.renderers), std::move(contents.backends),
          scene != contents.info.end() && scene->is_string() ? scene->get<std::string>() : std::string()};
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

std::map<int, std::string> pixelHashesOf(const FolderFrames& side) {
  std::map<int, std::string> hashes;
  for (const auto& [frame, fileHash] : side.fileHashes) {
    if (const auto known = side.pixelHashes.find(frame); known != side.pixelHashes.end()) {
      hashes[frame] = known->second;
      continue;
    }
    const DecodedImage image = decodePng(side.folder + "/" + side.files.at(frame));
    const std::size_t bytes = std::size_t(image.width) * image.height * 3;
    hashes[frame] = sha256Hex(image.pixels.get(), bytes);
  }
  return hashes;
}

}  // namespace

std::pair<std::map<int, std::string>, std::map<int, std::string>> comparableHashes(const FolderFrames& before,
                                                                                   const FolderFrames& after) {
  if (!before.encoder.empty() && before.encoder == after.encoder) return {before.fileHashes, after.fileHashes};
  return {pixelHashesOf(before), pixelHashesOf(after)};
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


PixelDifference comparePixels(const std::string& before, const std::string& after, int frame, int levels,
                              const std::string& imageFolder) {
  const std::string name = frameFileName(frame);
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
    path = imageFolder + "/" + kDiffImagePrefix + name;
    writeFileAtomically(path, PngEncoder().encode(diff));
  }
  return {differing / double(size_t(a.width) * a.height), largest, path, ""};
}

}  // namespace sl
