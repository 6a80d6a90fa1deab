// Charts for papers: --chart-formats svg,pdf writes each chart of geometry, stability and bench also as SVG and
// PDF beside its PNG (and its gnuplot script), and refuses an unknown format before any work.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

void expectSvgAndPdf(const fs::path& png) {
  ASSERT_TRUE(fs::exists(png)) << png;
  EXPECT_TRUE(fs::exists(fs::path(png).replace_extension(".gp"))) << png;
  const std::string svg = readFile(fs::path(png).replace_extension(".svg"));
  EXPECT_NE(svg.find("<svg"), std::string::npos) << png;
  EXPECT_NE(svg.find("</svg>"), std::string::npos) << png;  // whole
  const std::string pdf = readFile(fs::path(png).replace_extension(".pdf"));
  EXPECT_EQ(pdf.rfind("%PDF-", 0), 0u) << png;
  EXPECT_NE(pdf.find("%%EOF"), std::string::npos) << png;
}

TEST(ChartsCli, SvgAndPdfBesideEachPng) {
  TempFolder folder;
  const ProcessResult sweep =
      runLinkage({"geometry", shippedScene("default.json"), "--sweep-L", "2.5:3.5:3", "--csv", "sweep.csv", "--chart",
                  "sweep.png", "--chart-formats", "svg,pdf", "--quiet"},
                 folder.path());
  ASSERT_EQ(sweep.code, 0) << sweep.err;
  EXPECT_NE(sweep.out.find("wrote sweep.svg\nwrote sweep.pdf\n"), std::string::npos) << sweep.out;
  expectSvgAndPdf(folder.path() / "sweep.png");

  const ProcessResult stability = runLinkage({"stability", "--kind", "pole", "--grid", "3", "--methods", "ambient",
                                              "--out", "st", "--chart-formats", "pdf,svg", "--quiet"},
                                             folder.path());
  ASSERT_EQ(stability.code, 0) << stability.err;
  expectSvgAndPdf(folder.path() / "st/stability-pole-ambient.png");

  const ProcessResult bench = runLinkage({"bench", "--quick", "--start", "generic", "--methods", "ambient",
                                          "--integrators", "rk4", "--out", "b", "--chart-formats", "svg,pdf", "--quiet"},
                                         folder.path());
  ASSERT_EQ(bench.code, 0) << bench.err;
  expectSvgAndPdf(folder.path() / "b/wp-generic-error-time.png");
}

TEST(ChartsCli, UnknownFormatIsRefusedBeforeAnyWork) {
  TempFolder folder;
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"geometry", shippedScene("default.json"), "--sweep-L", "2.5:3.5:3", "--csv", "s.csv", "--chart", "s.png",
            "--chart-formats", "svg,eps"},
           {"stability", "--kind", "pole", "--grid", "3", "--out", "st", "--chart-formats", "jpg"},
           {"bench", "--quick", "--out", "b", "--chart-formats", "tiff"}}) {
    const ProcessResult result = runLinkage(args, folder.path());
    EXPECT_EQ(result.code, 2) << args[0] << ": " << result.err;
    EXPECT_NE(result.err.find("--chart-formats: found"), std::string::npos) << result.err;
  }
  EXPECT_TRUE(fs::is_empty(folder.path()));
}

}  // namespace
}  // namespace sl::testing
