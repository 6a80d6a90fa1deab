#pragma once
// Whole files as strings, for tests that compare bytes or parse what a program wrote.

#include <filesystem>
#include <map>
#include <string>

namespace sl::testing {

// The file's bytes; empty if it cannot be read (the comparison that follows then fails, naming the file).
std::string readFile(const std::filesystem::path& path);
// Replaces the file's content; throws std::runtime_error if it cannot be written.
void writeFile(const std::filesystem::path& path, const std::string& bytes);
// Every regular file under a folder, by path relative to it, with its bytes.
std::map<std::string, std::string> folderContents(const std::filesystem::path& folder);

}  // namespace sl::testing
