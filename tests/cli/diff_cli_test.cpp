// `linkage diff`: 0 when the two sides match, 1 when they differ, 2 when they cannot be compared.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

// Changes one hinge coordinate (p2x) of the row of `run` at `time` by `delta`.
void perturb(const std::string& path, const std::string& rowPrefix, double delta) {
  std::string text = readFile(path);
  const size_t row = text.find("\n" + rowPrefix);
  ASSERT_NE(row, std::string::npos);
  const size_t end = text.find('\n', row + 1);
  std::string line = text.substr(row + 1, end - row - 1);
  std::vector<std::string> fields;
  for (size_t start = 0, comma;; start = comma + 1) {
    comma = line.find(',', start);
    fields.push_back(line.substr(start, comma - start));
    if (comma == std::string::npos) break;
  }
  const size_t p2x = 9;  // run,time,phi,t,phidot,tdot,energy,p1x,p1y,p2x
  char number[32];
  std::snprintf(number, sizeof number, "%.17g", std::stod(fields[p2x]) + delta);
  fields[p2x] = number;
  std::string changed;
  for (const std::string& field : fields) changed.append(changed.empty() ? "" : ",").append(field);
  text.replace(row + 1, line.size(), changed);
  writeFile(path, text);
}

TEST(DiffCli, TrajectoryCsvs) {
  TempFolder folder;
  const std::string scene = shippedScene("comparison.json");
  ASSERT_EQ(runLinkage({"simulate", scene, "--csv", "a.csv"}, folder.path()).code, 0);
  ASSERT_EQ(runLinkage({"simulate", scene, "--csv", "b.csv"}, folder.path()).code, 0);
  const ProcessResult same = runLinkage({"diff", "a.csv", "b.csv"}, folder.path());
  EXPECT_EQ(same.code, 0) << same.out << same.err;
  EXPECT_NE(same.out.find("within --tol"), std::string::npos);

  perturb(folder / "b.csv", "embedded (published),1,", 1e-6);
  const ProcessResult changed = runLinkage({"diff", "a.csv", "b.csv", "--tol", "1e-9"}, folder.path());
  EXPECT_EQ(changed.code, 1);
  EXPECT_NE(
      changed.out.find(
          "run \"embedded (published)\": worst hinge difference 1e-06 at t = 1; first exceeds --tol 1e-09 at t = 1"),
      std::string::npos)
      << changed.out;
  EXPECT_NE(changed.out.find("run \"christoffel (published)\": worst hinge difference 0"), std::string::npos);
  EXPECT_EQ(runLinkage({"diff", "a.csv", "b.csv", "--tol", "1e-5"}, folder.path()).code, 0);
  EXPECT_EQ(runLinkage({"diff", "a.csv", "missing.csv"}, folder.path()).code, 2);
  writeFile(folder / "junk.csv", "not,a,trajectory\n");
  EXPECT_EQ(runLinkage({"diff", "a.csv", "junk.csv"}, folder.path()).code, 2);
}

TEST(DiffCli, RenderFolders) {
  TempFolder folder;
  // A small render of `scene` into `out`: frames 0..frames-1 at 160x90.
  const auto render = [&](const std::string& scene, const std::string& out, const std::string& frames = "0:4") {
    return runLinkage({"render", shippedScene(scene), "--out", out, "--size", "160x90", "--frames", frames, "--quiet"},
                      folder.path());
  };
  ASSERT_EQ(render("seam.json", "a").code, 0);
  ASSERT_EQ(render("seam.json", "b").code, 0);
  ASSERT_EQ(render("comparison.json", "c").code, 0);
  const ProcessResult same = runLinkage({"diff", "a", "b"}, folder.path());
  EXPECT_EQ(same.code, 0) << same.out << same.err;
  EXPECT_NE(same.out.find("4 frames vs 4; 0 differ"), std::string::npos) << same.out;
  const ProcessResult other = runLinkage({"diff", "a", "c", "--images", "--image-dir", "pictures"}, folder.path());
  EXPECT_EQ(other.code, 1);
  EXPECT_NE(other.out.find("4 frames vs 4; 4 differ; first differing frame 0"), std::string::npos) << other.out;
  EXPECT_NE(other.out.find("% of pixels differ"), std::string::npos);
  EXPECT_TRUE(fs::exists(folder.path() / "pictures" / "diff_frame_00000.png"));
  // The scene texts named: the same for a and b, different for a and c.
  EXPECT_NE(same.out.find("scene: the same scene text"), std::string::npos) << same.out;
  EXPECT_NE(other.out.find("scene: different scene texts"), std::string::npos) << other.out;
  // A passing comparison into the same image folder leaves no diff image of the earlier one (other files stay).
  writeFile(folder.path() / "pictures" / "notes.txt", "mine");
  const ProcessResult again = runLinkage({"diff", "a", "b", "--image-dir", "pictures"}, folder.path());
  EXPECT_EQ(again.code, 0) << again.err;
  EXPECT_NE(again.err.find("removed 4 diff image(s) of an earlier diff"), std::string::npos) << again.err;
  EXPECT_FALSE(fs::exists(folder.path() / "pictures" / "diff_frame_00000.png"));
  EXPECT_TRUE(fs::exists(folder.path() / "pictures" / "notes.txt"));
  ASSERT_EQ(render("seam.json", "d", "0:3").code, 0);
  const ProcessResult fewer = runLinkage({"diff", "a", "d"}, folder.path());
  EXPECT_EQ(fewer.code, 1);
  EXPECT_NE(fewer.out.find("first differing frame 3"), std::string::npos) << fewer.out;
  EXPECT_EQ(runLinkage({"diff", "a", "nowhere"}, folder.path()).code, 2);
}


// The manifest's meaning (one SHA-256 per PNG file; the encoder in the render's info): folders written by the same
// encoder compare by file hash, by different encoders (fast against small, or a format 1 manifest of an earlier
// version, which listed pixel hashes) by the pixels decoded from the files.
TEST(DiffCli, FoldersOfDifferentEncodersCompareByPixels) {
  TempFolder folder;
  const auto render = [&](const std::string& out, const std::vector<std::string>& extra) {
    std::vector<std::string> args{"render", shippedScene("seam.json"), "--out", out, "--size", "160x90", "--frames", "0:3", "--quiet"};
    args.insert(args.end(), extra.begin(), extra.end());
    return runLinkage(args, folder.path());
  };
  ASSERT_EQ(render("fast", {}).code, 0);
  ASSERT_EQ(render("small", {"--set", "output.png_compression=small"}).code, 0);
  const nlohmann::json fast = nlohmann::json::parse(readFile(folder.path() / "fast" / "manifest.json"));
  const nlohmann::json small = nlohmann::json::parse(readFile(folder.path() / "small" / "manifest.json"));
  EXPECT_EQ(fast.at("info").at("png"), "sphere-linkages fast 1");
  EXPECT_NE(fast.at("info").at("png"), small.at("info").at("png"));
  for (const auto& entry : fast.at("frames")) {
    EXPECT_FALSE(entry.contains("pixelSha256")) << "one hash per PNG frame: " << entry.dump();
    EXPECT_EQ(entry.at("fileSha256").get<std::string>().size(), 64u);
  }
  EXPECT_NE(fast.at("frames")[0].at("fileSha256"), small.at("frames")[0].at("fileSha256"));
  const ProcessResult same = runLinkage({"diff", "fast", "small"}, folder.path());
  EXPECT_EQ(same.code, 0) << same.out << same.err;
  EXPECT_NE(same.out.find("3 frames vs 3; 0 differ"), std::string::npos) << same.out;

  // A format 1 manifest (pixel and file hashes): compared by pixels; a wrong pixel hash is a difference.
  fs::copy(folder.path() / "small", folder.path() / "old", fs::copy_options::recursive);
  nlohmann::json old = small;
  old["format"] = "sphere-linkages frame manifest 1";
  old["info"].erase("png");
  for (auto& entry : old["frames"]) entry["pixelSha256"] = std::string(64, 'a');
  writeFile(folder.path() / "old" / "manifest.json", old.dump(1));
  const ProcessResult wrong = runLinkage({"diff", "old", "fast"}, folder.path());
  EXPECT_EQ(wrong.code, 1) << wrong.out << wrong.err;
  // --resume of a format 1 folder is refused with the reason; a whole render replaces it.
  const ProcessResult resume = runLinkage({"render", shippedScene("seam.json"), "--out", "old", "--size", "160x90",
                                           "--frames", "0:3", "--quiet", "--resume"}, folder.path());
  EXPECT_EQ(resume.code, 3) << resume.err;
  EXPECT_NE(resume.err.find("earlier version"), std::string::npos) << resume.err;
}

// Manifest entries are checked like a scene: an entry without its file is not complete (diff refuses the folder,
// --resume draws the frame again); a frame number out of range or of the wrong type names the file and JSON path.
TEST(DiffCli, ManifestEntriesAreNotTrusted) {
  TempFolder folder;
  const std::vector<std::string> render{"render", shippedScene("seam.json"), "--out", "a", "--size", "160x90", "--frames", "0:3", "--quiet"};
  ASSERT_EQ(runLinkage(render, folder.path()).code, 0);
  fs::copy(folder.path() / "a", folder.path() / "b", fs::copy_options::recursive);
  const fs::path manifestPath = folder.path() / "b" / "manifest.json";
  const nlohmann::json good = nlohmann::json::parse(readFile(manifestPath));

  nlohmann::json stripped = good;
  stripped["frames"][1].erase("file");
  stripped["frames"][1].erase("fileSha256");
  stripped["frames"][1]["pixelSha256"] = std::string(64, '0');
  writeFile(manifestPath, stripped.dump(1));
  fs::remove(folder.path() / "b" / "frame_00001.png");
  const ProcessResult diff = runLinkage({"diff", "a", "b"}, folder.path());
  EXPECT_NE(diff.code, 0) << diff.out;
  EXPECT_NE(diff.err.find("frame 1 is listed without its file"), std::string::npos) << diff.err;
  std::vector<std::string> resume = render;
  resume[3] = "b";
  resume.push_back("--resume");
  const ProcessResult resumed = runLinkage(resume, folder.path());
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  EXPECT_TRUE(fs::exists(folder.path() / "b" / "frame_00001.png")) << "the frame listed without a file is drawn again";
  EXPECT_EQ(runLinkage({"diff", "a", "b"}, folder.path()).code, 0);

  for (const auto& [value, shown] : {std::pair{nlohmann::json(1e12), std::string("1000000000000.0")},
                                     {nlohmann::json("x"), std::string("\"x\"")},
                                     {nlohmann::json(-1), std::string("-1")},
                                     {nlohmann::json(2.5), std::string("2.5")}}) {
    nlohmann::json bad = good;
    bad["frames"][2]["frame"] = value;
    writeFile(manifestPath, bad.dump(1));
    for (const bool viaDiff : {true, false}) {
      const ProcessResult result = viaDiff ? runLinkage({"diff", "a", "b"}, folder.path()) : runLinkage(resume, folder.path());
      EXPECT_EQ(result.code, 2) << shown << ": " << result.err;
      EXPECT_NE(result.err.find("b/manifest.json: frames[2].frame: found " + shown + "; expected an integer"),
                std::string::npos) << result.err;
      EXPECT_EQ(result.err.find("json.exception"), std::string::npos) << result.err;
    }
  }
}

}  // namespace
}  // namespace sl::testing
