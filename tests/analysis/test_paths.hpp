#pragma once
// A fresh, empty folder under the build tree's temporary directory for one test.

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace sl::testing {

inline std::string freshTestFolder(const std::string& name) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto folder = std::filesystem::temp_directory_path() / "sl-analysis-tests" /
                      (std::string(info->test_suite_name()) + "." + info->name() + "." + name);
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder.string();
}

}  // namespace sl::testing
