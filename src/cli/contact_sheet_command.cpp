// `linkage contact-sheet FOLDER --out FILE.png`: evenly spaced frames of a render in one picture, a grid of
// small copies each labelled with its frame number and time, to see a whole animation at a glance.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <vector>

#include <CLI/CLI.hpp>
#include <stb_easy_font.h>
#include <stb_image.h>
#include <stb_image_resize.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/summary.hpp"
#include "contracts/time_grid.hpp"
#include "cli/scene_input.hpp"
#include "contracts/limits.hpp"
#include "output/atomic_file.hpp"
#include "output/frame_manifest.hpp"
#include "output/sha256.hpp"
#include "output/png_encoder.hpp"

namespace sl {

namespace {

struct SheetArguments {
  std::string folder, out;
  int count = 12, columns = 4, tileWidth = 320;
  bool quiet = false, noClobber = false;
};

std::string readWholeFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CommandExit(kExitBadInput, path + ": cannot read (listed in manifest.json)");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

constexpr int kLabelScale = 2;                  // stb_easy_font's 7-pixel letters, doubled
constexpr int kLabelHeight = 12 * kLabelScale;  // the strip under each tile
constexpr int kGap = 8;
constexpr std::uint8_t kPaper = 255, kInk = 40;

// Fills the quads stb_easy_font lays out for `text` (axis-aligned rectangles) into the image at (x, y).
void drawLabel(Image& sheet, int x, int y, const std::string& text) {
  std::vector<char> buffer(text.size() * 270 + 64);  // the library's bound per character
  std::string writable = text;
  const int quads = stb_easy_font_print(0, 0, writable.data(), nullptr, buffer.data(), int(buffer.size()));
  const float* vertices = reinterpret_cast<const float*>(buffer.data());  // x, y, z, colour: 16 bytes a vertex
  for (int q = 0; q < quads; ++q) {
    const float* v = vertices + q * 16;
    const int x0 = x + int(v[0]) * kLabelScale, y0 = y + int(v[1]) * kLabelScale;
    const int x1 = x + int(v[8]) * kLabelScale, y1 = y + int(v[9]) * kLabelScale;
    for (int py = std::max(0, y0); py < std::min(sheet.height, y1); ++py)
      for (int px = std::max(0, x0); px < std::min(sheet.width, x1); ++px)
        for (int c = 0; c < 3; ++c) sheet.rgb[(size_t(py) * sheet.width + px) * 3 + c] = kInk;
  }
}

void runContactSheet(SheetArguments args) {
  if (args.out.empty()) {  // renders/default/ -> renders/default-sheet.png
    std::string folder = args.folder;
    while (folder.size() > 1 && folder.back() == '/') folder.pop_back();
    args.out = (folder == "." || folder == "/" ? std::string("contact") : folder) + "-sheet.png";
  }
  const CommandSummary summary("contact-sheet", args.quiet);
  // The manifest through the one validated reader (as --resume and diff read it): entries well formed, frame numbers
  // in range, file names inside the folder.
  const std::string path = args.folder + "/manifest.json";
  if (!std::filesystem::exists(path))
    throw CommandExit(kExitBadInput, path + ": cannot read (is " + args.folder + " a render folder?)");
  ManifestContents manifest;
  try {
    manifest = readManifestFile(path);
  } catch (const ManifestInvalid& error) {
    throw CommandExit(kExitBadInput, error.what());
  }
  const auto infoNumber = [&](const char* key) {
    const nlohmann::json* value = manifest.info.is_object() && manifest.info.contains(key) ? &manifest.info.at(key) : nullptr;
    if (!value || !value->is_number_integer() || value->get<long>() < 1 || value->get<long>() > limits::kMaxFrames)
      throw CommandExit(kExitBadInput, path + ": info." + key + ": expected a positive integer (a render's manifest)");
    return int(value->get<long>());
  };
  const int fps = infoNumber("fps"), width = infoNumber("width"), height = infoNumber("height");
  const int frameCount = infoNumber("frames");
  std::vector<FrameEntry> frames;
  std::vector<NamedFile> inputs{{"the manifest", path}};
  for (const auto& [frame, entry] : manifest.frames)
    if (!entry.file.empty()) frames.push_back(entry), inputs.push_back({"frame " + std::to_string(frame), args.folder + "/" + entry.file});
  if (frames.empty()) throw CommandExit(kExitBadInput, path + ": lists no PNG frames");
  if (args.out.size() < 5 || args.out.substr(args.out.size() - 4) != ".png")
    throw CommandExit(kExitBadInput, "--out: found \"" + args.out + "\"; expected a file name ending in .png");
  if (args.noClobber) refuseExistingOutputs("contact-sheet", {{"--out", args.out}});
  requireOutputsBeforeWork("contact-sheet", inputs, {{"--out", args.out}});

  const int count = std::min<int>(args.count, int(frames.size()));
  const int columns = std::min(args.columns, count), rows = (count + columns - 1) / columns;
  const int tileHeight = std::max(1, int(std::lround(double(args.tileWidth) * height / width)));
  const long sheetWidth = kGap + long(columns) * (args.tileWidth + kGap);
  const long sheetHeight = kGap + long(rows) * (tileHeight + kLabelHeight + kGap);
  if (sheetWidth > limits::kMaxImageSide || sheetHeight > limits::kMaxImageSide)
    throw CommandExit(kExitBadInput, "linkage contact-sheet: the sheet would be " + std::to_string(sheetWidth) + "x" +
                                         std::to_string(sheetHeight) + " pixels; expected at most " +
                                         std::to_string(limits::kMaxImageSide) +
                                         " on a side: fewer frames (--count), other --columns or a smaller --tile-width");
  // An unfinished render (a shard set with a shard missing, an interrupted render) is said, not passed off as
  // whole. A render of every k-th frame (--frames ::k) is whole: its frames are 0, k, 2k, ... to the end.
  const int step = frames.size() > 1 ? frames[1].frame - frames[0].frame : frameCount;
  bool whole = frames.front().frame < step && frames.back().frame + step >= frameCount;
  for (std::size_t i = 1; i < frames.size() && whole; ++i) whole = frames[i].frame - frames[i - 1].frame == step;
  if (!whole && !args.quiet)
    std::cerr << "linkage contact-sheet: warning: " << args.folder << " holds " << frames.size() << " of the render's "
              << frameCount << " frames, with gaps (an unfinished render or shard set); the sheet shows those it holds\n";
  std::vector<FrameEntry> chosen;  // evenly spaced, the first and the last included
  for (int i = 0; i < count; ++i)
    chosen.push_back(frames[count == 1 ? 0 : size_t(i) * (frames.size() - 1) / size_t(count - 1)]);

  Image sheet;
  sheet.width = int(sheetWidth);
  sheet.height = int(sheetHeight);
  sheet.rgb.assign(size_t(sheet.width) * sheet.height * 3, kPaper);
  for (int i = 0; i < count; ++i) {
    // Each frame is the one the manifest lists: a file replaced since is refused, not shown as the original.
    const std::string file = args.folder + "/" + chosen[size_t(i)].file;
    const std::string bytes = readWholeFile(file);
    if (sha256Hex(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()) != chosen[size_t(i)].fileSha256)
      throw CommandExit(kExitBadInput, file + ": is not the frame manifest.json lists (changed since the render wrote it); "
                                              "render it again (--resume redraws it)");
    int frameWidth = 0, frameHeight = 0, channels = 0;
    std::unique_ptr<unsigned char, void (*)(void*)> pixels(
        stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &frameWidth,
                              &frameHeight, &channels, 3),
        stbi_image_free);
    if (!pixels) throw CommandExit(kExitBadInput, file + ": cannot decode PNG: " + stbi_failure_reason());
    if (frameWidth != width || frameHeight != height)
      throw CommandExit(kExitBadInput, file + ": " + std::to_string(frameWidth) + "x" + std::to_string(frameHeight) +
                                           "; manifest.json says the render is " + std::to_string(width) + "x" +
                                           std::to_string(height));
    std::vector<unsigned char> tile(size_t(args.tileWidth) * tileHeight * 3);
    stbir_resize_uint8(pixels.get(), frameWidth, frameHeight, 0, tile.data(), args.tileWidth, tileHeight, 0, 3);
    const int x = kGap + (i % columns) * (args.tileWidth + kGap);
    const int y = kGap + (i / columns) * (tileHeight + kLabelHeight + kGap);
    for (int row = 0; row < tileHeight; ++row)
      std::copy_n(tile.data() + size_t(row) * args.tileWidth * 3, size_t(args.tileWidth) * 3,
                  sheet.rgb.data() + (size_t(y + row) * sheet.width + x) * 3);
    char label[64];
    std::snprintf(label, sizeof label, "frame %d   t = %.4g", chosen[size_t(i)].frame,
                  frameTime(chosen[size_t(i)].frame, fps));
    drawLabel(sheet, x, y + tileHeight + 3 * kLabelScale, label);
  }
  writeFileAtomically(args.out, PngEncoder().encode(sheet));
  summary.print(std::to_string(count) + " of " + std::to_string(frames.size()) + " frames of " + args.folder +
                (whole ? "" : " (frames missing)") +
                " in " + std::to_string(rows) + " x " + std::to_string(columns) + " -> " + args.out);
}

}  // namespace

void addContactSheetCommand(CLI::App& app) {
  auto args = std::make_shared<SheetArguments>();
  CLI::App* command =
      app.add_subcommand("contact-sheet", "Evenly spaced frames of a render in one picture, with their times");
  command->add_option("folder", args->folder, "a render folder (frames and manifest.json)")->required();
  command->add_option("--out", args->out, "the PNG file to write; default: FOLDER-sheet.png beside the folder");
  addNoClobberFlag(*command, args->noClobber);
  command->add_option("--count", args->count, "how many frames (the first and the last included)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  command->add_option("--columns", args->columns, "frames per row")->check(CLI::Range(1, 100))->capture_default_str();
  command->add_option("--tile-width", args->tileWidth, "width of each small frame in pixels")
      ->check(CLI::Range(16, 4096))
      ->capture_default_str();
  command->add_flag("--quiet", args->quiet, "no summary line");
  command->footer(
      "Examples:\n"
      "  linkage contact-sheet renders/default --out default-sheet.png\n"
      "  linkage contact-sheet renders/jacobi --count 20 --columns 5 --tile-width 240 --out jacobi-sheet.png");
  command->callback([args] { runContactSheet(*args); });
}

}  // namespace sl
