#pragma once
// A PNG writer built for speed: every row filtered "up" (PNG specification, section 9.2: each byte minus the
// byte above it; the first row has zeros above), and the filtered stream compressed as one deflate block
// (RFC 1951) whose only matches are runs of the previous byte (distance 1, lengths 3..258; a run starts at 8 repeats,
// shorter repeats are literals), Huffman-coded with
// a code built from this image's own symbol counts in every eighth row (a "dynamic" block, lengths limited to
// 15 bits; every symbol has a code). Rendered
// frames are mostly flat: "up" turns everything that repeats the row above into zeros, and the runs take them
// at a few bits per 258 bytes. When the Huffman block would be larger than the data (noise), stored blocks are
// written instead. The symbol counts come first (the sampled rows filtered on their own); then the stream is
// filtered, marked and deflated band by band, each band in cache between those passes, never whole in memory.
//
// Two implementations of the byte-level work (the filter and marking the bytes that repeat the one before): a portable one and an
// AVX2 one, chosen at run time by what the CPU has. They compute the same integers, so a frame gives the same
// bytes on every CPU: shards rendered on different cluster nodes stay byte-identical (tests check both paths).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "contracts/image.hpp"

namespace sl {

enum class FastPngPath {
  automatic,  // AVX2 where the CPU has it, else portable
  portable    // never the SIMD code (tests compare the two)
};

// True if this CPU runs the AVX2 path (automatic chooses it).
bool fastPngHasAvx2();

// Working memory reused between frames by one thread.
struct FastPngScratch {
  std::vector<std::uint8_t> band;      // a band of the filtered stream, after the end of the band before
  std::vector<std::uint64_t> equal;    // bit i: filtered byte i repeats byte i - 1
  std::vector<std::uint8_t> sample;    // a row sampled for the symbol counts, filtered
  std::vector<std::uint64_t> sampleEqual;  // its repeat bits
  std::vector<std::uint8_t> deflated;  // the Huffman-coded block, before it is known to beat stored blocks
  std::vector<std::uint8_t> filtered;  // the whole stream, for stored blocks (noise)
};

// The filtered stream is filtered, marked and deflated a band of rows at a time, so that a band stays in the core's
// cache between those passes: about this many bytes (whole rows, at least one). The file does not depend on it.
inline constexpr std::size_t kFastPngBandBytes = 64 * 1024;

// The PNG file of an RGB8 image (width, height >= 1 and rgb of width*height*3 bytes: checked by the caller).
std::vector<std::uint8_t> encodeFastPng(const Image& image, FastPngScratch& scratch,
                                        FastPngPath path = FastPngPath::automatic,
                                        std::size_t bandBytes = kFastPngBandBytes);

}  // namespace sl
