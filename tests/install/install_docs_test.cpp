// The installed documentation: the README's links resolve beside it (share/doc/linkage/), and the man page made
// from the help texts is installed with the binary.
#include <filesystem>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "install_prefix.hpp"
#include "support/child_process.hpp"
#include "support/files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

TEST(InstallDocs, ReadmeLinksResolveAndTheManPageIsInstalled) {
  TempFolder temp;
  const fs::path prefix = temp.path() / "prefix";
  const ProcessResult install = installInto(prefix, temp.path());
  ASSERT_EQ(install.code, 0) << install.out << install.err;
  const fs::path doc = prefix / "share" / "doc" / "linkage";
  const std::string readme = readFile(doc / "README.md");
  ASSERT_FALSE(readme.empty());
  int links = 0;
  const std::regex link(R"(\]\(([^)#\s]+)(#[^)]*)?\))");
  for (auto it = std::sregex_iterator(readme.begin(), readme.end(), link); it != std::sregex_iterator(); ++it) {
    const std::string target = (*it)[1];
    if (target.find("://") != std::string::npos) continue;  // a web address
    ++links;
    EXPECT_TRUE(fs::exists(doc / target)) << "the installed README links to " << target << ", not installed";
  }
  EXPECT_GT(links, 10);

  const fs::path man = prefix / "share" / "man" / "man1" / "linkage.1";
  ASSERT_TRUE(fs::exists(man)) << "no man page (linkage --man, written when linkage is linked)";
  const std::string page = readFile(man);
  EXPECT_NE(page.find(".TH LINKAGE \"1\""), std::string::npos) << page.substr(0, 400);
  for (const char* command : {"render", "still", "contact\\-sheet", "diff", "numbers", "validate"})  // roff escapes -
    EXPECT_NE(page.find(command), std::string::npos) << command << " missing from the man page";
  EXPECT_NE(page.find("\\-\\-pixel\\-tol"), std::string::npos);  // subcommands' options too
  const ProcessResult shown = runShell("man -l " + shellQuoted(man.string()) + " > /dev/null", temp.path());
  EXPECT_EQ(shown.code, 0) << shown.err;
  // A man page's sections, each command under COMMANDS with its examples, and roff that groff reads without a
  // warning (help2man listed the commands as options and ran the examples together into one paragraph).
  for (const char* section : {".SH NAME", ".SH SYNOPSIS", ".SH COMMANDS", ".SH EXIT STATUS", ".SH ENVIRONMENT",
                              ".SH FILES", ".SH EXAMPLES", ".SS \"linkage render\"", ".SS \"linkage connect\"",
                              "LINKAGE_LOCK_WAIT", ".B 130"})
    EXPECT_NE(page.find(section), std::string::npos) << section;
  EXPECT_NE(page.find(".nf\n  linkage render scenes/default.json\n  linkage render scenes/comparison.json"),
            std::string::npos)
      << "render's examples as literal lines";
  const ProcessResult lint = runShell("groff -man -ww -z " + shellQuoted(man.string()), temp.path());
  EXPECT_EQ(lint.code, 0) << lint.err;
  EXPECT_EQ(lint.err, "") << "groff warns of the man page";
}

}  // namespace
}  // namespace sl::testing
