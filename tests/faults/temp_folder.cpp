#include "temp_folder.hpp"

#include <stdlib.h>
#include <stdexcept>

namespace sl::faults {

TempFolder::TempFolder() {
  std::string pattern = (std::filesystem::temp_directory_path() / "sl-faults-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot create a temporary folder");
  path_ = pattern;
}

TempFolder::~TempFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace sl::faults
