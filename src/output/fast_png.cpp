#include "output/fast_png.hpp"

#include <libdeflate.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <utility>

#include "output/deflate_codes.hpp"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define SL_FAST_PNG_X86 1
#endif

namespace sl {
namespace {

using namespace detail;  // the deflate pieces (output/deflate_codes.hpp)

// === The byte-level work, twice: portable and AVX2. Both compute exactly the same results.

void filterUpPortable(std::uint8_t* out, const std::uint8_t* row, const std::uint8_t* above, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<std::uint8_t>(row[i] - above[i]);
}

// Bit j of words (word j / 64, bit j % 64) says whether p[j] repeats p[j - 1], for j in [0, count): p[-1] must be
// readable. Whole words are assigned; the bits of a last partial word are or-ed into it (the caller zeroes it).
void equalMaskPortable(const std::uint8_t* p, std::size_t count, std::uint64_t* words) {
  std::size_t j = 0;
  if constexpr (std::endian::native == std::endian::little) {
    // Eight bytes at a time: a byte of x is zero where the two loads agree.
    constexpr std::uint64_t low7 = 0x7F7F7F7F7F7F7F7Full, high = 0x8080808080808080ull;
    for (; j + 64 <= count; j += 64) {
      std::uint64_t word = 0;
      for (std::size_t k = 0; k < 64; k += 8) {
        std::uint64_t a, b;
        std::memcpy(&a, p + j + k, 8);
        std::memcpy(&b, p + j + k - 1, 8);
        const std::uint64_t x = a ^ b;
        const std::uint64_t nonzero = (((x & low7) + low7) | x) & high;  // exact: no carries between bytes
        const std::uint64_t equal = (~nonzero & high) >> 7;               // 1 in the lowest bit of each equal byte
        word |= ((equal * 0x0102040810204080ull) >> 56) << k;             // gathers them: bit k + m for byte m
      }
      words[j / 64] = word;
    }
  }
  for (; j < count; ++j)
    if (p[j] == p[j - 1]) words[j / 64] |= std::uint64_t{1} << (j % 64);
}

#ifdef SL_FAST_PNG_X86
__attribute__((target("avx2"))) void filterUpAvx2(std::uint8_t* out, const std::uint8_t* row,
                                                   const std::uint8_t* above, std::size_t n) {
  std::size_t i = 0;
  for (; i + 32 <= n; i += 32) {
    const __m256i a = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(row + i));
    const __m256i b = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(above + i));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + i), _mm256_sub_epi8(a, b));
  }
  filterUpPortable(out + i, row + i, above + i, n - i);
}

__attribute__((target("avx2"))) void equalMaskAvx2(const std::uint8_t* p, std::size_t count, std::uint64_t* words) {
  std::size_t j = 0;
  for (; j + 64 <= count; j += 64) {
    const auto* a = reinterpret_cast<const __m256i*>(p + j);
    const auto* b = reinterpret_cast<const __m256i*>(p + j - 1);
    const auto lowBits = static_cast<std::uint32_t>(
        _mm256_movemask_epi8(_mm256_cmpeq_epi8(_mm256_loadu_si256(a), _mm256_loadu_si256(b))));
    const auto highBits = static_cast<std::uint32_t>(
        _mm256_movemask_epi8(_mm256_cmpeq_epi8(_mm256_loadu_si256(a + 1), _mm256_loadu_si256(b + 1))));
    words[j / 64] = (std::uint64_t{highBits} << 32) | lowBits;
  }
  for (; j < count; ++j)
    if (p[j] == p[j - 1]) words[j / 64] |= std::uint64_t{1} << (j % 64);
}
#endif

struct Kernels {
  void (*filterUp)(std::uint8_t*, const std::uint8_t*, const std::uint8_t*, std::size_t);
  void (*equalMask)(const std::uint8_t*, std::size_t, std::uint64_t*);
};

Kernels kernelsFor(FastPngPath path) {
#ifdef SL_FAST_PNG_X86
  if (path == FastPngPath::automatic && fastPngHasAvx2()) return {filterUpAvx2, equalMaskAvx2};
#endif
  return {filterUpPortable, equalMaskPortable};
}

// === The filtered stream: every row "up"-filtered behind its filter byte.

std::size_t streamRowBytes(const Image& image) { return static_cast<std::size_t>(image.width) * 3 + 1; }
std::size_t streamBytes(const Image& image) { return streamRowBytes(image) * static_cast<std::size_t>(image.height); }

// Bytes [from, to) of the filtered stream into dest, straight from the image (each row needs only itself and the
// row above, so any stretch can be filtered on its own).
void filterStream(const Image& image, const Kernels& kernels, std::size_t from, std::size_t to, std::uint8_t* dest) {
  const std::size_t rowBytes = streamRowBytes(image), stride = rowBytes - 1;
  while (from < to) {
    const std::size_t y = from / rowBytes, rowEnd = std::min(to, (y + 1) * rowBytes);
    if (from % rowBytes == 0) *dest++ = 2, ++from;  // "up"; on the first row the bytes above count as zero
    const std::size_t count = rowEnd - from;
    const std::uint8_t* pixels = image.rgb.data() + y * stride + (from % rowBytes - 1);
    if (count > 0 && y == 0) std::memcpy(dest, pixels, count);
    if (count > 0 && y > 0) kernels.filterUp(dest, pixels, pixels - stride, count);
    dest += count;
    from = rowEnd;
  }
}

// Part of the filtered stream in memory: `bytes` holds stream position `first` (and the bytes before it that the
// holder kept).
struct StreamWindow {
  const std::uint8_t* bytes;
  std::size_t first;
  const std::uint8_t* at(std::size_t i) const {
    return bytes + (static_cast<std::ptrdiff_t>(i) - static_cast<std::ptrdiff_t>(first));
  }
};

// The repeat bits of stream bytes [from, from + count), held at p (p[-1] readable), into words: byte `from` (a
// multiple of 64) at bit 0 of words[0]. The stream's first byte repeats nothing.
void markRepeats(const Kernels& kernels, const std::uint8_t* p, std::size_t from, std::size_t count,
                 std::uint64_t* words) {
  kernels.equalMask(p, count, words);
  if (from == 0) words[0] &= ~std::uint64_t{1};
}

// The repeat bits of part of the stream (bit i: byte i repeats byte i - 1): `words` holds word firstWord.
struct MaskWindow {
  const std::uint64_t* words;
  std::size_t firstWord;
  std::uint64_t from(std::size_t i) const {  // 64 bits from bit i on
    const std::uint64_t* word = words + (i / 64 - firstWord);
    const std::size_t shift = i % 64;
    return shift == 0 ? word[0] : (word[0] >> shift) | (word[1] << (64 - shift));
  }
};

// Cuts bytes [begin, end) of the filtered stream (n bytes) into literals and runs, greedily: a byte that starts
// kRunStart or more repeats of the one before starts a run as long as the repeats go, cut into runs of 258, a rest
// of 1 or 2 given as literals; any other byte is a literal. literals(pointer, count) and run(length) receive them in
// order; either may return false to end the walk.
// In steps: advance() goes as far as the repeat bits known (those of bytes below `known`; known >= n: all, the
// bits from n on zero) decide, and the next step goes on from there. A run that reaches past what is known sends its
// runs of 258 so far and the rest once its end is known: the same symbols however the stream is cut into steps.
// A step stops at most 63 bytes before `known`, or inside a run, and reads no byte before where it stopped.
class StreamWalker {
 public:
  StreamWalker(std::size_t begin, std::size_t end, std::size_t n) : i_(begin), end_(end), n_(n) {}

  // False once a receiver has ended the walk.
  template <class Literals, class Run>
  bool advance(const StreamWindow& bytes, const MaskWindow& mask, std::size_t known, Literals literals, Run run) {
    const bool all = known >= n_;
    if (i_ == 0) {
      if (!literals(bytes.at(0), 1)) return false;
      i_ = 1;
    }
    while (i_ < end_) {
      if (!inRun_) {
        if (!all && i_ + 64 > known) return true;
        // Bit j of `starts`: a run of kRunStart or more begins at i + j (for j <= 64 - kRunStart; the last bits
        // lack the bytes after). Shorter repeats are literals: fewer, longer stretches of literals are faster.
        const std::uint64_t repeats = mask.from(i_);
        std::uint64_t starts = repeats;
        for (int shift = 1; shift < kRunStart; ++shift) starts &= repeats >> shift;
        if (!(starts & 1)) {  // literals up to the next run worth a match
          const std::size_t k = std::min<std::size_t>(std::min(std::countr_zero(starts), 65 - kRunStart), end_ - i_);
          if (!literals(bytes.at(i_), k)) return false;
          i_ += k;
          continue;
        }
        inRun_ = true;
      }
      const std::size_t limit = all ? end_ : std::min(end_, known);
      std::size_t length = 0;
      for (int ones = 64; ones == 64 && i_ + length < limit; length += static_cast<std::size_t>(ones))
        ones = std::countr_one(mask.from(i_ + length));
      if (i_ + length >= limit && limit < end_) {  // goes on past what is known: its runs of 258 so far
        for (length = limit - i_; length >= kMaxRun; length -= kMaxRun, i_ += kMaxRun)
          if (!run(kMaxRun)) return false;
        return true;
      }
      length = std::min(length, end_ - i_);
      i_ += length;
      inRun_ = false;
      for (; length >= kMaxRun; length -= kMaxRun)
        if (!run(kMaxRun)) return false;
      if (length >= kMinRun ? !run(static_cast<int>(length))
                            : (length > 0 && !literals(bytes.at(i_ - length), length)))
        return false;
    }
    return true;
  }

 private:
  std::size_t i_, end_, n_;
  bool inRun_ = false;  // i_ is inside a run whose end was not yet known
};

// Symbol counts for the Huffman code, from every eighth row (rendered frames change slowly down the image), plus
// one for every symbol, so that every literal and every run length has a code whatever the other rows hold. Each
// row is filtered with the 64 bytes after it (their repeat bits decide the row's last symbols) into `sample`.
std::array<std::uint32_t, kLitLenSymbols> sampleCounts(const Image& image, const Kernels& kernels,
                                                       FastPngScratch& scratch) {
  const std::size_t rowBytes = streamRowBytes(image), n = streamBytes(image);
  std::array<std::array<std::uint32_t, 256>, 2> literal{};  // two tables: repeated bytes do not wait on one counter
  std::array<std::uint32_t, kLitLenSymbols> counts{};
  for (int y = 0; y < image.height; y += 8) {
    const std::size_t begin = static_cast<std::size_t>(y) * rowBytes, end = begin + rowBytes;
    const std::size_t from = begin / 64 * 64, to = std::min(n, end + 64);  // the bytes whose repeat bits are read
    scratch.sample.resize(to - from + 1);  // and the byte before them
    if (from > 0)
      filterStream(image, kernels, from - 1, to, scratch.sample.data());
    else
      scratch.sample[0] = 0, filterStream(image, kernels, 0, to, scratch.sample.data() + 1);
    scratch.sampleEqual.assign((to - from) / 64 + 2, 0);
    markRepeats(kernels, scratch.sample.data() + 1, from, to - from, scratch.sampleEqual.data());
    StreamWalker(begin, end, n).advance(
        StreamWindow{scratch.sample.data() + 1, from}, MaskWindow{scratch.sampleEqual.data(), from / 64}, to,
        [&](const std::uint8_t* bytes, std::size_t k) {
          std::size_t j = 0;
          for (; j + 2 <= k; j += 2) ++literal[0][bytes[j]], ++literal[1][bytes[j + 1]];
          if (j < k) ++literal[0][bytes[j]];
          return true;
        },
        [&](int length) {
          ++counts[kLengthCodes[length].symbol];
          return true;
        });
  }
  for (int b = 0; b < 256; ++b) counts[b] += literal[0][b] + literal[1][b];
  for (auto& c : counts) ++c;
  return counts;
}

constexpr std::array<int, 19> kCodeLengthOrder{16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};

// One dynamic-Huffman block: its header fields and codes.
struct DynamicBlock {
  std::array<std::uint8_t, kLitLenSymbols> litLengths{};
  std::array<std::uint32_t, kLitLenSymbols> litCodes{};
  std::array<std::uint8_t, 19> clLengths{};
  std::array<std::uint32_t, 19> clCodes{};
  // A run's whole code by its length: length symbol, extra bits, distance 1.
  std::array<std::uint32_t, kMaxRun + 1> runBits{};
  std::array<std::uint8_t, kMaxRun + 1> runBitCount{};
  int litCount = 257, codeLengthCount = 4;
};

// Two distance codes of one bit each (a complete code); only distance 1 (code 0, bit 0) is used.
constexpr int kDistanceCodes = 2;

DynamicBlock planBlock(const std::array<std::uint32_t, kLitLenSymbols>& counts) {
  DynamicBlock block;
  huffmanLengths(counts.data(), kLitLenSymbols, 15, block.litLengths.data());
  canonicalCodes(block.litLengths.data(), kLitLenSymbols, block.litCodes.data());
  block.litCount = kLitLenSymbols;
  while (block.litCount > 257 && block.litLengths[block.litCount - 1] == 0) --block.litCount;
  std::array<std::uint32_t, 19> clCounts{};
  for (int s = 0; s < block.litCount; ++s) ++clCounts[block.litLengths[s]];
  clCounts[1] += kDistanceCodes;
  huffmanLengths(clCounts.data(), 19, 7, block.clLengths.data());
  canonicalCodes(block.clLengths.data(), 19, block.clCodes.data());
  block.codeLengthCount = 19;
  while (block.codeLengthCount > 4 && block.clLengths[kCodeLengthOrder[block.codeLengthCount - 1]] == 0)
    --block.codeLengthCount;
  for (int length = kMinRun; length <= kMaxRun; ++length) {
    const LengthCode& code = kLengthCodes[length];
    const int symbolBits = block.litLengths[code.symbol];
    block.runBits[length] = block.litCodes[code.symbol] | (std::uint32_t(code.extraValue) << symbolBits);
    block.runBitCount[length] = static_cast<std::uint8_t>(symbolBits + code.extraBits + 1);
  }
  return block;
}

// Each band (kFastPngBandBytes) comes after kBandLookback bytes of the band before, which the walk may still read
// (it stops at most 127 bytes before the end of a band: 63 before the repeat bits known, which end at most 63 before
// the band's end).
constexpr std::size_t kBandLookback = 256;

// The block into out, and the zlib checksum of the stream into `adler`; nullptr if it would pass `limit` (then
// stored blocks are smaller: the caller writes those). `out` has room up to limit + 512.
std::uint8_t* writeDynamicBlock(const DynamicBlock& block, const Image& image, const Kernels& kernels,
                                std::size_t bandBytesWanted, FastPngScratch& scratch, std::uint8_t* out,
                                const std::uint8_t* limit, std::uint32_t& adler) {
  BitWriter writer(out);
  writer.put(1, 1);  // final block
  writer.put(2, 2);  // dynamic Huffman
  writer.put(std::uint64_t(block.litCount - 257), 5);
  writer.put(kDistanceCodes - 1, 5);
  writer.put(std::uint64_t(block.codeLengthCount - 4), 4);
  for (int i = 0; i < block.codeLengthCount; ++i) writer.put(block.clLengths[kCodeLengthOrder[i]], 3);
  for (int s = 0; s < block.litCount; ++s) {
    const int v = block.litLengths[s];
    writer.put(block.clCodes[v], block.clLengths[v]);
  }
  for (int d = 0; d < kDistanceCodes; ++d) writer.put(block.clCodes[1], block.clLengths[1]);
  if (writer.position() > limit) return nullptr;
  const auto* codes = block.litCodes.data();
  const auto* lengths = block.litLengths.data();
  // At most 57 literals of at most 15 bits, three to a put (45 bits): a third fewer trips through the writer's
  // chain of dependent shifts than pairs.
  const auto literals = [&](const std::uint8_t* bytes, std::size_t k) {
    std::size_t j = 0;
    for (; j + 3 <= k; j += 3) {
      const std::uint8_t a = bytes[j], b = bytes[j + 1], c = bytes[j + 2];
      const int la = lengths[a], lab = la + lengths[b];
      writer.put(codes[a] | (std::uint64_t(codes[b]) << la) | (std::uint64_t(codes[c]) << lab), lab + lengths[c]);
    }
    for (; j < k; ++j) writer.put(codes[bytes[j]], lengths[bytes[j]]);
    return writer.position() <= limit;
  };
  const auto run = [&](int length) {
    writer.put(block.runBits[length], block.runBitCount[length]);
    return writer.position() <= limit;
  };

  const std::size_t rowBytes = streamRowBytes(image), n = streamBytes(image);
  const std::size_t bandBytes = std::max<std::size_t>(1, bandBytesWanted / rowBytes) * rowBytes;
  scratch.band.resize(kBandLookback + std::min(bandBytes, n));
  std::fill(scratch.band.begin(), scratch.band.begin() + kBandLookback, 0);
  scratch.equal.resize(n / 64 + 2);
  std::uint64_t* mask = scratch.equal.data();
  mask[n / 64] = mask[n / 64 + 1] = 0;  // the bits from n on stay zero (the last word's are or-ed in)
  std::uint8_t* band = scratch.band.data() + kBandLookback;  // stream position `start`
  StreamWalker walker(0, n, n);
  std::size_t known = 0;  // repeat bits set below this (a multiple of 64, or n)
  for (std::size_t start = 0, previous = 0; start < n; start += previous) {
    const std::size_t size = std::min(bandBytes, n - start), end = start + size;
    std::memmove(band - kBandLookback, band - kBandLookback + previous, kBandLookback);
    filterStream(image, kernels, start, end, band);
    adler = libdeflate_adler32(adler, band, size);
    const std::size_t markedTo = end == n ? n : end / 64 * 64;
    if (markedTo > known) {
      // Byte known - 1 is in the band or its lookback: known >= start - 63.
      markRepeats(kernels, band - (start - known), known, markedTo - known, mask + known / 64);
      known = markedTo;
    }
    if (!walker.advance(StreamWindow{band, start}, MaskWindow{mask, 0}, known, literals, run)) return nullptr;
    previous = size;
  }
  writer.put(block.litCodes[kEndOfBlock], block.litLengths[kEndOfBlock]);
  return writer.finish();
}

constexpr std::size_t kStoredBlockMax = 65535;

std::size_t storedSize(std::size_t n) { return n + 5 * std::max<std::size_t>(1, (n + kStoredBlockMax - 1) / kStoredBlockMax); }

std::uint8_t* writeStoredBlocks(const std::uint8_t* data, std::size_t n, std::uint8_t* out) {
  std::size_t offset = 0;
  do {
    const std::size_t size = std::min(kStoredBlockMax, n - offset);
    *out++ = offset + size == n ? 1 : 0;  // BFINAL, BTYPE 00, padding to the byte
    const auto length = static_cast<std::uint16_t>(size);
    const auto complement = static_cast<std::uint16_t>(~length);
    *out++ = static_cast<std::uint8_t>(length), *out++ = static_cast<std::uint8_t>(length >> 8);
    *out++ = static_cast<std::uint8_t>(complement), *out++ = static_cast<std::uint8_t>(complement >> 8);
    std::memcpy(out, data + offset, size);
    out += size;
    offset += size;
  } while (offset < n);
  return out;
}

// === PNG container (PNG specification, section 5)

std::uint8_t* put32(std::uint8_t* out, std::uint32_t v) {
  for (int shift : {24, 16, 8, 0}) *out++ = static_cast<std::uint8_t>(v >> shift);
  return out;
}

// Writes length, type and CRC around `size` bytes of data already at out + 8; returns the end.
std::uint8_t* closeChunk(std::uint8_t* out, const char type[4], std::size_t size) {
  put32(out, static_cast<std::uint32_t>(size));
  std::memcpy(out + 4, type, 4);
  return put32(out + 8 + size, libdeflate_crc32(0, out + 4, size + 4));
}

}  // namespace

bool fastPngHasAvx2() {
#ifdef SL_FAST_PNG_X86
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
#else
  return false;
#endif
}

std::vector<std::uint8_t> encodeFastPng(const Image& image, FastPngScratch& scratch, FastPngPath path,
                                        std::size_t bandBytes) {
  const Kernels kernels = kernelsFor(path);
  const std::size_t n = streamBytes(image);
  const DynamicBlock block = planBlock(sampleCounts(image, kernels, scratch));
  // Huffman-coded unless that is no smaller than stored blocks (noise).
  const std::size_t storedBytes = storedSize(n);
  scratch.deflated.resize(storedBytes + 512);  // room for the header (< 270 bytes) and one step past the limit
  std::uint32_t adler = 1;
  const std::uint8_t* huffmanEnd = writeDynamicBlock(block, image, kernels, bandBytes, scratch,
                                                     scratch.deflated.data(), scratch.deflated.data() + storedBytes,
                                                     adler);
  const bool stored = huffmanEnd == nullptr || std::size_t(huffmanEnd - scratch.deflated.data()) >= storedBytes;
  const std::size_t deflateBytes = stored ? storedBytes : std::size_t(huffmanEnd - scratch.deflated.data());
  if (stored) {  // the whole stream at once, and its checksum again (the bands may have stopped early)
    scratch.filtered.resize(n);
    filterStream(image, kernels, 0, n, scratch.filtered.data());
    adler = libdeflate_adler32(1, scratch.filtered.data(), n);
  }

  constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  constexpr std::size_t kHeaderChunk = 12 + 13, kEndChunk = 12;
  const std::size_t zlibBytes = 2 + deflateBytes + 4;
  std::vector<std::uint8_t> png(8 + kHeaderChunk + 12 + zlibBytes + kEndChunk);
  std::uint8_t* out = png.data();
  std::memcpy(out, kSignature, 8);
  out += 8;
  std::uint8_t* data = out + 8;
  data = put32(data, static_cast<std::uint32_t>(image.width));
  data = put32(data, static_cast<std::uint32_t>(image.height));
  for (std::uint8_t b : {8, 2, 0, 0, 0}) *data++ = b;  // 8 bits, truecolour RGB, deflate, adaptive filters, no interlace
  out = closeChunk(out, "IHDR", 13);

  std::uint8_t* idat = out + 8;
  data = idat;
  *data++ = 0x78, *data++ = 0x01;  // zlib: deflate, 32 KiB window, "fastest" (RFC 1950)
  if (stored) {
    data = writeStoredBlocks(scratch.filtered.data(), n, data);
  } else {
    std::memcpy(data, scratch.deflated.data(), deflateBytes);
    data += deflateBytes;
  }
  data = put32(data, adler);
  out = closeChunk(out, "IDAT", static_cast<std::size_t>(data - idat));
  out = closeChunk(out, "IEND", 0);
  png.resize(static_cast<std::size_t>(out - png.data()));
  return png;
}

}  // namespace sl
