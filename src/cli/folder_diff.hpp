#pragma once
// Comparing two render folders through their manifests (output/frame_manifest.hpp): which frames differ
// by pixel hash, and optionally by how much (fraction of differing pixels, with a tolerance per channel and
// a diff image), so that frames from another GL renderer can still be held to a tolerance.

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sl {

struct FolderDifference {
  int framesBefore = 0, framesAfter = 0;
  int differing = 0;  // frames whose pixels differ or that only one side has
  std::optional<int> firstDiffering;
  bool matches() const { return differing == 0; }
};

// What DIR/manifest.json says of the folder's frames, each listed file checked against its hash; throws
// std::invalid_argument if the manifest is unreadable or malformed, a frame has no file or a file does not match.
struct FolderFrames {
  std::string folder;
  std::string encoder;                      // the render's PNG encoder (info "png"); empty for format 1
  std::map<int, std::string> files;         // frame -> its file's name in the folder
  std::map<int, std::string> fileHashes;    // frame -> SHA-256 of its file
  std::map<int, std::string> pixelHashes;   // frame -> SHA-256 of its pixels, where the manifest lists it
};
FolderFrames readFolderFrames(const std::string& folder);

// Frame -> a hash that is equal on both sides exactly when the pixels are: the file hashes when both folders were
// written by the same encoder, else pixel hashes (from the manifest, or by decoding the file).
std::pair<std::map<int, std::string>, std::map<int, std::string>> comparableHashes(const FolderFrames& before,
                                                                                   const FolderFrames& after);

// What drew DIR's frames as DIR/manifest.json records it: "renderer | version | cpu ..." and the GL backends, in
// its order; empty where it names none (backends: manifests before 0.5).
struct DrawnBy {
  std::vector<std::string> renderers, backends;
  std::string sceneSha256;  // and from which scene text (with its --set overrides), empty if not recorded
};
DrawnBy readDrawnBy(const std::string& folder);

FolderDifference compareFolders(const std::map<int, std::string>& before, const std::map<int, std::string>& after);

// A diff image is named after its frame's file with this prefix (diff_frame_00012.png); `diff` removes the ones an
// earlier comparison left in its --image-dir.
inline constexpr const char* kDiffImagePrefix = "diff_";

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
