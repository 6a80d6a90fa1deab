// The everyday conventions of every command: progress lines in a log (stderr not a terminal), a summary line at
// the end and --quiet everywhere, "-" for a scene on standard input, "did you mean" for mistyped commands and
// options, list-methods with its defaults, --frames A:B:STEP and --replace.
#include <algorithm>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/exit_codes.hpp"
#include "cli/frame_range.hpp"
#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

int countOf(const std::string& text, const std::string& part) {
  int count = 0;
  for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
  return count;
}

// A test's stderr is a file, as in a cluster job: a line at every tenth of the work, each whole.
TEST(EverydayCli, ProgressLinesInALog) {
  TempFolder folder;
  const ProcessResult render = runLinkage(
      {"render", shippedScene("seam.json"), "--size", "160x90", "--frames", "0:100", "--out", "r"}, folder.path());
  ASSERT_EQ(render.code, 0) << render.err;
  EXPECT_EQ(render.err.find('\r'), std::string::npos) << render.err;
  for (int percent = 10; percent <= 100; percent += 10) {
    const std::string line = "linkage render: frame " + std::to_string(percent) + "/100 (" + std::to_string(percent) + "%)";
    EXPECT_NE(render.err.find(line), std::string::npos) << line << "\n" << render.err;
  }
  EXPECT_EQ(countOf(render.err, "linkage render: frame "), 10) << render.err;
  // Grid cells of a sweep, likewise.
  const ProcessResult sweep = runLinkage(
      {"stability", "--kind", "pole", "--grid", "10", "--methods", "ambient", "--no-charts", "--out", "s"},
      folder.path());
  ASSERT_EQ(sweep.code, 0) << sweep.err;
  EXPECT_EQ(countOf(sweep.err, "linkage stability: cell "), 10) << sweep.err;
  EXPECT_NE(sweep.err.find("cell 100/100 (100%)"), std::string::npos) << sweep.err;
  // Grid rows of a curvature grid, likewise; the CSV is the same as without progress (rows computed in blocks).
  const ProcessResult grid =
      runLinkage({"geometry", shippedScene("default.json"), "--grid", "40", "--csv", "k.csv"}, folder.path());
  ASSERT_EQ(grid.code, 0) << grid.err;
  EXPECT_EQ(countOf(grid.err, "linkage geometry: grid row "), 10) << grid.err;
  EXPECT_NE(grid.err.find("grid row 40/40 (100%)"), std::string::npos) << grid.err;
  const ProcessResult quiet = runLinkage(
      {"render", shippedScene("seam.json"), "--size", "160x90", "--frames", "0:100", "--out", "r", "--quiet"},
      folder.path());
  EXPECT_EQ(quiet.err, "");
}

struct CommandCase {
  std::string name;
  std::vector<std::string> args;
};

std::vector<CommandCase> everyCommand() {
  const std::string seam = shippedScene("seam.json"), four = shippedScene("default.json");
  return {
      {"validate", {"validate", seam}},
      {"simulate", {"simulate", seam, "--csv", "t.csv"}},
      {"render", {"render", seam, "--size", "160x90", "--frames", "0:3", "--out", "r"}},
      {"diff", {"diff", "r", "r"}},
      {"still", {"still", seam, "--time", "1", "--size", "160x90", "--out", "still.png"}},
      {"contact-sheet", {"contact-sheet", "r", "--out", "sheet.png"}},
      {"list-methods", {"list-methods"}},
      {"bench", {"bench", "--quick", "--start", "generic", "--methods", "ambient", "--integrators", "rk4",
                 "--no-charts", "--out", "b"}},
      {"stability", {"stability", "--kind", "pole", "--grid", "3", "--methods", "ambient", "--no-charts", "--out", "s"}},
      {"geometry", {"geometry", four, "--summary"}},
      {"numbers", {"numbers", seam}},
      {"connect", {"connect", four, "--to", R"({"coords": [-0.6, 2.2]})", "--max-length", "3"}},
      {"periodic", {"periodic", four, "--max-length", "7"}},
      {"schema", {"schema"}},
  };
}

TEST(EverydayCli, EveryCommandEndsWithASummaryAndTakesQuiet) {
  TempFolder folder;
  for (const CommandCase& command : everyCommand()) {
    const ProcessResult loud = runLinkage(command.args, folder.path());
    EXPECT_EQ(loud.code, 0) << command.name << ": " << loud.err;
    const size_t last = loud.err.rfind("linkage " + command.name + ": ");
    ASSERT_NE(last, std::string::npos) << command.name << ": " << loud.err;
    EXPECT_TRUE(std::regex_search(loud.err.substr(last), std::regex(" in [0-9.e-]+ s.*\n$")))
        << command.name << ": " << loud.err;
    std::vector<std::string> quietArgs = command.args;
    quietArgs.push_back("--quiet");
    const ProcessResult quiet = runLinkage(quietArgs, folder.path());
    EXPECT_EQ(quiet.code, 0) << command.name << ": " << quiet.err;
    EXPECT_EQ(quiet.err, "") << command.name;
  }
}

TEST(EverydayCli, DashReadsTheSceneFromStandardInput) {
  TempFolder folder;
  const std::string scene = shellQuoted(shippedScene("seam.json"));
  const std::string linkage = shellQuoted(linkageBinary());
  const ProcessResult valid = runShell(linkage + " validate - < " + scene, folder.path());
  EXPECT_EQ(valid.code, 0) << valid.err;
  EXPECT_NE(valid.out.find("(standard input): ok: \"seam\""), std::string::npos) << valid.out;
  const ProcessResult simulated = runShell("cat " + scene + " | " + linkage + " simulate - --csv piped.csv", folder.path());
  EXPECT_EQ(simulated.code, 0) << simulated.err;
  ASSERT_EQ(runLinkage({"simulate", shippedScene("seam.json"), "--csv", "file.csv"}, folder.path()).code, 0);
  EXPECT_EQ(readFile(folder.path() / "piped.csv"), readFile(folder.path() / "file.csv"));
  const ProcessResult bad = runShell("echo '{\"name\": \"x\"}' | " + linkage + " validate -", folder.path());
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("(standard input): duration: missing"), std::string::npos) << bad.err;
}

TEST(EverydayCli, DidYouMeanForCommandsAndOptions) {
  TempFolder folder;
  const ProcessResult command = runLinkage({"rendr", "x.json"}, folder.path());
  EXPECT_EQ(command.code, 2);
  EXPECT_NE(command.err.find("\"rendr\" is no command; did you mean \"render\"?"), std::string::npos) << command.err;
  const ProcessResult option =
      runLinkage({"render", shippedScene("seam.json"), "--qiuet", "--sise=3x3", "--frames", "0:1"}, folder.path());
  EXPECT_EQ(option.code, 2);
  EXPECT_NE(option.err.find("render: \"--qiuet\" is no option; did you mean \"--quiet\"?"), std::string::npos)
      << option.err;
  EXPECT_NE(option.err.find("\"--sise\" is no option; did you mean \"--size\"?"), std::string::npos) << option.err;
  EXPECT_FALSE(fs::exists(folder.path() / "renders"));
  const ProcessResult far = runLinkage({"validate", shippedScene("seam.json"), "--zzzzzzzz"}, folder.path());
  EXPECT_EQ(far.code, 2);
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
  // An abbreviation is answered with the options it begins, and the program's words come before the parser's.
  const ProcessResult shortened = runLinkage({"still", shippedScene("seam.json"), "--t", "7"}, folder.path());
  EXPECT_EQ(shortened.code, 2);
  const std::size_t hint = shortened.err.find("still: \"--t\" is no option; did you mean \"--time\" or \"--transparent\"?");
  ASSERT_NE(hint, std::string::npos) << shortened.err;
  EXPECT_LT(hint, shortened.err.find("--time is required")) << shortened.err;
  EXPECT_LT(option.err.find("did you mean"), option.err.find("not expected")) << option.err;
}

TEST(EverydayCli, ListMethodsMarksTheDefaultsAndSaysWhatEachIs) {
  TempFolder folder;
  const ProcessResult list = runLinkage({"list-methods"}, folder.path());
  ASSERT_EQ(list.code, 0);
  EXPECT_TRUE(std::regex_search(list.out, std::regex("\n  ambient +\\(default\\) chart-free")) ) << list.out;
  EXPECT_TRUE(std::regex_search(list.out, std::regex("\n  rkf78 +\\(default\\) ")) ) << list.out;
  EXPECT_EQ(countOf(list.out, "(default)"), 2) << list.out;
  EXPECT_TRUE(std::regex_search(list.out, std::regex("\n  christoffel-fd +spec section 4 as published")) ) << list.out;
  EXPECT_NE(list.out.find("defaults: tolerance 1e-14, step 0.01"), std::string::npos) << list.out;
}

TEST(EverydayCli, FramesWithAStepAndReplace) {
  TempFolder folder;
  const auto render = [&](const std::string& scene, const std::vector<std::string>& more) {
    std::vector<std::string> args{"render", shippedScene(scene), "--size", "160x90", "--out", "r", "--quiet"};
    args.insert(args.end(), more.begin(), more.end());
    return runLinkage(args, folder.path());
  };
  ASSERT_EQ(render("seam.json", {"--frames", "5:50:20"}).code, 0);
  std::vector<std::string> frames;
  for (const auto& entry : fs::directory_iterator(folder.path() / "r"))  // the lock files (dot files) aside
    if (entry.path().filename().string()[0] != '.') frames.push_back(entry.path().filename());
  std::sort(frames.begin(), frames.end());
  EXPECT_EQ(frames, (std::vector<std::string>{"frame_00005.png", "frame_00025.png", "frame_00045.png", "manifest.json"}));
  // Every 20th frame equals that frame of a render of the range.
  ASSERT_EQ(runLinkage({"render", shippedScene("seam.json"), "--size", "160x90", "--out", "all", "--frames", "0:46",
                        "--quiet"},
                       folder.path())
                .code,
            0);
  for (const char* name : {"frame_00005.png", "frame_00025.png", "frame_00045.png"})
    EXPECT_EQ(readFile(folder.path() / "r" / name), readFile(folder.path() / "all" / name)) << name;
  EXPECT_EQ(render("seam.json", {"--frames", "0:10:0"}).code, 2);
  ASSERT_EQ(runLinkage({"render", shippedScene("seam.json"), "--size", "160x90", "--out", "one", "--frames", "25",
                        "--quiet"},
                       folder.path())
                .code,
            0);  // one frame: the same as that frame of a range
  EXPECT_EQ(readFile(folder.path() / "one/frame_00025.png"), readFile(folder.path() / "all/frame_00025.png"));
  EXPECT_FALSE(fs::exists(folder.path() / "one/frame_00026.png"));
  EXPECT_EQ(render("seam.json", {"--frames", "301"}).code, 2);
  // Another scene's range only joins the same render; --replace removes the earlier one first.
  EXPECT_EQ(render("comparison.json", {"--frames", "0:2"}).code, 2);
  EXPECT_EQ(render("comparison.json", {"--frames", "0:2", "--replace"}).code, 0);
  EXPECT_FALSE(fs::exists(folder.path() / "r/frame_00005.png"));
  EXPECT_TRUE(fs::exists(folder.path() / "r/frame_00001.png"));
  EXPECT_EQ(render("comparison.json", {"--frames", "0:2", "--replace", "--resume"}).code, 2);
}

// --time A:B picks the frames whose time t has A <= t < B, as --frames picks numbers: at 30 fps 2.5:3 is frames
// 75..89 (t = 2.5 .. 2.9667), "19.99:" the last one, A:B:STEP every STEP-th; the files are those of --frames.
TEST(EverydayCli, TimeRangesInSeconds) {
  const FrameRange half = parseTimeRange("2.5:3", 20, 30);
  EXPECT_EQ(half.first, 75);
  EXPECT_EQ(half.end, 90);
  const FrameRange last = parseTimeRange("19.99:", 20, 30);
  EXPECT_EQ(last.first, 600);
  EXPECT_EQ(last.end, 601);
  const FrameRange stepped = parseTimeRange(":1:10", 20, 30);
  EXPECT_EQ(stepped.count(), 3);  // frames 0, 10, 20
  const FrameRange whole = parseTimeRange(":", 20, 30);
  EXPECT_EQ(whole.end, 601);
  EXPECT_THROW(parseTimeRange("0.01:0.02", 20, 30), CommandExit);  // no frame at 30 fps in [0.01, 0.02)

  TempFolder folder;
  const ProcessResult byTime = runLinkage(
      {"render", shippedScene("default.json"), "--size", "160x90", "--time", "2.5:3", "--out", "t"}, folder.path());
  ASSERT_EQ(byTime.code, 0) << byTime.err;
  const ProcessResult byNumber = runLinkage(
      {"render", shippedScene("default.json"), "--size", "160x90", "--frames", "75:90", "--out", "f"}, folder.path());
  ASSERT_EQ(byNumber.code, 0) << byNumber.err;
  for (int frame = 74; frame <= 90; ++frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", frame);
    const bool inRange = frame >= 75 && frame < 90;
    EXPECT_EQ(fs::exists(folder.path() / "t" / name), inRange) << name;
    if (inRange) {
      EXPECT_EQ(readFile(folder.path() / "t" / name), readFile(folder.path() / "f" / name)) << name;
    }
  }
}

// --video is repeatable: an mp4 and a gif from one drawing of each frame, each with its manifest, whose frames
// carry the same pixel checksums as a render of one video; the same video named twice is refused before any work.
TEST(EverydayCli, SeveralVideosFromOneDrawing) {
  TempFolder folder;
  const ProcessResult both =
      runLinkage({"render", shippedScene("default.json"), "--size", "160x90", "--frames", "0:12", "--no-png", "--video",
                  "v/talk.mp4", "--video", "v/blog.gif"},
                 folder.path());
  ASSERT_EQ(both.code, 0) << both.err;
  EXPECT_NE(both.err.find("-> v/talk.mp4 and v/blog.gif"), std::string::npos) << both.err;
  const ProcessResult one = runLinkage(
      {"render", shippedScene("default.json"), "--size", "160x90", "--frames", "0:12", "--no-png", "--video", "one.mp4"},
      folder.path());
  ASSERT_EQ(one.code, 0) << one.err;
  const auto framesOf = [&](const fs::path& manifest) {
    return nlohmann::json::parse(readFile(folder.path() / manifest))["frames"];
  };
  const nlohmann::json reference = framesOf("one.mp4.manifest.json");
  EXPECT_EQ(reference.size(), 12u);
  EXPECT_EQ(framesOf("v/talk.mp4.manifest.json"), reference);
  EXPECT_EQ(framesOf("v/blog.gif.manifest.json"), reference);
  EXPECT_GT(fs::file_size(folder.path() / "v/talk.mp4"), 0u);
  EXPECT_GT(fs::file_size(folder.path() / "v/blog.gif"), 0u);

  const ProcessResult twice = runLinkage({"render", shippedScene("default.json"), "--no-png", "--video", "w/a.mp4",
                                          "--video", "w/./a.mp4"},
                                         folder.path());
  EXPECT_EQ(twice.code, 2);
  EXPECT_NE(twice.err.find("--video: names w/./a.mp4 twice"), std::string::npos) << twice.err;
  EXPECT_FALSE(fs::exists(folder.path() / "w"));
}

// --crf: the encoder's constant rate factor, lower larger; out of range refused before any frame; and the hold
// keys lengthen the video by their frames (ffprobe's check in the sink counts them).
TEST(EverydayCli, EncoderSettingsAndHolds) {
  TempFolder folder;
  const auto render = [&](const std::string& video, std::vector<std::string> more) {
    std::vector<std::string> args{"render",   shippedScene("default.json"),
                                  "--size",   "160x90",
                                  "--frames", "0:12",
                                  "--no-png", "--quiet",
                                  "--video",  video};
    args.insert(args.end(), more.begin(), more.end());
    return runLinkage(args, folder.path());
  };
  ASSERT_EQ(render("sharp.mp4", {"--crf", "10"}).code, 0);
  ASSERT_EQ(render("soft.mp4", {"--crf", "45"}).code, 0);
  EXPECT_GT(fs::file_size(folder.path() / "sharp.mp4"), 2 * fs::file_size(folder.path() / "soft.mp4"));
  const ProcessResult refused = render("none.mp4", {"--crf", "60"});
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.err.find("--crf: found 60; expected an integer from 0 to 51"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(folder.path() / "none.mp4"));
  const ProcessResult held = render("held.gif", {"--set", "output.hold_start=0.5", "--set", "output.hold_end=1"});
  ASSERT_EQ(held.code, 0) << held.err;
  const ProcessResult probe = runShell(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 held.gif",
      folder.path());
  EXPECT_EQ(probe.out, std::to_string(12 + 15 + 30) + "\n");  // 30 frames/s
}

// Playback speed (--speed, output.playback_speed): every frame shown, at fps x speed frames a second, so the video
// lasts duration / speed; a hold is seconds of the video; the PNG frames do not change; out of range is refused with
// nothing written.
TEST(EverydayCli, PlaybackSpeed) {
  TempFolder folder;
  const auto render = [&](const std::string& out, std::vector<std::string> more) {
    std::vector<std::string> args{"render", shippedScene("default.json"), "--size", "160x90", "--frames", "0:12",
                                  "--quiet"};
    args.insert(args.end(), more.begin(), more.end());
    return runLinkage(args, folder.path());
  };
  ASSERT_EQ(render("", {"--video", "fast.mp4", "--speed", "2", "--set", "output.hold_end=0.5", "--out", "fast"}).code,
            0);
  ASSERT_EQ(render("", {"--video", "slow.mp4", "--set", "output.playback_speed=0.5", "--out", "slow"}).code, 0);
  const auto probe = [&](const std::string& video) {
    return runShell(
               "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
               "stream=r_frame_rate,nb_read_frames -of csv=p=0 " +
                   video,
               folder.path())
        .out;
  };
  EXPECT_EQ(probe("fast.mp4"), "60/1," + std::to_string(12 + 30) + "\n");  // 0.5 s held at 60 frames/s
  EXPECT_EQ(probe("slow.mp4"), "15/1,12\n");
  for (int k = 0; k < 12; ++k) {  // the same frames at any speed
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", k);
    EXPECT_EQ(readFile(folder.path() / "fast" / name), readFile(folder.path() / "slow" / name)) << name;
  }
  const ProcessResult refused = render("", {"--video", "none.mp4", "--no-png", "--speed", "20"});
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.err.find("--speed"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(folder.path() / "none.mp4"));
}

// -q/--quality: manim's presets set the size, the rate and the video quality, into a folder of their own; --size
// still overrides the preset's size; an unknown preset is refused with the list.
TEST(EverydayCli, QualityPresets) {
  TempFolder folder;
  const auto pngSize = [](const fs::path& png) {
    const std::string bytes = readFile(png);
    const auto be32 = [&](std::size_t at) {
      return (unsigned(static_cast<unsigned char>(bytes.at(at))) << 24) |
             (unsigned(static_cast<unsigned char>(bytes.at(at + 1))) << 16) |
             (unsigned(static_cast<unsigned char>(bytes.at(at + 2))) << 8) |
             unsigned(static_cast<unsigned char>(bytes.at(at + 3)));
    };
    return std::to_string(be32(16)) + "x" + std::to_string(be32(20));
  };
  const ProcessResult low =
      runLinkage({"render", shippedScene("default.json"), "-q", "low", "--frames", "0:2", "--quiet"}, folder.path());
  ASSERT_EQ(low.code, 0) << low.err;
  EXPECT_EQ(pngSize(folder.path() / "renders/default-854x480-15fps/frame_00001.png"), "854x480");
  const ProcessResult sized = runLinkage(
      {"render", shippedScene("default.json"), "--quality", "high", "--size", "320x180", "--frames", "0:1", "--quiet"},
      folder.path());
  ASSERT_EQ(sized.code, 0) << sized.err;
  EXPECT_EQ(pngSize(folder.path() / "renders/default-320x180-60fps/frame_00000.png"), "320x180");
  const ProcessResult unknown = runLinkage({"render", shippedScene("default.json"), "-q", "ultra"}, folder.path());
  EXPECT_EQ(unknown.code, 2);
  EXPECT_NE(unknown.err.find("-q/--quality: found \"ultra\"; expected one of low (854x480, 15 frames/s, small video)"),
            std::string::npos)
      << unknown.err;
}

// --help-all shows every command's notes and examples, as its own --help does (CLI11 left the footers out).
TEST(EverydayCli, HelpAllShowsEveryCommandsExamples) {
  TempFolder folder;
  const ProcessResult all = runLinkage({"--help-all"}, folder.path());
  ASSERT_EQ(all.code, 0) << all.err;
  int commands = 0;
  for (const char* command : {"render", "still", "contact-sheet", "simulate", "validate", "diff", "numbers", "connect",
                              "periodic", "geometry", "stability", "bench"}) {
    const ProcessResult own = runLinkage({command, "--help"}, folder.path());
    ASSERT_EQ(own.code, 0) << command;
    const std::size_t examples = own.out.find("Example");
    if (examples == std::string::npos) continue;
    ++commands;
    const std::size_t line = own.out.find("linkage ", examples);
    ASSERT_NE(line, std::string::npos) << command;
    const std::string example = own.out.substr(line, own.out.find('\n', line) - line);
    EXPECT_NE(all.out.find(example), std::string::npos) << command << ": " << example;
  }
  EXPECT_GE(commands, 10);
}

// still and contact-sheet name their output when --out is not given (beside the render folder); --no-clobber
// refuses an output that exists, before any work, and leaves it as it was (still, contact-sheet and render).
TEST(EverydayCli, DefaultOutputNamesAndNoClobber) {
  TempFolder folder;
  const ProcessResult still =
      runLinkage({"still", shippedScene("default.json"), "--time", "1.5", "--size", "160x90"}, folder.path());
  ASSERT_EQ(still.code, 0) << still.err;
  const fs::path stillPath = folder.path() / "renders" / "default-t1.5-160x90.png";
  ASSERT_TRUE(fs::exists(stillPath)) << still.err;
  const std::string before = readFile(stillPath);
  const ProcessResult again = runLinkage(
      {"still", shippedScene("default.json"), "--time", "1.5", "--size", "160x90", "--transparent", "--no-clobber",
       "--out", "renders/default-t1.5-160x90.png"},
      folder.path());
  EXPECT_EQ(again.code, 2);
  EXPECT_NE(again.err.find("exists, and --no-clobber never replaces a file"), std::string::npos) << again.err;
  EXPECT_EQ(readFile(stillPath), before);

  ASSERT_EQ(runLinkage({"render", shippedScene("default.json"), "--size", "160x90", "--frames", "0:3", "--out", "r"},
                       folder.path()).code, 0);
  const ProcessResult sheet = runLinkage({"contact-sheet", "r/", "--count", "3"}, folder.path());
  ASSERT_EQ(sheet.code, 0) << sheet.err;
  EXPECT_TRUE(fs::exists(folder.path() / "r-sheet.png"));
  EXPECT_EQ(runLinkage({"contact-sheet", "r", "--no-clobber"}, folder.path()).code, 2);
  const ProcessResult render = runLinkage(
      {"render", shippedScene("default.json"), "--size", "160x90", "--frames", "0:3", "--out", "r", "--no-clobber"},
      folder.path());
  EXPECT_EQ(render.code, 2);
  EXPECT_NE(render.err.find("r/manifest.json exists"), std::string::npos) << render.err;
}

// A render whose scene --set changed in anything but its output goes to a folder of its own, named by the change,
// and never replaces the scene's own render; the output's own settings keep their suffixes.
TEST(EverydayCli, RendersOfAChangedSceneGetAFolderOfTheirOwn) {
  TempFolder folder;
  const auto render = [&](const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"render", shippedScene("default.json"), "--frames", "0:2", "--quiet"};
    args.insert(args.end(), extra.begin(), extra.end());
    return runLinkage(args, folder.path());
  };
  ASSERT_EQ(render({"--size", "160x90"}).code, 0);
  ASSERT_EQ(render({"--size", "160x90", "--set", "linkage.L=3.2"}).code, 0);
  ASSERT_EQ(render({"--size", "160x90", "--set", "linkage.L=3.2", "--set", "output.fps=10"}).code, 0);
  EXPECT_TRUE(fs::exists(folder.path() / "renders/default-160x90/manifest.json"));
  EXPECT_TRUE(fs::exists(folder.path() / "renders/default-linkage.L=3.2-160x90/manifest.json"));
  EXPECT_TRUE(fs::exists(folder.path() / "renders/default-linkage.L=3.2-160x90-10fps/manifest.json"));
  const std::string own = readFile(folder.path() / "renders/default-160x90/manifest.json");
  const std::string changed = readFile(folder.path() / "renders/default-linkage.L=3.2-160x90/manifest.json");
  EXPECT_NE(own, changed);
}

TEST(EverydayCli, UnsetAndAppendByJsonPath) {
  TempFolder folder;
  const std::string seam = shippedScene("seam.json");  // runs[0]: christoffel, dopri5, tolerance 1e-10
  const ProcessResult kept = runLinkage({"validate", seam, "--set", "runs[0].integrator=rk4"}, folder.path());
  EXPECT_EQ(kept.code, 2);
  EXPECT_NE(kept.err.find("runs[0].tolerance: is not used"), std::string::npos) << kept.err;
  const ProcessResult unset =
      runLinkage({"validate", seam, "--set", "runs[0].integrator=rk4", "--unset", "runs[0].tolerance"}, folder.path());
  EXPECT_EQ(unset.code, 0) << unset.err;
  EXPECT_NE(unset.out.find("\"exact\" (christoffel, rk4)"), std::string::npos) << unset.out;
  const ProcessResult appended = runLinkage(
      {"validate", seam, "--set", "runs[2]={\"name\": \"third\", \"method\": \"ambient\"}", "--unset", "runs[1]"},
      folder.path());
  EXPECT_EQ(appended.code, 0) << appended.err;
  EXPECT_NE(appended.out.find("runs: \"exact\" (christoffel, dopri5) \"third\" (ambient, rkf78)\n"), std::string::npos)
      << appended.out;
  const ProcessResult beyond = runLinkage({"validate", seam, "--set", "runs[3]={\"name\": \"x\"}"}, folder.path());
  EXPECT_EQ(beyond.code, 2);
  EXPECT_NE(beyond.err.find("--set runs[3]: expected an existing array element [3] or the next one (the scene has 2"),
            std::string::npos)
      << beyond.err;
  const ProcessResult missing = runLinkage({"validate", seam, "--unset", "runs[0].nothing"}, folder.path());
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("--unset runs[0].nothing: the scene has no such key"), std::string::npos) << missing.err;
}

// default.json's title is "..., {n} rods, L = {L}": an override of L shows in the frame, exactly as a title that
// says it literally.
TEST(EverydayCli, TitlePlaceholdersFollowOverrides) {
  TempFolder folder;
  std::string text = readFile(shippedScene("default.json"));
  ASSERT_NE(text.find("{n} rods, L = {L}"), std::string::npos);
  std::string literal = text;
  literal.replace(literal.find("{n} rods, L = {L}"), 17, "4 rods, L = 3.2");
  literal.replace(literal.find("\"L\": 3.0"), 8, "\"L\": 3.2");
  writeFile(folder.path() / "literal.json", literal);
  std::string stale = literal;
  stale.replace(stale.find("L = 3.2"), 7, "L = 3");
  writeFile(folder.path() / "stale.json", stale);
  const auto render = [&](const std::string& scene, const std::string& out, std::vector<std::string> more = {}) {
    // Full size: a narrow frame shortens the title line to fit, cutting off its end.
    std::vector<std::string> args{"render", scene, "--frames", "0:1", "--out", out, "--quiet"};
    args.insert(args.end(), more.begin(), more.end());
    return runLinkage(args, folder.path()).code;
  };
  ASSERT_EQ(render(shippedScene("default.json"), "set", {"--set", "linkage.L=3.2"}), 0);
  ASSERT_EQ(render("literal.json", "literal"), 0);
  ASSERT_EQ(render("stale.json", "stale"), 0);
  EXPECT_TRUE(readFile(folder.path() / "set/frame_00000.png") == readFile(folder.path() / "literal/frame_00000.png"));
  EXPECT_FALSE(readFile(folder.path() / "set/frame_00000.png") == readFile(folder.path() / "stale/frame_00000.png"));
}

// The rules of docs/hardening.md for the newer commands: standard output checked before exit, a file that cannot
// be written fails the command and leaves nothing.
TEST(EverydayCli, NewerCommandsKeepTheOutputRules) {
  TempFolder folder;
  const std::string linkage = shellQuoted(linkageBinary()), scene = shellQuoted(shippedScene("seam.json"));
  const ProcessResult full = runShell(linkage + " numbers " + scene + " --quiet > /dev/full", folder.path());
  EXPECT_EQ(full.code, 3) << full.err;
  EXPECT_NE(full.err.find("standard output"), std::string::npos) << full.err;
  const ProcessResult file = runShell(linkage + " numbers " + scene + " --quiet > out.json", folder.path());
  EXPECT_EQ(file.code, 0) << file.err;
  writeFile(folder.path() / "plain", "a file, not a folder");  // so the --out below cannot be written, even as root
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"still", shippedScene("seam.json"), "--time", "1", "--size", "160x90", "--out",
                                 "plain/s.png"},
        std::vector<std::string>{"numbers", shippedScene("seam.json"), "--out", "plain/n.json"}}) {
    const ProcessResult refused = runLinkage(args, folder.path());
    EXPECT_NE(refused.code, 0) << args[0];
    EXPECT_NE(refused.err.find("plain/"), std::string::npos) << args[0] << ": " << refused.err;
  }
  EXPECT_EQ(readFile(folder.path() / "plain"), "a file, not a folder");
}

}  // namespace
}  // namespace sl::testing
