#pragma once
// Scans of a row of bytes for the next cell worth looking at. The front end's masks are mostly
// runs of equal bytes (a boundary is short), so the scans compare 16 cells at once where SSE2 is
// there and cell by cell elsewhere, with the same answer.
#include <bit>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace topocut {

#if defined(__SSE2__)
// Bit i: whether byte i of the 16 at p equals byte i of v.
inline unsigned equal_bytes16(const unsigned char* p, __m128i v) {
  return static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)), v)));
}
#endif

// The first column in [from, to) where rows a and b hold different bytes, to if none.
inline int first_difference(const unsigned char* a, const unsigned char* b, int from, int to) {
  int c = from;
#if defined(__SSE2__)
  for (; c + 16 <= to; c += 16) {
    const unsigned equal = equal_bytes16(a + c, _mm_loadu_si128(reinterpret_cast<const __m128i*>(b + c)));
    if (equal != 0xFFFFu) return c + std::countr_zero(~equal);
  }
#endif
  while (c < to && a[c] == b[c]) ++c;
  return c;
}

// The first of the cells [from, to) of row that is nonzero, to if none.
inline int first_nonzero(const unsigned char* row, int from, int to) {
  int x = from;
#if defined(__SSE2__)
  const __m128i zero = _mm_setzero_si128();
  for (; x + 16 <= to; x += 16) {
    const unsigned zeros = equal_bytes16(row + x, zero);
    if (zeros != 0xFFFFu) return x + std::countr_zero(~zeros);
  }
#endif
  while (x < to && row[x] == 0) ++x;
  return x;
}

}  // namespace topocut
