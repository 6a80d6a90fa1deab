#include "cli/render_folder.hpp"

#include <cctype>
#include <filesystem>

#include "cli/exit_codes.hpp"
#include "output/frame_manifest.hpp"
#include "output/sha256.hpp"
#include "scene/scene_overrides.hpp"

namespace sl {

namespace {

// "-linkage.L=3.2,duration=5" for the overrides that change the picture (not the output's own settings, which
// have their suffixes below); characters a file name should not hold become '_'; a hash when it grows long.
std::string overridesSuffix(const std::vector<std::string>& overrides) {
  std::string text;
  for (std::string override : overrides) {
    if (override.rfind(kUnsetPrefix, 0) == 0) override = "unset-" + override.substr(std::string(kUnsetPrefix).size());
    const std::string key = override.substr(0, override.find('='));
    if (key.rfind("output", 0) == 0 || key.rfind("unset-output", 0) == 0) continue;
    for (char& c : override)
      if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '=' || c == '-' || c == '_' || c == '[' ||
            c == ']'))
        c = '_';
    text += (text.empty() ? "" : ",") + override;
  }
  if (text.empty()) return "";
  constexpr std::size_t kReadableLength = 48;
  if (text.size() > kReadableLength)
    text = "set-" + sha256Hex(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()).substr(0, 12);
  return "-" + text;
}

}  // namespace

std::string renderFolderFor(const Scene& scene, ImageSize ownSize, int ownFps, int step, bool preview,
                            const std::vector<std::string>& overrides) {
  std::string folder = scene.output.folder + overridesSuffix(overrides);
  if (preview) return folder + "-preview";
  const ImageSize size = scene.output.size;
  if (size.width != ownSize.width || size.height != ownSize.height)
    folder += "-" + std::to_string(size.width) + "x" + std::to_string(size.height);
  if (scene.output.fps != ownFps) folder += "-" + std::to_string(scene.output.fps) + "fps";
  if (step > 1) folder += "-every" + std::to_string(step);
  return folder;
}

ImageSize previewSize(ImageSize size) {
  const auto quarter = [](int side) { return std::max(16, side / 4 / 2 * 2); };
  return {quarter(size.width), quarter(size.height)};
}

void refuseJoiningAnotherRender(const std::string& folder, const nlohmann::json& ours) {
  const std::string path = (std::filesystem::path(folder) / "manifest.json").string();
  if (!std::filesystem::exists(path)) return;  // nothing to join yet
  ManifestContents manifest;
  try {
    manifest = readManifestFile(path);
  } catch (const ManifestInvalid&) {
    return;  // the manifest's own checks report it
  }
  // An earlier version's render: FrameManifest says so (it is never joined, whatever its scene).
  if (manifest.format != kCurrentManifestFormat) return;
  const nlohmann::json& theirs = manifest.info;
  const auto text = [](const nlohmann::json& info, const char* key) {
    return info.contains(key) ? info[key].dump() : std::string("none");
  };
  std::string differences;
  const auto differ = [&](const char* key) { return text(theirs, key) != text(ours, key); };
  const auto add = [&](const std::string& what) { differences += (differences.empty() ? "" : "; ") + what; };
  if (differ("scene")) add("the scene: " + text(theirs, "scene") + " there, " + text(ours, "scene") + " here");
  else if (differ("sceneSha256")) add("the scene's text or its --set/--unset overrides");
  if (differ("width") || differ("height"))
    add("the size: " + text(theirs, "width") + "x" + text(theirs, "height") + " there, " + text(ours, "width") + "x" +
        text(ours, "height") + " here");
  if (differ("fps")) add("the frame rate: " + text(theirs, "fps") + " fps there, " + text(ours, "fps") + " here");
  if (differ("frames")) add("the frame count: " + text(theirs, "frames") + " there, " + text(ours, "frames") + " here");
  if (differences.empty()) return;
  throw CommandExit(kExitBadInput,
                    "linkage render: " + folder + " holds another render; what differs: " + differences +
                        ". Shards (--frames) and --resume only join the same render; a whole render (without "
                        "--frames or --resume) replaces it, as does --replace; or use another --out");
}

}  // namespace sl
