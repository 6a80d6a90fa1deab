// The GL backend chosen at run time (--gl, LINKAGE_GL; docs/rendering.md, "GL backends"): EGL's software device
// and OSMesa draw the same bytes, every manifest names its backend and renderer, and a folder of frames drawn by
// another renderer (llvmpipe generating code for another CPU) is never joined.

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "render/gl_backend.hpp"
#include "support/child_process.hpp"
#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

bool built(GlBackend backend) {
  for (GlBackend b : builtGlBackends())
    if (b == backend) return true;
  return false;
}

nlohmann::json manifestOf(const fs::path& folder) {
  std::ifstream in(folder / "manifest.json");
  return nlohmann::json::parse(in);
}

// Every shipped scene, a few frames spread over it (2 frames a second of its time, every 7th: the camera turning,
// paths and plots growing), through EGL and through OSMesa: the same files, frame for frame.
TEST(GlBackendCli, EglAndOsMesaDrawTheSameBytesForEveryShippedScene) {
  if (!built(GlBackend::Egl) || !built(GlBackend::OsMesa)) GTEST_SKIP() << "needs both backends built";
  TempFolder folder;
  int scenes = 0;
  for (const auto& entry : fs::directory_iterator(sourcePath("scenes"))) {
    if (entry.path().extension() != ".json" || entry.path().filename() == "scene.schema.json") continue;
    const std::string name = entry.path().stem().string();
    std::vector<nlohmann::json> frames;
    for (const std::string backend : {"egl", "osmesa"}) {
      const std::string out = name + "-" + backend;
      const ProcessResult render =
          runLinkage({"render", entry.path().string(), "--size", "640x360", "--set", "output.fps=2", "--frames",
                      "0::7", "--gl", backend, "--threads", "1", "--out", out, "--quiet"},
                     folder.path());
      ASSERT_EQ(render.code, 0) << name << " " << backend << ": " << render.err;
      const nlohmann::json manifest = manifestOf(folder.path() / out);
      EXPECT_EQ(manifest.at("backends"), nlohmann::json::array({backend})) << name;
      ASSERT_EQ(manifest.at("renderers").size(), 1u) << name;
      EXPECT_NE(manifest.at("renderers")[0].get<std::string>().find("llvmpipe"), std::string::npos);
      EXPECT_NE(manifest.at("renderers")[0].get<std::string>().find(" | cpu "), std::string::npos);
      frames.push_back(manifest.at("frames"));
    }
    ASSERT_GE(frames[0].size(), 2u) << name;
    EXPECT_EQ(frames[0], frames[1]) << name << ": EGL and OSMesa drew different bytes";
    ++scenes;
  }
  EXPECT_GE(scenes, 17);
}

// The option wins over LINKAGE_GL; LINKAGE_GL over auto; auto takes EGL where it is built. The summary line and
// the manifest say which drew.
TEST(GlBackendCli, OptionThenEnvironmentThenAuto) {
  TempFolder folder;
  const std::string render = shellQuoted(linkageBinary()) + " render " + shellQuoted(shippedScene("seam.json")) +
                             " --size 160x90 --frames 0:2 --threads 1 --out ";
  const std::string first = built(GlBackend::Egl) ? "egl" : "osmesa";
  const ProcessResult automatic = runShell(render + "auto", folder.path());
  ASSERT_EQ(automatic.code, 0) << automatic.err;
  EXPECT_EQ(manifestOf(folder.path() / "auto").at("backends"), nlohmann::json::array({first}));
  EXPECT_NE(automatic.err.find("frames/s, " + first + ")"), std::string::npos) << automatic.err;
  if (!built(GlBackend::Egl) || !built(GlBackend::OsMesa)) return;
  const ProcessResult environment = runShell("LINKAGE_GL=osmesa " + render + "env", folder.path());
  ASSERT_EQ(environment.code, 0) << environment.err;
  EXPECT_EQ(manifestOf(folder.path() / "env").at("backends"), nlohmann::json::array({"osmesa"}));
  const ProcessResult option = runShell("LINKAGE_GL=osmesa " + render + "option --gl egl", folder.path());
  ASSERT_EQ(option.code, 0) << option.err;
  EXPECT_EQ(manifestOf(folder.path() / "option").at("backends"), nlohmann::json::array({"egl"}));
  EXPECT_EQ(manifestOf(folder.path() / "env").at("frames"), manifestOf(folder.path() / "option").at("frames"));
}

TEST(GlBackendCli, UnusableChoicesAreRefusedWithTheirSource) {
  TempFolder folder;
  const std::string render = shellQuoted(linkageBinary()) + " render " + shellQuoted(shippedScene("seam.json")) +
                             " --size 160x90 --frames 0:1 --out r";
  const ProcessResult environment = runShell("LINKAGE_GL=vulkan " + render, folder.path());
  EXPECT_EQ(environment.code, 2) << environment.err;
  EXPECT_NE(environment.err.find("LINKAGE_GL: found \"vulkan\"; expected one of auto, egl, egl-gpu, osmesa"),
            std::string::npos)
      << environment.err;
  const ProcessResult option = runShell(render + " --gl vulkan", folder.path());
  EXPECT_EQ(option.code, 2) << option.err;
  EXPECT_NE(option.err.find("--gl"), std::string::npos) << option.err;
  EXPECT_FALSE(fs::exists(folder.path() / "r"));
  for (GlBackend missing : {GlBackend::OsMesa, GlBackend::Egl}) {
    if (built(missing)) continue;
    const ProcessResult refused = runShell(render + " --gl " + nameOf(missing), folder.path());
    EXPECT_EQ(refused.code, 2) << refused.err;
    EXPECT_NE(refused.err.find("built without " + nameOf(missing)), std::string::npos) << refused.err;
  }
}

// A GPU only when asked for, and where there is none a clear failure, nothing written: never a silent fall back
// to llvmpipe (whose pixels differ from a GPU's).
TEST(GlBackendCli, AGpuAskedForWhereThereIsNoneFailsClearly) {
  if (!built(GlBackend::EglGpu)) GTEST_SKIP() << "built without EGL";
  TempFolder folder;
  const ProcessResult gpu = runLinkage({"still", shippedScene("seam.json"), "--time", "1", "--size", "160x90",
                                        "--gl", "egl-gpu", "--out", "gpu.png"},
                                       folder.path());
  if (gpu.code == 0) {  // a machine with a GPU: it drew, through it
    EXPECT_NE(gpu.err.find("(egl-gpu)"), std::string::npos) << gpu.err;
    return;
  }
  EXPECT_EQ(gpu.code, 3) << gpu.err;
  EXPECT_NE(gpu.err.find("egl-gpu: none of EGL's"), std::string::npos) << gpu.err;
  EXPECT_FALSE(fs::exists(folder.path() / "gpu.png"));
}

// Shards drawn by llvmpipe generating code for different CPUs (emulated here by Mesa's own switch: a CPU without
// AVX, whose frames differ from this machine's by a level or two on a few pixels) are not merged into one folder:
// the second is refused before it draws, naming both renderers.
TEST(GlBackendCli, ShardsOfAnotherRendererAreNotJoined) {
  TempFolder folder;
  const std::string shard = shellQuoted(linkageBinary()) + " render " + shellQuoted(shippedScene("default.json")) +
                            " --size 160x90 --threads 1 --out r --frames ";
  const ProcessResult first = runShell(shard + "0:3", folder.path());
  ASSERT_EQ(first.code, 0) << first.err;
  const std::string noAvx = "GALLIUM_OVERRIDE_CPU_CAPS=sse4.1 ";
  const ProcessResult narrower = runShell(noAvx + shard + "3:6", folder.path());
  EXPECT_EQ(narrower.code, 3) << narrower.err;
  EXPECT_NE(narrower.err.find("holds frames drawn by llvmpipe"), std::string::npos) << narrower.err;
  EXPECT_NE(narrower.err.find("GALLIUM_OVERRIDE_CPU_CAPS=sse4.1"), std::string::npos) << narrower.err;
  EXPECT_FALSE(fs::exists(folder.path() / "r" / "frame_00003.png"));
  EXPECT_EQ(manifestOf(folder.path() / "r").at("frames").size(), 3u);
  // The same renderer joins, and --resume too.
  const ProcessResult same = runShell(shard + "3:6", folder.path());
  ASSERT_EQ(same.code, 0) << same.err;
  EXPECT_EQ(manifestOf(folder.path() / "r").at("frames").size(), 6u);
  EXPECT_EQ(manifestOf(folder.path() / "r").at("renderers").size(), 1u);
  const ProcessResult resumed = runShell(noAvx + shard + "0:6 --resume", folder.path());
  EXPECT_EQ(resumed.code, 3) << resumed.err;
  // --replace takes the folder over, as a whole render does: the other renderer's frames go first.
  const ProcessResult replaced = runShell(noAvx + shard + "0:2 --replace", folder.path());
  ASSERT_EQ(replaced.code, 0) << replaced.err;
  EXPECT_EQ(manifestOf(folder.path() / "r").at("frames").size(), 2u);
  EXPECT_FALSE(fs::exists(folder.path() / "r" / "frame_00005.png"));
  EXPECT_NE(manifestOf(folder.path() / "r").at("renderers")[0].get<std::string>().find("GALLIUM_OVERRIDE_CPU_CAPS"),
            std::string::npos);
}

// GL set-up failures are reported, never a signal: under an address-space limit (ulimit -v, as batch systems set)
// llvmpipe's shader compiler crashed (SIGSEGV) in still, render --threads 1 and render --video.
TEST(GlBackendCli, AnAddressSpaceLimitIsNamedNotACrash) {
  TempFolder folder;
  const std::string seam = shellQuoted(shippedScene("seam.json"));
  const std::string linkage = shellQuoted(linkageBinary());
  for (const std::string& command :
       {linkage + " still " + seam + " --time 1 --size 160x90 --out s.png",
        linkage + " render " + seam + " --size 160x90 --frames 0:2 --threads 1 --out r",
        linkage + " render " + seam + " --size 160x90 --frames 0:2 --video v.mp4 --no-png"}) {
    for (const char* kilobytes : {"300000", "450000"}) {
      const ProcessResult limited = runShell(std::string("ulimit -v ") + kilobytes + " && " + command, folder.path());
      EXPECT_EQ(limited.signal, 0) << command;
      EXPECT_EQ(limited.code, 3) << command << ": " << limited.err;
      EXPECT_NE(limited.err.find("the address-space limit (ulimit -v"), std::string::npos) << limited.err;
    }
  }
  EXPECT_FALSE(fs::exists(folder.path() / "s.png"));
  EXPECT_FALSE(fs::exists(folder.path() / "v.mp4"));
  EXPECT_FALSE(fs::exists(folder.path() / "r" / "frame_00000.png"));
}

}  // namespace
}  // namespace sl::testing
