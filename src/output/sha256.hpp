#pragma once
// SHA-256 as lowercase hex, by OpenSSL's libcrypto.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace sl {

std::string sha256Hex(const std::uint8_t* data, std::size_t size);
inline std::string sha256Hex(const std::vector<std::uint8_t>& bytes) { return sha256Hex(bytes.data(), bytes.size()); }
// Of a file's contents; empty string if it cannot be read.
std::string sha256OfFile(const std::string& path);

}  // namespace sl
