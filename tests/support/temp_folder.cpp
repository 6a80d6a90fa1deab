#include "support/temp_folder.hpp"

#include <stdlib.h>
#include <cerrno>
#include <system_error>

namespace sl::testing {

TempFolder::TempFolder() {
  // mkdtemp: a name no other test (or concurrent ctest process) can have taken.
  std::string pattern = (std::filesystem::temp_directory_path() / "sl-test-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr)
    throw std::system_error(errno, std::generic_category(), "cannot create a temporary folder " + pattern);
  path_ = pattern;
}

TempFolder::~TempFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace sl::testing
