// Atomic writes: a reader never sees a partial file under the final name, and no temporary is left.

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <string>
#include <thread>

#include "output/atomic_file.hpp"
#include "support/files.hpp"
#include "support/temp_folder.hpp"

namespace sl {
namespace {

TEST(AtomicFile, ReadersSeeOnlyWholeFiles) {
  const testing::TempFolder folder;
  const std::string path = folder / "frame.png";
  const std::vector<std::uint8_t> a(3 << 20, 'a'), b(1 << 20, 'b');  // 3 MiB and 1 MiB
  const std::string aBytes(a.begin(), a.end()), bBytes(b.begin(), b.end());
  writeFileAtomically(path, a);
  std::atomic<bool> done{false};
  std::thread writer([&] {
    for (int k = 0; k < 40; ++k) writeFileAtomically(path, k % 2 ? a : b);
    done = true;
  });
  int reads = 0;
  while (!done) {
    const std::string seen = testing::readFile(path);
    ASSERT_TRUE(seen == aBytes || seen == bBytes) << "a reader saw " << seen.size() << " bytes";
    ++reads;
  }
  writer.join();
  EXPECT_GT(reads, 0);
  for (const auto& entry : std::filesystem::directory_iterator(folder.path()))
    EXPECT_EQ(entry.path().filename(), "frame.png") << "left behind: " << entry.path();
}

TEST(AtomicFile, UnwritableFolderNamesThePath) {
  try {
    writeFileAtomically("/nonexistent/folder/frame.png", std::string("x"));
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/folder/frame.png"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sl
