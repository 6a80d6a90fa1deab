// Installing: `cmake --install` puts `linkage` and the shipped scenes on a prefix; the binary needs nothing
// from the source or build trees (no path to them inside it), so the prefix can be moved and still renders
// frames byte-identical to the build tree's. The Debian package builds and names its run-time dependencies.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "install_prefix.hpp"
#include "support/child_process.hpp"
#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

TEST(Install, MovedPrefixRendersTheSameBytesAsTheBuildTree) {
  TempFolder temp;
  const fs::path prefix = temp.path() / "prefix";
  const ProcessResult install = installInto(prefix, temp.path());
  ASSERT_EQ(install.code, 0) << install.out << install.err;
  // Moved: a cluster node or another user's prefix has none of the paths the build knew.
  const fs::path moved = temp.path() / "elsewhere";
  fs::rename(prefix, moved);
  const fs::path binary = moved / "bin" / "linkage";
  ASSERT_TRUE(fs::exists(binary));
  const fs::path scene = moved / "share" / "sphere-linkages" / "scenes" / "curvature.json";
  ASSERT_TRUE(fs::exists(scene));
  ASSERT_TRUE(fs::exists(moved / "share" / "sphere-linkages" / "scenes" / "README.md"));

  // No path into the source or build tree inside the binary.
  const std::string bytes = readFile(binary);
  EXPECT_EQ(bytes.find(SL_SOURCE_DIR), std::string::npos) << "the installed binary names the source tree";
  EXPECT_EQ(bytes.find(SL_BUILD_DIR), std::string::npos) << "the installed binary names the build tree";

  const std::vector<std::string> render{"render", scene.string(), "--size", "320x180", "--frames", "0:4", "--quiet"};
  std::vector<std::string> installed = render, built = render;
  installed.insert(installed.end(), {"--out", "installed"});
  built.insert(built.end(), {"--out", "built"});
  const ProcessResult a = runProcess(binary.string(), installed, temp.path());
  ASSERT_EQ(a.code, 0) << a.err;
  const ProcessResult b = runLinkage(built, temp.path());
  ASSERT_EQ(b.code, 0) << b.err;
  for (int k = 0; k < 4; ++k) {
    const std::string name = "frame_0000" + std::to_string(k) + ".png";
    EXPECT_EQ(readFile(temp.path() / "installed" / name), readFile(temp.path() / "built" / name)) << name;
  }
  EXPECT_EQ(readFile(temp.path() / "installed" / "manifest.json"), readFile(temp.path() / "built" / "manifest.json"));
}

TEST(Install, DebianPackageCarriesTheProgramScenesAndRunTimeDependencies) {
  TempFolder temp;
  const ProcessResult cpack = runShell("cd " + shellQuoted(SL_BUILD_DIR) + " && " + SL_CPACK_COMMAND + " -G DEB -B " +
                                           shellQuoted(temp.path().string()),
                                       temp.path(), 600);
  ASSERT_EQ(cpack.code, 0) << cpack.out << cpack.err;
  std::string deb;
  for (const auto& entry : fs::directory_iterator(temp.path()))
    if (entry.path().extension() == ".deb") deb = entry.path().string();
  ASSERT_FALSE(deb.empty()) << cpack.out;
  EXPECT_EQ(fs::path(deb).filename().string().rfind("linkage_", 0), 0u) << deb;
  const ProcessResult depends = runShell("dpkg-deb -f " + shellQuoted(deb) + " Depends", temp.path());
  ASSERT_EQ(depends.code, 0) << depends.err;
  std::vector<std::string> packages{"ffmpeg", "fonts-dejavu-core", "gnuplot", "libdeflate0", "libc6"};
  // The GL backends built (SL_GL_BACKENDS: "egl,osmesa"): the libraries linked and, for EGL, Mesa's vendor and
  // driver that libEGL loads at run time.
  const std::string backends = SL_GL_BACKENDS;
  if (backends.find("egl") != std::string::npos) packages.insert(packages.end(), {"libegl1", "libegl-mesa0", "libgl1-mesa-dri"});
  if (backends.find("osmesa") != std::string::npos) packages.push_back("libosmesa6");
  else EXPECT_EQ(depends.out.find("libosmesa6"), std::string::npos) << "a build without OSMesa depends on it";
  for (const std::string& package : packages)
    EXPECT_NE(depends.out.find(package), std::string::npos) << package << " missing from Depends: " << depends.out;
  const ProcessResult contents = runShell("dpkg-deb -c " + shellQuoted(deb), temp.path());
  ASSERT_EQ(contents.code, 0) << contents.err;
  EXPECT_NE(contents.out.find("./usr/bin/linkage"), std::string::npos) << contents.out;
  EXPECT_NE(contents.out.find("./usr/share/sphere-linkages/scenes/default.json"), std::string::npos);
  EXPECT_NE(contents.out.find("./usr/share/doc/linkage/LICENSE"), std::string::npos);
  EXPECT_NE(contents.out.find("./usr/share/doc/linkage/docs/guide.md"), std::string::npos);
  EXPECT_NE(contents.out.find("./usr/share/man/man1/linkage.1"), std::string::npos);
}

}  // namespace
}  // namespace sl::testing
