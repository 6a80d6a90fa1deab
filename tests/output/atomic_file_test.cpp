// Atomic writes: a reader never sees a partial file under the final name, and no temporary is left.

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

#include "output/atomic_file.hpp"
#include "test_folder.hpp"

namespace sl::output {
namespace {

std::vector<std::uint8_t> readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(AtomicFile, ReadersSeeOnlyWholeFiles) {
  const std::string folder = testing::freshFolder();
  const std::string path = folder + "/frame.png";
  const std::vector<std::uint8_t> a(3 << 20, 'a'), b(1 << 20, 'b');  // 3 MiB and 1 MiB
  writeFileAtomically(path, a);
  std::atomic<bool> done{false};
  std::thread writer([&] {
    for (int k = 0; k < 40; ++k) writeFileAtomically(path, k % 2 ? a : b);
    done = true;
  });
  int reads = 0;
  while (!done) {
    const auto seen = readAll(path);
    ASSERT_TRUE(seen == a || seen == b) << "a reader saw " << seen.size() << " bytes";
    ++reads;
  }
  writer.join();
  EXPECT_GT(reads, 0);
  for (const auto& entry : std::filesystem::directory_iterator(folder))
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
}  // namespace sl::output
