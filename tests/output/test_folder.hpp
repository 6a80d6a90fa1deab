#pragma once
// A fresh empty folder per test under the system temporary directory, removed afterwards.

#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

namespace sl::output::testing {

inline std::string freshFolder() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto path = std::filesystem::temp_directory_path() / ("sl_output_" + std::string(info->test_suite_name()) +
                                                              "_" + info->name() + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(path);
  std::filesystem::create_directories(path);
  return path.string();
}

}  // namespace sl::output::testing
