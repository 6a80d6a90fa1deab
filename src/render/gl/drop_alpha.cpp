#include "render/gl/drop_alpha.hpp"

#include <cstring>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define SL_DROP_ALPHA_X86 1
#endif

namespace sl {
namespace {

void dropAlphaPortable(const std::uint8_t* rgba, std::uint8_t* rgb, std::size_t pixels) {
  for (std::size_t i = 0; i < pixels; ++i, rgba += 4, rgb += 3) std::memcpy(rgb, rgba, 3);
}

#ifdef SL_DROP_ALPHA_X86
// Four pixels per shuffle into the low 12 bytes; each 16-byte store overlaps the next by 4 bytes, so the last
// four pixels (whose store would pass the end) go the portable way.
__attribute__((target("ssse3"))) void dropAlphaSsse3(const std::uint8_t* rgba, std::uint8_t* rgb, std::size_t pixels) {
  const __m128i order = _mm_setr_epi8(0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, -1, -1, -1, -1);
  std::size_t i = 0;
  for (; i + 8 <= pixels; i += 4) {
    const __m128i four = _mm_loadu_si128(reinterpret_cast<const __m128i*>(rgba + 4 * i));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(rgb + 3 * i), _mm_shuffle_epi8(four, order));
  }
  dropAlphaPortable(rgba + 4 * i, rgb + 3 * i, pixels - i);
}
#endif

}  // namespace

void dropAlpha(const std::uint8_t* rgba, std::uint8_t* rgb, std::size_t pixels, DropAlphaPath path) {
#ifdef SL_DROP_ALPHA_X86
  static const bool hasSsse3 = __builtin_cpu_supports("ssse3");
  if (path == DropAlphaPath::automatic && hasSsse3) return dropAlphaSsse3(rgba, rgb, pixels);
#endif
  (void)path;
  dropAlphaPortable(rgba, rgb, pixels);
}

}  // namespace sl
