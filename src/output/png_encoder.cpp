#include "output/png_encoder.hpp"

#include <libdeflate.h>

#include <cstring>
#include <stdexcept>
#include <string>

namespace sl {
namespace {

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift : {24, 16, 8, 0}) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

// length, type, data, CRC-32 of type + data (PNG specification, section 5.3).
void chunk(std::vector<std::uint8_t>& out, const char type[4], const std::uint8_t* data, std::size_t size) {
  put32(out, static_cast<std::uint32_t>(size));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data, data + size);
  put32(out, libdeflate_crc32(0, out.data() + start, size + 4));
}

}  // namespace

namespace {
constexpr int kSmallLevel = 1;
}

PngEncoder::PngEncoder(PngCompression compression) : compression_(compression) {
  if (compression_ != PngCompression::Small) return;
  compressor_ = libdeflate_alloc_compressor(kSmallLevel);
  if (!compressor_) throw std::runtime_error("libdeflate: cannot create a level 1 compressor");
}

PngEncoder::~PngEncoder() {
  if (compressor_) libdeflate_free_compressor(static_cast<libdeflate_compressor*>(compressor_));
}

std::string PngEncoder::identity(PngCompression compression) {
  if (compression == PngCompression::Fast) return "sphere-linkages fast 1";
  return std::string("libdeflate ") + LIBDEFLATE_VERSION_STRING + " level " + std::to_string(kSmallLevel);
}

std::vector<std::uint8_t> PngEncoder::encode(const Image& image) {
  const std::size_t stride = static_cast<std::size_t>(image.width) * 3;
  if (image.width <= 0 || image.height <= 0 || image.rgb.size() != stride * image.height)
    throw std::invalid_argument("PNG: image buffer does not match " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + " RGB");
  if (compression_ == PngCompression::Fast) return encodeFastPng(image, scratch_);
  filtered_.resize((stride + 1) * image.height);
  for (int y = 0; y < image.height; ++y) {
    std::uint8_t* row = filtered_.data() + y * (stride + 1);
    row[0] = 0;  // filter "none"
    std::memcpy(row + 1, image.rgb.data() + y * stride, stride);
  }
  auto* compressor = static_cast<libdeflate_compressor*>(compressor_);
  std::vector<std::uint8_t> idat(libdeflate_zlib_compress_bound(compressor, filtered_.size()));
  idat.resize(libdeflate_zlib_compress(compressor, filtered_.data(), filtered_.size(), idat.data(), idat.size()));
  if (idat.empty()) throw std::runtime_error("libdeflate: compression failed");

  std::vector<std::uint8_t> png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  png.reserve(idat.size() + 64);
  std::vector<std::uint8_t> header;
  put32(header, static_cast<std::uint32_t>(image.width));
  put32(header, static_cast<std::uint32_t>(image.height));
  header.insert(header.end(), {8, 2, 0, 0, 0});  // 8 bits, truecolour RGB, deflate, adaptive filters, no interlace
  chunk(png, "IHDR", header.data(), header.size());
  chunk(png, "IDAT", idat.data(), idat.size());
  chunk(png, "IEND", nullptr, 0);
  return png;
}

}  // namespace sl
