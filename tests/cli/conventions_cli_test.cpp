// Command-line conventions: --version, the summary line every command ends with (also when stderr is a pipe,
// as in a cluster job's log), --quiet meaning errors only.
#include <sys/stat.h>

#include <algorithm>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <thread>
#include <thread>

#include <gtest/gtest.h>

#include "render/gl_backend.hpp"
#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

namespace fs = std::filesystem;

TEST(ConventionsCli, VersionNamesVersionCommitCompilerAndGlRenderer) {
  TempFolder folder;
  const ProcessResult version = runLinkage({"--version"}, folder.path());
  ASSERT_EQ(version.code, 0) << version.err;
  EXPECT_EQ(version.out.rfind("linkage 0.", 0), 0u) << version.out;
  EXPECT_NE(version.out.find("(commit "), std::string::npos);
  EXPECT_NE(version.out.find("compiler: "), std::string::npos);
  EXPECT_NE(version.out.find("GL renderer: llvmpipe"), std::string::npos) << version.out;
  // The backends this binary has, the one auto takes first.
  std::string backends;
  for (GlBackend b : builtGlBackends()) backends += (backends.empty() ? "" : ", ") + nameOf(b);
  EXPECT_NE(version.out.find("GL backends: " + backends + "\n"), std::string::npos) << version.out;
  EXPECT_EQ(runLinkage({}, folder.path()).code, 2);  // no command: a usage error, not a silent success
}

// stderr is a pipe here: the summary line must still be there, and --quiet must leave nothing.
TEST(ConventionsCli, SummaryLineOnAPipeAndQuietMeansErrorsOnly) {
  TempFolder folder;
  const std::string seam = shippedScene("seam.json");  // its published run stops: a report a quiet run hides
  const std::vector<std::string> render{"render", seam, "--size", "160x90", "--out", "out"};
  std::vector<std::string> shard = render;
  shard.insert(shard.end(), {"--frames", "100:103"});
  const ProcessResult loud = runLinkage(shard, folder.path());
  ASSERT_EQ(loud.code, 0) << loud.err;
  EXPECT_NE(loud.err.find("linkage render: 3 frames of 160x90 -> out/ (PNG + manifest.json) in "), std::string::npos)
      << loud.err;
  EXPECT_NE(loud.err.find("run \"published\" stopped at t = 0: field-blow-up"), std::string::npos) << loud.err;
  // The summary names the GL backend that drew the frames (auto: EGL's software device where EGL is built).
  const std::string drawnBy = builtGlBackends().size() > 1 && builtGlBackends()[1] == GlBackend::Egl ? "egl" : "osmesa";
  EXPECT_NE(loud.err.find("frames/s, " + drawnBy + "); \"exact\" ran to t = 3.4; \"published\" stopped at t = 0 "
                          "(field-blow-up)"),
            std::string::npos)
      << loud.err;

  shard.push_back("--quiet");
  const ProcessResult quiet = runLinkage(shard, folder.path());
  ASSERT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  EXPECT_EQ(quiet.out, "");

  const ProcessResult geometry = runLinkage({"geometry", shippedScene("default.json"), "--summary"}, folder.path());
  EXPECT_NE(geometry.err.find("geometry: summary"), std::string::npos) << geometry.err;
}

// --set KEY=VALUE: any key by its JSON path, with the file's own checks and path-named messages.
TEST(ConventionsCli, SetOverridesAnySceneKeyAndIsCheckedLikeTheFile) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  const ProcessResult set = runLinkage(
      {"validate", scene, "--set", "linkage.L=3.2", "--set", "output.fps=60", "--set", "view.sphere.color_by=curvature"},
      folder.path());
  ASSERT_EQ(set.code, 0) << set.err;
  EXPECT_NE(set.out.find("L = 3.2, 1201 frames of 1280x720 at 60 fps"), std::string::npos) << set.out;
  const ProcessResult range = runLinkage({"validate", scene, "--set", "linkage.L=5"}, folder.path());
  EXPECT_EQ(range.code, 2);
  EXPECT_NE(range.err.find("linkage.L: found 5"), std::string::npos) << range.err;
  const ProcessResult typo = runLinkage({"validate", scene, "--set", "linkage.LL=3"}, folder.path());
  EXPECT_NE(typo.err.find("linkage.LL: unknown key (did you mean \"L\"?)"), std::string::npos) << typo.err;
  const ProcessResult element = runLinkage({"validate", scene, "--set", "runs[3].step=0.1"}, folder.path());
  EXPECT_NE(element.err.find("--set runs[3].step: expected an existing array element"), std::string::npos)
      << element.err;
  EXPECT_EQ(runLinkage({"validate", scene, "--set", "noequals"}, folder.path()).code, 2);
  // A plain word is a string: the method by name.
  const ProcessResult method = runLinkage({"validate", scene, "--set", "runs[0].method=christoffel"}, folder.path());
  EXPECT_NE(method.out.find("(christoffel, dopri5)"), std::string::npos) << method.out << method.err;
  // Simulate takes it too.
  const ProcessResult simulate =
      runLinkage({"simulate", scene, "--set", "duration=0.5", "--set", "output.fps=4"}, folder.path());
  ASSERT_EQ(simulate.code, 0) << simulate.err;
  EXPECT_EQ(std::count(simulate.out.begin(), simulate.out.end(), '\n'), 1 + 3);
}

// A scene read through a pipe is read once: its identity is its text, so shards of two different piped scenes
// never join one folder.
TEST(ConventionsCli, PipedScenesAreReadOnceAndKeepTheirIdentity) {
  TempFolder folder;
  const auto renderThroughFifo = [&](const std::string& text, const std::string& frames) {
    const fs::path fifo = folder.path() / "scene.fifo";
    fs::remove(fifo);
    EXPECT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::thread writer([&] { writeFile(fifo, text); });
    const ProcessResult result = runLinkage(
        {"render", fifo.string(), "--size", "160x90", "--out", "out", "--frames", frames, "--quiet"}, folder.path());
    writer.join();
    return result;
  };
  const std::string scene = readFile(shippedScene("default.json"));
  ASSERT_EQ(renderThroughFifo(scene, "0:1").code, 0);
  std::string edited = scene;
  edited.replace(edited.find("\"L\": 3.0"), 8, "\"L\": 3.3");
  const ProcessResult other = renderThroughFifo(edited, "1:2");
  EXPECT_EQ(other.code, 2) << other.err;
  EXPECT_NE(other.err.find("out holds another render; what differs: the scene's text"), std::string::npos) << other.err;
  EXPECT_EQ(renderThroughFifo(scene, "1:2").code, 0);  // the same piped scene joins
}

// Video formats by extension; a video path that cannot work is refused by validate and by render before any
// frame is drawn.
TEST(ConventionsCli, VideoPathsAreCheckedUpFrontAndTheFormatFollowsTheExtension) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  fs::create_directories(folder.path() / "existing");
  for (const std::string& bad : std::vector<std::string>{"out", "out.txt", "out/", "existing", "existing/", "/dev/null",
                                 std::string(230, 'v') + ".mp4", "missing-parent/sub/x.mp4x"}) {
    SCOPED_TRACE(bad);
    const ProcessResult validate = runLinkage({"validate", scene, "--set", "output.video=\"" + bad + "\""}, folder.path());
    EXPECT_EQ(validate.code, 2) << validate.out;
    EXPECT_NE(validate.err.find("output.video: found"), std::string::npos) << validate.err;
    const ProcessResult render =
        runLinkage({"render", scene, "--size", "160x90", "--frames", "0:2", "--video", bad, "--out", "frames"},
                   folder.path());
    EXPECT_EQ(render.code, 2);
    EXPECT_NE(render.err.find("--video: found"), std::string::npos) << render.err;
    EXPECT_FALSE(fs::exists(folder.path() / "frames"));
  }
  const ProcessResult odd =
      runLinkage({"render", scene, "--size", "161x91", "--frames", "0:2", "--video", "odd.webm", "--no-png"},
                 folder.path());
  EXPECT_EQ(odd.code, 2);
  EXPECT_NE(odd.err.find("needs an even size"), std::string::npos) << odd.err;
  const ProcessResult gif = runLinkage(
      {"render", scene, "--size", "161x91", "--frames", "0:4", "--video", "clip.GIF", "--no-png", "--video-quality", "small"},
      folder.path());
  ASSERT_EQ(gif.code, 0) << gif.err;
  EXPECT_EQ(readFile(folder.path() / "clip.GIF").substr(0, 6), "GIF89a");
  EXPECT_EQ(runLinkage({"render", scene, "--video", "x.mp4", "--video-quality", "best", "--no-png"}, folder.path()).code,
            2);
}

// Help texts read as documentation: no parser artefacts, defaults in words.
TEST(ConventionsCli, HelpTextsHaveNoParserArtefacts) {
  TempFolder folder;
  for (const char* command : {"render", "simulate", "validate", "diff", "list-methods", "bench", "stability", "geometry"}) {
    SCOPED_TRACE(command);
    const ProcessResult help = runLinkage({command, "--help"}, folder.path());
    EXPECT_EQ(help.code, 0) << help.err;
    for (const char* artefact : {"{false}", "{true}", ":INT", ":FLOAT", ":POSITIVE", " in [", "TEXT="})
      EXPECT_EQ(help.out.find(artefact), std::string::npos) << artefact << " in\n" << help.out;
    EXPECT_NE(help.out.find("xample"), std::string::npos) << "no example in\n" << help.out;
  }
  const ProcessResult stability = runLinkage({"stability", "--help"}, folder.path());
  EXPECT_NE(stability.out.find("--grid INT"), std::string::npos);
  EXPECT_NE(stability.out.find("(default 64)"), std::string::npos) << stability.out;
}

}  // namespace
}  // namespace sl
