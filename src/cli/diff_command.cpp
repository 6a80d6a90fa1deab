// `linkage diff OLD NEW`: two trajectory CSVs, or two render folders through their manifests.
// Exit 0 when they match (within --tol for trajectories), 1 when not, 2 when they cannot be read.

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <tuple>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/number_options.hpp"
#include "cli/csv_diff.hpp"
#include "cli/exit_codes.hpp"
#include "cli/folder_diff.hpp"

namespace sl {

namespace {

namespace fs = std::filesystem;

struct DiffArguments {
  std::string before, after;
  double tolerance = 1e-9;
  bool images = false;
  std::string imageFolder = "diff-images";
  int maxImages = 10;
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

bool diffTrajectories(const DiffArguments& args) {
  const auto differences = compareTrajectories(readCsvFile(args.before), readCsvFile(args.after), args.tolerance);
  return printTrajectoryDifferences(std::cout, differences, args.tolerance);
}

bool diffFolders(const DiffArguments& args) {
  std::map<int, std::string> before, after;
  try {
    std::tie(before, after) = comparableHashes(readFolderFrames(args.before), readFolderFrames(args.after));
  } catch (const std::invalid_argument& error) {
    throw CommandExit(kExitBadInput, error.what());
  }
  const FolderDifference result = compareFolders(before, after);
  std::cout << result.framesBefore << " frames vs " << result.framesAfter << "; " << result.differing << " differ";
  if (result.firstDiffering) std::cout << "; first differing frame " << *result.firstDiffering;
  std::cout << '\n';
  if (!args.images) return result.matches();
  int written = 0;
  for (const auto& [frame, hash] : before) {
    const auto other = after.find(frame);
    if (other == after.end() || other->second == hash || written >= args.maxImages) continue;
    PixelDifference pixels;
    try {
      pixels = comparePixels(args.before, args.after, frame, args.imageFolder);
    } catch (const std::invalid_argument& error) {
      throw CommandExit(kExitBadInput, error.what());
    }
    if (!pixels.note.empty())
      std::cout << "frame " << frame << ": " << pixels.note << " (no pixel comparison)\n";
    else
      std::cout << "frame " << frame << ": " << pixels.fraction * 100 << "% of pixels differ; " << pixels.diffImage
                << '\n';
    ++written;
  }
  return result.matches();
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
  const bool match = folders ? diffFolders(args) : diffTrajectories(args);
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
                    "folders: decode differing frames, print the fraction of differing pixels, write diff images");
  command->add_option("--image-dir", args->imageFolder, "where --images writes diff_frame_NNNNN.png")
      ->capture_default_str();
  command->add_option("--max-images", args->maxImages, "at most this many diff images")
      ->check(finitePositive())
      ->capture_default_str();
  command->footer(
      "CSV: per run, the worst hinge position difference and the first time it exceeds --tol.\n"
      "Folders: frames compared by the pixel SHA-256 in manifest.json; the first differing frame and how many.\n"
      "Examples:\n"
      "  linkage diff old.csv new.csv --tol 1e-8\n"
      "  linkage diff renders/default renders/default-new --images");
  command->callback([args] { runDiff(*args); });
}

}  // namespace sl
