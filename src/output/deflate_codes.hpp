#pragma once
// The pieces of deflate (RFC 1951) the fast PNG writer (output/fast_png.cpp) builds its blocks from: the length
// codes of runs, Huffman code lengths and canonical codes, and a bit writer.

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>

namespace sl::detail {

constexpr int kMinRun = 3, kMaxRun = 258;
constexpr int kRunStart = 8;  // repeats that start a run (a run's rest after cuts of 258 may be shorter)
constexpr int kLitLenSymbols = 286, kEndOfBlock = 256;

// Length symbols 257..285: first length and extra bits (RFC 1951, section 3.2.5).
constexpr std::array<int, 29> kLengthBase{3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                          31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr std::array<int, 29> kLengthExtra{0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                           2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};

struct LengthCode {
  int symbol = 0, extraBits = 0, extraValue = 0;
};

constexpr std::array<LengthCode, kMaxRun + 1> makeLengthCodes() {
  std::array<LengthCode, kMaxRun + 1> codes{};
  for (int length = kMinRun; length <= kMaxRun; ++length) {
    int i = length == kMaxRun ? 28 : 27;
    while (kLengthBase[i] > length) --i;
    codes[length] = {257 + i, kLengthExtra[i], length - kLengthBase[i]};
  }
  return codes;
}
constexpr std::array<LengthCode, kMaxRun + 1> kLengthCodes = makeLengthCodes();

// Least-significant-bit-first writer into memory sized in advance plus 8 bytes of slack: every put stores eight
// bytes and moves on by the whole bytes filled, so there is no branch (at most 7 + 57 bits are ever pending).
class BitWriter {
 public:
  explicit BitWriter(std::uint8_t* out) : out_(out) {}
  void put(std::uint64_t bits, int count) {  // count <= 57: the 7 bits still pending and these fit the buffer
    buffer_ |= bits << filled_;
    filled_ += count;
    if constexpr (std::endian::native == std::endian::little) {
      std::memcpy(out_, &buffer_, 8);
    } else {
      for (int k = 0; k < 8; ++k) out_[k] = static_cast<std::uint8_t>(buffer_ >> (8 * k));
    }
    const int bytes = filled_ >> 3;
    out_ += bytes;
    buffer_ >>= 8 * bytes;
    filled_ &= 7;
  }
  const std::uint8_t* position() const { return out_; }
  std::uint8_t* finish() {  // the last byte padded with zeros (already stored by put)
    return out_ + (filled_ > 0 ? 1 : 0);
  }

 private:
  std::uint8_t* out_;
  std::uint64_t buffer_ = 0;
  int filled_ = 0;
};

// Huffman code lengths for the counts, none longer than `limit`; a complete code (Kraft sum 1), as zlib's
// inflate requires. One used symbol gets a partner of the same length. Longer than `limit`: the counts are
// halved (rounded up, so a used symbol stays used) and the code built again.
void huffmanLengths(const std::uint32_t* counts, int symbols, int limit, std::uint8_t* lengths);

// Canonical codes for the lengths (RFC 1951, section 3.2.2), bit-reversed: deflate sends a code's first bit first
// and the bit writer fills from the least significant bit.
void canonicalCodes(const std::uint8_t* lengths, int symbols, std::uint32_t* codes);

}  // namespace sl::detail
