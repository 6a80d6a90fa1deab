// `linkage diff OLD NEW`: two trajectory CSVs, or two render folders through their manifests.
// Exit 0 when they match (within --tol for trajectories), 1 when not, 2 when they cannot be read.

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <tuple>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/number_options.hpp"
#include "cli/csv_diff.hpp"
#include "cli/exit_codes.hpp"
#include "cli/folder_diff.hpp"
#include "cli/summary.hpp"

namespace sl {

namespace {

namespace fs = std::filesystem;

struct DiffArguments {
  std::string before, after;
  double tolerance = 1e-9;
  bool images = false;
  PixelTolerance pixels;
  std::string imageFolder;  // empty: no diff images
  int maxImages = 10;
  bool quiet = false;
};

TrajectoryCsv readCsvFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw CommandExit(kExitBadInput, path + ": cannot read");
  try {
    return readTrajectoryCsv(in, path);
  } catch (const std::runtime_error& error) {
    throw CommandExit(kExitBadInput, error.what());
  }
}

std::string trajectorySummary(const std::vector<RunDifference>& differences) {
  int differing = 0, notCompared = 0;
  for (const RunDifference& run : differences) {
    differing += run.matches() ? 0 : 1;
    notCompared += run.comparedRows == 0 && !run.structure.empty() ? 1 : 0;
  }
  return std::to_string(differences.size()) + " run" + (differences.size() == 1 ? "" : "s") + ", " +
         std::to_string(differing) + " differ" + (notCompared ? " (" + std::to_string(notCompared) + " not compared)" : "");
}

bool diffTrajectories(const DiffArguments& args, std::string& summary) {
  const auto differences = compareTrajectories(readCsvFile(args.before), readCsvFile(args.after), args.tolerance);
  summary = trajectorySummary(differences);
  return printTrajectoryDifferences(std::cout, differences, args.tolerance);
}

std::string joined(const std::vector<std::string>& parts) {
  if (parts.empty()) return "not recorded";
  std::string text;
  for (const std::string& part : parts) text += (text.empty() ? "" : ", ") + part;
  return text;
}

// "0.0123% of pixels differ by more than 2 levels (largest 7)"
std::string pixelLine(int frame, const PixelDifference& pixels, const PixelTolerance& tolerance) {
  std::ostringstream line;
  line << "frame " << frame << ": ";
  if (!pixels.note.empty()) {
    line << pixels.note << " (no pixel comparison)";
    return line.str();
  }
  line << pixels.fraction * 100 << "% of pixels differ";
  if (tolerance.levels > 0) line << " by more than " << tolerance.levels << " levels";
  line << " (largest channel difference " << pixels.largestLevel << ")";
  if (tolerance.maxDifferingPercent > 0)
    line << (pixels.withinTolerance(tolerance) ? "; within" : "; beyond") << " --max-differing "
         << tolerance.maxDifferingPercent << "%";
  if (!pixels.diffImage.empty()) line << "; " << pixels.diffImage;
  return line.str();
}

bool diffFolders(const DiffArguments& args, std::string& summary) {
  std::map<int, std::string> before, after;
  DrawnBy drawnBefore, drawnAfter;
  try {
    std::tie(before, after) = comparableHashes(readFolderFrames(args.before), readFolderFrames(args.after));
    drawnBefore = readDrawnBy(args.before);
    drawnAfter = readDrawnBy(args.after);
  } catch (const std::invalid_argument& error) {
    throw CommandExit(kExitBadInput, error.what());
  }
  const auto shown = [](const DrawnBy& drawn) {
    return joined(drawn.renderers) + (drawn.backends.empty() ? "" : " (through " + joined(drawn.backends) + ")");
  };
  std::cout << "GL renderer: " << args.before << ": " << shown(drawnBefore) << "; " << args.after << ": "
            << shown(drawnAfter) << '\n';
  // The backend alone changes nothing (EGL's software device and OSMesa are the same llvmpipe); the renderer, its
  // version or the CPU llvmpipe generated code for may (docs/rendering.md, "Across machines").
  if (drawnBefore.renderers != drawnAfter.renderers && !args.quiet)
    std::cerr << "linkage diff: warning: the two renders name different GL renderers (or CPUs), so their pixels may "
                 "differ slightly; compare them with --pixel-tol LEVELS --max-differing PERCENT\n";
  // The scene texts first: frames that differ because the scene did are not a regression of the program.
  if (!drawnBefore.sceneSha256.empty() && !drawnAfter.sceneSha256.empty()) {
    if (drawnBefore.sceneSha256 == drawnAfter.sceneSha256)
      std::cout << "scene: the same scene text (sceneSha256 " << drawnBefore.sceneSha256.substr(0, 12) << "...)\n";
    else
      std::cout << "scene: different scene texts (sceneSha256 " << drawnBefore.sceneSha256.substr(0, 12) << "... in "
                << args.before << ", " << drawnAfter.sceneSha256.substr(0, 12) << "... in " << args.after
                << "): the scene or its --set overrides changed\n";
  }
  // Diff images of an earlier comparison would read as this one's: they go first.
  if (!args.imageFolder.empty() && fs::is_directory(args.imageFolder)) {
    int removed = 0;
    for (const auto& entry : fs::directory_iterator(args.imageFolder)) {
      const std::string name = entry.path().filename().string();
      if (entry.is_regular_file() && name.rfind(kDiffImagePrefix, 0) == 0 && entry.path().extension() == ".png")
        removed += fs::remove(entry.path()) ? 1 : 0;
    }
    if (removed > 0 && !args.quiet)
      std::cerr << "linkage diff: removed " << removed << " diff image(s) of an earlier diff from " << args.imageFolder
                << "\n";
  }
  const FolderDifference byHash = compareFolders(before, after);
  const bool tolerant = args.pixels.levels > 0 || args.pixels.maxDifferingPercent > 0;
  const bool decode = args.images || tolerant || !args.imageFolder.empty();
  // Frames whose pixel hashes differ on both sides are decoded when asked; a frame only one side has differs.
  int differing = 0;
  std::optional<int> first;
  std::vector<std::string> lines;
  int shownLines = 0, allLines = 0;
  for (const auto& [frame, hash] : before) {
    const auto other = after.find(frame);
    if (other == after.end() || other->second == hash || !decode) continue;
    ++allLines;
    const bool show = shownLines < args.maxImages;
    PixelDifference pixels;
    try {
      pixels = comparePixels(args.before, args.after, frame, args.pixels.levels, show ? args.imageFolder : "");
    } catch (const std::invalid_argument& error) {
      throw CommandExit(kExitBadInput, error.what());
    }
    if (!pixels.withinTolerance(args.pixels)) {
      ++differing;
      if (!first || frame < *first) first = frame;
    }
    if (show) {
      lines.push_back(pixelLine(frame, pixels, args.pixels));
      ++shownLines;
    }
  }
  if (decode) {  // frames one side lacks
    for (const auto& [frame, hash] : before)
      if (!after.count(frame) && (++differing, !first || frame < *first)) first = frame;
    for (const auto& [frame, hash] : after)
      if (!before.count(frame) && (++differing, !first || frame < *first)) first = frame;
  } else {
    differing = byHash.differing;
    first = byHash.firstDiffering;
  }
  std::ostringstream head;
  head << byHash.framesBefore << " frames vs " << byHash.framesAfter << "; " << differing << " differ";
  if (tolerant)
    head << " beyond --pixel-tol " << args.pixels.levels << " --max-differing " << args.pixels.maxDifferingPercent
         << "% (" << byHash.differing << " by pixel hash)";
  if (first) head << "; first differing frame " << *first;
  std::cout << head.str() << '\n';
  for (const std::string& line : lines) std::cout << line << '\n';
  if (shownLines < allLines)
    std::cout << shownLines << " of " << allLines << " frames with other pixels shown (--max-images N for more)\n";
  if (decode && args.imageFolder.empty() && allLines > 0)
    std::cout << "no diff images written (--image-dir DIR writes them)\n";
  summary = head.str();
  return differing == 0;
}

void runDiff(const DiffArguments& args) {
  const bool folders = fs::is_directory(args.before) && fs::is_directory(args.after);
  const bool files = fs::is_regular_file(args.before) && fs::is_regular_file(args.after);
  if (!folders && !files) {
    for (const std::string& path : {args.before, args.after})
      if (!fs::exists(path)) throw CommandExit(kExitBadInput, "diff: " + path + ": no such file or folder");
    throw CommandExit(kExitBadInput, "diff: expected two trajectory CSV files or two render folders, found \"" +
                                         args.before + "\" and \"" + args.after + "\"");
  }
  const CommandSummary summary("diff", args.quiet);
  std::string what;
  const bool match = folders ? diffFolders(args, what) : diffTrajectories(args, what);
  summary.print(std::string(folders ? "folders" : "trajectories") + ": " + what + (match ? "; they match" : ""));
  if (!match) throw CommandExit(kExitMismatch, "");
}

}  // namespace

void addDiffCommand(CLI::App& app) {
  auto args = std::make_shared<DiffArguments>();
  CLI::App* command =
      app.add_subcommand("diff", "Compare two trajectory CSVs or two render folders (exit 0 same, 1 different)");
  command->add_option("old", args->before, "CSV from `linkage simulate --csv`, or a render folder")->required();
  command->add_option("new", args->after, "the same kind as OLD")->required();
  command->add_option("--tol", args->tolerance, "CSV: largest hinge position difference that still matches")
      ->check(finiteNonNegative())
      ->capture_default_str();
  command->add_flag("--images", args->images,
                    "folders: decode the frames whose pixel hashes differ and print the fraction of differing pixels");
  command->add_option("--pixel-tol", args->pixels.levels,
                      "folders: a pixel differs only when a channel differs by more than LEVELS (0..255; implies "
                      "--images)")
      ->check(CLI::Range(0, 255))
      ->capture_default_str();
  command->add_option("--max-differing", args->pixels.maxDifferingPercent,
                      "folders: a frame matches when at most PERCENT of its pixels differ (implies --images)")
      ->check(finiteRange(0.0, 100.0))
      ->capture_default_str();
  command->add_option("--image-dir", args->imageFolder,
                      "write diff_frame_NNNNN.png (differing pixels red) into this folder; none without it");
  command->add_option("--max-images", args->maxImages, "at most this many per-frame lines and diff images")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  command->add_flag("--quiet", args->quiet, "no warning or summary line on stderr (the report on stdout stays)");
  command->footer(
      "CSV: per run, the worst hinge position difference and the first time it exceeds --tol.\n"
      "A run missing from one file, or sampled at other times, is reported as not compared.\n"
      "Folders: frames compared by the pixel SHA-256 in manifest.json; the first differing frame and how many, and\n"
      "the GL renderer each manifest names (a warning when they differ). Frames from another Mesa build differ by a\n"
      "level or two here and there: --pixel-tol and --max-differing hold them to a tolerance instead.\n"
      "Examples:\n"
      "  linkage diff old.csv new.csv --tol 1e-8\n"
      "  linkage diff renders/default renders/default-new --images --image-dir renders/diff\n"
      "  linkage diff golden/frames renders/ci --pixel-tol 2 --max-differing 0.5");
  command->callback([args] { runDiff(*args); });
}

}  // namespace sl
