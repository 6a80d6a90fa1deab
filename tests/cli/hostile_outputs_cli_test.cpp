// The fourth round of hostile inputs (docs/hardening.md), outputs and the contact sheet: every output of every
// command checked against its inputs and its other outputs and for a writable place before any work; the
// contact sheet reads the manifest through the validated reader, refuses frames changed behind its back, bounds
// its size up front and says when frames are missing.

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/child_process.hpp"
#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

void copyScene(const std::string& name, const fs::path& to) { fs::copy_file(shippedScene(name), to); }

// An output that is an input, or another output, is refused before any work, and the input is left as it was.
TEST(HostileOutputsCli, OutputsNeverReplaceInputsOrEachOther) {
  TempFolder folder;
  copyScene("seam.json", folder.path() / "S.json");
  copyScene("seam.json", folder.path() / "S.png");  // a scene file of any name: still must not write over it
  const std::string scene = readFile(folder.path() / "S.json");
  const ProcessResult numbers = runLinkage({"numbers", "S.json", "--out", "S.json"}, folder.path());
  EXPECT_EQ(numbers.code, 2) << numbers.err;
  EXPECT_NE(numbers.err.find("--out S.json is the same file as the scene"), std::string::npos) << numbers.err;
  EXPECT_EQ(readFile(folder.path() / "S.json"), scene);
  const ProcessResult still = runLinkage({"still", "S.png", "--time", "1", "--out", "./S.png"}, folder.path());
  EXPECT_EQ(still.code, 2) << still.err;
  EXPECT_EQ(readFile(folder.path() / "S.png"), scene);

  ASSERT_EQ(runLinkage({"render", "S.json", "--size", "160x90", "--frames", "0:4", "--out", "F", "--quiet"},
                       folder.path())
                .code,
            0);
  const std::string frame = readFile(folder.path() / "F" / "frame_00002.png");
  const ProcessResult sheet = runLinkage({"contact-sheet", "F", "--out", "F/frame_00002.png"}, folder.path());
  EXPECT_EQ(sheet.code, 2) << sheet.err;
  EXPECT_NE(sheet.err.find("is the same file as frame 2"), std::string::npos) << sheet.err;
  EXPECT_EQ(readFile(folder.path() / "F" / "frame_00002.png"), frame);

  // geometry --maps M writes M/curvature.png with its script M/curvature.gp: --csv there is refused.
  fs::create_directories(folder.path() / "M");
  const ProcessResult maps = runLinkage({"geometry", shippedScene("default.json"), "--grid", "16", "--maps", "M",
                                         "--csv", "M/curvature.gp"},
                                        folder.path());
  EXPECT_EQ(maps.code, 2) << maps.err;
  EXPECT_NE(maps.err.find("--maps M/curvature.gp is the same file as --csv"), std::string::npos) << maps.err;
  EXPECT_FALSE(fs::exists(folder.path() / "M" / "curvature.png"));
}

// An output where nothing can be written (a folder path through a regular file) is refused before the work, naming
// the option, not a temporary file after it; a folder that does not exist yet is created, as for every command.
TEST(HostileOutputsCli, OutputPlacesAreCheckedBeforeTheWork) {
  TempFolder folder;
  const std::string seam = shippedScene("seam.json");
  ASSERT_EQ(runLinkage({"render", seam, "--size", "160x90", "--frames", "0:2", "--out", "F", "--quiet"}, folder.path())
                .code,
            0);
  writeFile(folder.path() / "plain", "a file, not a folder");
  const std::vector<std::vector<std::string>> commands{
      {"numbers", seam, "--out", "plain/n.json"},
      {"still", seam, "--time", "1", "--size", "160x90", "--out", "plain/s.png"},
      {"contact-sheet", "F", "--out", "plain/sheet.png"},
      {"simulate", seam, "--csv", "plain/t.csv"},
  };
  for (const auto& command : commands) {
    const ProcessResult refused = runLinkage(command, folder.path());
    EXPECT_EQ(refused.code, 2) << command[0] << ": " << refused.err;
    EXPECT_NE(refused.err.find("linkage " + command[0] + ": --"), std::string::npos) << refused.err;
    EXPECT_NE(refused.err.find(" plain/"), std::string::npos) << refused.err;
    EXPECT_NE(refused.err.find("is not a directory"), std::string::npos) << command[0] << ": " << refused.err;
    EXPECT_EQ(refused.err.find(".tmp."), std::string::npos) << refused.err;  // not a temporary's name, after the work
  }
  const ProcessResult folderAsFile = runLinkage({"numbers", seam, "--out", "F"}, folder.path());
  EXPECT_EQ(folderAsFile.code, 2);
  EXPECT_NE(folderAsFile.err.find("--out: F exists and is not a regular file (a folder)"), std::string::npos)
      << folderAsFile.err;
  // A folder not there yet is made, as simulate always did.
  EXPECT_EQ(runLinkage({"numbers", seam, "--out", "new/n.json", "--quiet"}, folder.path()).code, 0);
  EXPECT_TRUE(fs::exists(folder.path() / "new" / "n.json"));
}

nlohmann::json readJson(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}
void writeJson(const fs::path& path, const nlohmann::json& json) { std::ofstream(path) << json.dump(1); }

// The contact sheet trusts nothing in the folder it is not given by the render: entries outside the folder, frame
// numbers beyond range, files replaced since, sizes beyond the bound; and it says when frames are missing.
TEST(HostileOutputsCli, ContactSheetTrustsOnlyWhatTheRenderWrote) {
  TempFolder folder;
  ASSERT_EQ(runLinkage({"render", shippedScene("seam.json"), "--size", "160x90", "--frames", "0:6", "--out", "F",
                        "--quiet"},
                       folder.path())
                .code,
            0);
  const fs::path manifestPath = folder.path() / "F" / "manifest.json";
  const nlohmann::json manifest = readJson(manifestPath);
  fs::copy_file(folder.path() / "F" / "frame_00000.png", folder.path() / "other.png");

  nlohmann::json outside = manifest;
  outside["frames"][1]["file"] = "../other.png";
  writeJson(manifestPath, outside);
  ProcessResult sheet = runLinkage({"contact-sheet", "F", "--out", "a.png"}, folder.path());
  EXPECT_EQ(sheet.code, 2) << sheet.err;
  EXPECT_NE(sheet.err.find("frames[1].file"), std::string::npos) << sheet.err;

  nlohmann::json wrapped = manifest;
  wrapped["frames"][1]["frame"] = 2147483648LL;
  writeJson(manifestPath, wrapped);
  sheet = runLinkage({"contact-sheet", "F", "--out", "b.png"}, folder.path());
  EXPECT_EQ(sheet.code, 2) << sheet.err;
  EXPECT_NE(sheet.err.find("frames[1].frame"), std::string::npos) << sheet.err;

  writeJson(manifestPath, manifest);
  fs::copy_file(folder.path() / "F" / "frame_00005.png", folder.path() / "F" / "frame_00003.png",
                fs::copy_options::overwrite_existing);  // replaced behind the manifest's back
  sheet = runLinkage({"contact-sheet", "F", "--out", "c.png"}, folder.path());
  EXPECT_EQ(sheet.code, 2) << sheet.err;
  EXPECT_NE(sheet.err.find("frame_00003.png: is not the frame manifest.json lists"), std::string::npos) << sheet.err;

  // 16 frames of 8192 pixels' width each: a sheet beyond the image bound, refused before anything is decoded.
  sheet = runLinkage({"contact-sheet", "F", "--count", "6", "--columns", "1", "--tile-width", "4096", "--out", "d.png"},
                     folder.path());
  EXPECT_EQ(sheet.code, 2) << sheet.err;
  EXPECT_NE(sheet.err.find("expected at most 8192 on a side"), std::string::npos) << sheet.err;
  for (const char* name : {"a.png", "b.png", "c.png", "d.png"}) EXPECT_FALSE(fs::exists(folder.path() / name)) << name;

  // Frames 0-5 of 301: an unfinished render, said in a warning and the summary; the sheet is still made.
  fs::copy_file(folder.path() / "F" / "frame_00005.png", folder.path() / "F" / "frame_00003.png",
                fs::copy_options::overwrite_existing);
  ASSERT_EQ(runLinkage({"render", shippedScene("seam.json"), "--size", "160x90", "--frames", "3", "--out", "F",
                        "--quiet"},
                       folder.path())
                .code,
            0);  // frame 3 drawn again: the folder is as the render left it
  sheet = runLinkage({"contact-sheet", "F", "--out", "e.png"}, folder.path());
  EXPECT_EQ(sheet.code, 0) << sheet.err;
  EXPECT_NE(sheet.err.find("holds 6 of the render's 301 frames, with gaps"), std::string::npos) << sheet.err;
  EXPECT_NE(sheet.err.find("(frames missing)"), std::string::npos) << sheet.err;
}

// --set values that are not UTF-8 (class 3) are a bad input named as such, exit 2, in validate as in render: they
// ended in an exception's text (exit 3, no option named) or entered the scene.
TEST(HostileOutputsCli, SetValuesThatAreNotUtf8AreRefused) {
  TempFolder folder;
  const std::string seam = shippedScene("seam.json");
  for (const std::string& assignment : {std::string("title=caf\xe9"), std::string("name=\xff\xfe"),
                                       std::string("t\xc3itle=x"), std::string("runs[0].name=\"\xed\xa0\x80\"")}) {
    for (const std::string command : {"validate", "render"}) {
      std::vector<std::string> args{command, seam, "--set", assignment};
      if (command == "render") args.insert(args.end(), {"--size", "160x90", "--frames", "0:1", "--out", "r"});
      const ProcessResult refused = runLinkage(args, folder.path());
      EXPECT_EQ(refused.code, 2) << command << " " << refused.err;
      EXPECT_NE(refused.err.find("--set: found"), std::string::npos) << refused.err;
      EXPECT_NE(refused.err.find("which is not UTF-8 text"), std::string::npos) << refused.err;
    }
  }
  EXPECT_FALSE(fs::exists(folder.path() / "r"));
  EXPECT_EQ(runLinkage({"validate", seam, "--set", "title=café"}, folder.path()).code, 0);
}

// A connect from a shape to itself (class 13) is refused: the shortest "motion" had a length of 1e-14 and left in a
// direction made of rounding noise. Also in `linkage connect --to` and `initial.connect` (the bad scene
// connect_to_itself.json).
TEST(HostileOutputsCli, ConnectFromAShapeToItselfIsRefused) {
  TempFolder folder;
  writeFile(folder.path() / "s.json", R"({"name": "s", "linkage": {"rods": 4, "L": 3.0},
    "initial": {"coords": [0.3, 0.2], "velocity": [0.5, 0.7]}, "duration": 1,
    "runs": [{"name": "a", "method": "ambient", "integrator": "dopri5", "tolerance": 1e-10}]})");
  const ProcessResult itself = runLinkage({"connect", "s.json", "--to", R"({"coords": [0.3, 0.2]})"}, folder.path());
  EXPECT_EQ(itself.code, 2) << itself.out << itself.err;
  EXPECT_NE(itself.err.find("--to: is the start's own shape"), std::string::npos) << itself.err;
  EXPECT_EQ(runLinkage({"connect", "s.json", "--to", R"({"coords": [0.3, 0.25]})", "--quiet"}, folder.path()).code, 0);
}

// Class 5: a start at speed 1.7e6 stopped at t = 0.023 with "step-size-collapse" (the step floor was in time, not
// arc length), one at 1.7e150 at t = 0 with "constraint-rank-loss" for a chain nowhere near a line, and an arrival of
// 1e-300 overflowed the found motion's energy. A fast motion now runs to its end; one that would cover more than
// limits::kMaxHingeTravel rod lengths in its duration, or overflow, is refused before any work by validate and simulate alike.
TEST(HostileOutputsCli, HugeStartSpeedsRunOrAreRefusedWithTheTrueReason) {
  TempFolder folder;
  auto scene = [&](const std::string& velocity, const std::string& duration) {
    writeFile(folder.path() / "fast.json", R"({"name": "fast", "linkage": {"rods": 4, "L": 3.0},
      "initial": {"coords": [0.3, 0.2], "velocity": [)" + velocity + R"(, 0.7]}, "duration": )" + duration + R"(,
      "runs": [{"name": "a", "method": "ambient", "integrator": "dopri5", "tolerance": 1e-10}]})");
  };
  scene("1e6", "0.03");  // 5e4 units of length: past t = 0.023, where it stopped
  const ProcessResult fast = runLinkage({"simulate", "fast.json", "--csv", "fast.csv"}, folder.path());
  EXPECT_EQ(fast.code, 0) << fast.err;
  EXPECT_NE(fast.err.find("\"a\" ran to t = 0.03"), std::string::npos) << fast.err;
  for (const char* velocity : {"1e10", "1e150"}) {
    scene(velocity, "1");
    for (const char* command : {"validate", "simulate"}) {
      const ProcessResult refused = runLinkage({command, "fast.json"}, folder.path());
      EXPECT_EQ(refused.code, 2) << command << " " << velocity << ": " << refused.err;
      EXPECT_NE(refused.err.find("fast.json: initial: the start moves the hinges at"), std::string::npos) << refused.err;
      EXPECT_NE(refused.err.find("expected at most 1e+06"), std::string::npos) << refused.err;
      EXPECT_EQ(refused.err.find("constraint-rank-loss"), std::string::npos) << refused.err;
    }
  }
  const ProcessResult overflow = runLinkage(
      {"validate", shippedScene("connect.json"), "--set", "initial.connect.arrival=1e-300"}, folder.path(), 120);
  EXPECT_EQ(overflow.code, 2) << overflow.err;
  EXPECT_NE(overflow.err.find("the kinetic energy overflows; expected a later arrival"), std::string::npos)
      << overflow.err;
}

// The searches before any work (closed geodesics, connect; class 6) answer SIGTERM between their shots: periodic
// up to length 200 takes about two minutes and ran to its end, then exited 0; connect exited 143 (no handler).
TEST(HostileOutputsCli, SearchesAnswerSigterm) {
  TempFolder folder;
  ChildProcess periodic(linkageBinary(), {"periodic", shippedScene("default.json"), "--max-length", "200"},
                        folder.path());
  while (periodic.running() && !catchesSignal(periodic.pid(), SIGTERM))  // events only: no deadline
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  periodic.sendSignal(SIGTERM);
  const ProcessResult stopped = periodic.wait();
  EXPECT_EQ(stopped.code, 130) << stopped.err;
  EXPECT_NE(stopped.err.find("stopped by SIGTERM"), std::string::npos) << stopped.err;
  EXPECT_EQ(stopped.out, "");
}

// connect's third route (each motion shot again with a method) answers too: 16 of 18 motions, about ten seconds
// of embedded-fd shots, are left when the first progress line is out (the event; route 3 ignored SIGTERM).
TEST(HostileOutputsCli, ConnectsThirdRouteAnswersSigterm) {
  TempFolder folder;
  ChildProcess connect(linkageBinary(),
                       {"connect", shippedScene("default.json"), "--to", R"({"coords": [-0.6, 2.2]})", "--max-length",
                        "16", "--method", "embedded-fd"},
                       folder.path());
  while (connect.running() && connect.errSoFar().find("method shot") == std::string::npos)  // events only
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  connect.sendSignal(SIGTERM);
  const ProcessResult stopped = connect.wait();
  EXPECT_EQ(stopped.code, 130) << stopped.err;
  EXPECT_NE(stopped.err.find("stopped by SIGTERM"), std::string::npos) << stopped.err;
  EXPECT_EQ(stopped.out, "");
}

}  // namespace
}  // namespace sl::testing
