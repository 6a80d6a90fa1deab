#pragma once
// Comparing two render folders through their manifests (output/frame_manifest.hpp): which frames differ
// by pixel hash, and optionally by how much (fraction of differing pixels, with a tolerance per channel and
// a diff image), so that frames from another GL renderer can still be held to a tolerance.

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace sl {

struct FolderDifference {
  int framesBefore = 0, framesAfter = 0;
  int differing = 0;  // frames whose pixels differ or that only one side has
  std::optional<int> firstDiffering;
  bool matches() const { return differing == 0; }
};

// Frame number -> pixel SHA-256 from DIR/manifest.json; throws std::invalid_argument if unreadable.
std::map<int, std::string> readPixelHashes(const std::string& folder);

// The GL renderers ("renderer | version") DIR/manifest.json records, in its order; empty if it names none.
std::vector<std::string> readRenderers(const std::string& folder);

FolderDifference compareFolders(const std::map<int, std::string>& before, const std::map<int, std::string>& after);

struct PixelTolerance {
  int levels = 0;               // a pixel differs only when a channel differs by more than this (0..255)
  double maxDifferingPercent = 0;  // a frame matches when at most this percentage of its pixels differ
};

struct PixelDifference {
  double fraction = 0;    // of pixels with a channel differing by more than the tolerance's levels
  int largestLevel = 0;   // the largest channel difference anywhere in the frame (0..255)
  std::string diffImage;  // path written, empty if none
  std::string note;       // why no pixel comparison was possible (different sizes), if so
  bool withinTolerance(const PixelTolerance& tolerance) const {
    return note.empty() && fraction * 100 <= tolerance.maxDifferingPercent;
  }
};

// Decodes DIR/frame_k.png on both sides and counts the pixels differing beyond `levels`; if imageFolder is not
// empty, writes a diff image there (differing pixels red over a faded grey copy of the new frame). Throws
// std::invalid_argument if a frame cannot be read.
PixelDifference comparePixels(const std::string& before, const std::string& after, int frame, int levels,
                              const std::string& imageFolder);

}  // namespace sl
