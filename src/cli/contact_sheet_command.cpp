// `linkage contact-sheet FOLDER --out FILE.png`: evenly spaced frames of a render in one picture, a grid of
// small copies each labelled with its frame number and time, to see a whole animation at a glance.

#include <algorithm>
#include <cstdio>
#include <fstream>
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
#include "output/atomic_file.hpp"
#include "output/png_encoder.hpp"

namespace sl {

namespace {

struct SheetArguments {
  std::string folder, out;
  int count = 12, columns = 4, tileWidth = 320;
  bool quiet = false;
};

struct RenderedFrame {
  int frame;
  std::string file;
};

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

void runContactSheet(const SheetArguments& args) {
  const CommandSummary summary("contact-sheet", args.quiet);
  const std::string path = args.folder + "/manifest.json";
  std::ifstream in(path);
  if (!in) throw CommandExit(kExitBadInput, path + ": cannot read (is " + args.folder + " a render folder?)");
  std::vector<RenderedFrame> frames;
  int fps = 0;
  try {
    const nlohmann::json manifest = nlohmann::json::parse(in);
    fps = manifest.at("info").at("fps").get<int>();
    for (const auto& entry : manifest.at("frames"))
      if (!entry.value("file", "").empty())
        frames.push_back({entry.at("frame").get<int>(), entry.at("file").get<std::string>()});
  } catch (const nlohmann::json::exception& error) {
    throw CommandExit(kExitBadInput, path + ": not a frame manifest: " + error.what());
  }
  if (frames.empty() || fps <= 0) throw CommandExit(kExitBadInput, path + ": lists no PNG frames");
  if (args.out.size() < 5 || args.out.substr(args.out.size() - 4) != ".png")
    throw CommandExit(kExitBadInput, "--out: found \"" + args.out + "\"; expected a file name ending in .png");
  std::sort(frames.begin(), frames.end(), [](const auto& a, const auto& b) { return a.frame < b.frame; });
  const int count = std::min<int>(args.count, int(frames.size()));
  std::vector<RenderedFrame> chosen;  // evenly spaced, the first and the last included
  for (int i = 0; i < count; ++i)
    chosen.push_back(frames[count == 1 ? 0 : size_t(i) * (frames.size() - 1) / size_t(count - 1)]);

  const int columns = std::min(args.columns, count), rows = (count + columns - 1) / columns;
  int tileHeight = 0;
  Image sheet;
  for (int i = 0; i < count; ++i) {
    const std::string file = args.folder + "/" + chosen[size_t(i)].file;
    int width = 0, height = 0, channels = 0;
    std::unique_ptr<unsigned char, void (*)(void*)> pixels(stbi_load(file.c_str(), &width, &height, &channels, 3),
                                                           stbi_image_free);
    if (!pixels) throw CommandExit(kExitBadInput, file + ": cannot decode PNG: " + stbi_failure_reason());
    if (i == 0) {
      tileHeight = std::max(1, int(std::lround(double(args.tileWidth) * height / width)));
      sheet.width = kGap + columns * (args.tileWidth + kGap);
      sheet.height = kGap + rows * (tileHeight + kLabelHeight + kGap);
      sheet.rgb.assign(size_t(sheet.width) * sheet.height * 3, kPaper);
    }
    std::vector<unsigned char> tile(size_t(args.tileWidth) * tileHeight * 3);
    stbir_resize_uint8(pixels.get(), width, height, 0, tile.data(), args.tileWidth, tileHeight, 0, 3);
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
                " in " + std::to_string(rows) + " x " + std::to_string(columns) + " -> " + args.out);
}

}  // namespace

void addContactSheetCommand(CLI::App& app) {
  auto args = std::make_shared<SheetArguments>();
  CLI::App* command =
      app.add_subcommand("contact-sheet", "Evenly spaced frames of a render in one picture, with their times");
  command->add_option("folder", args->folder, "a render folder (frames and manifest.json)")->required();
  command->add_option("--out", args->out, "the PNG file to write")->required();
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
