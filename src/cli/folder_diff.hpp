#pragma once
// Comparing two render folders through their manifests (output/frame_manifest.hpp): which frames differ
// by pixel hash, and optionally by how much (fraction of differing pixels, with a diff image).

#include <iosfwd>
#include <map>
#include <optional>
#include <string>

namespace sl {

struct FolderDifference {
  int framesBefore = 0, framesAfter = 0;
  int differing = 0;  // frames whose pixels differ or that only one side has
  std::optional<int> firstDiffering;
  bool matches() const { return differing == 0; }
};

// Frame number -> pixel SHA-256 from DIR/manifest.json; throws std::invalid_argument if unreadable.
std::map<int, std::string> readPixelHashes(const std::string& folder);

FolderDifference compareFolders(const std::map<int, std::string>& before, const std::map<int, std::string>& after);

struct PixelDifference {
  double fraction = 0;    // of pixels with any channel different
  std::string diffImage;  // path written, empty if none
  std::string note;       // why no pixel comparison was possible (different sizes), if so
};

// Decodes DIR/frame_k.png on both sides; writes a diff image (differing pixels red over a faded grey
// copy of the new frame) into imageFolder. Throws std::runtime_error if a frame cannot be read.
PixelDifference comparePixels(const std::string& before, const std::string& after, int frame,
                              const std::string& imageFolder);

}  // namespace sl
