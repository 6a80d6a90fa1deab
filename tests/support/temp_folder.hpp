#pragma once
// A fresh, empty folder under the system's temporary directory for one test, removed with everything in it
// when the object goes.

#include <filesystem>
#include <string>

namespace sl::testing {

class TempFolder {
 public:
  TempFolder();
  ~TempFolder();
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // The path of `name` inside the folder, as a string (what most calls take).
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace sl::testing
