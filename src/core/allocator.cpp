#include "topocut/core/allocator.h"

// Any C library header defines __GLIBC__ when glibc is the C library; without one the test below
// is always false and the function silently does nothing.
#include <cstdlib>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace topocut {

void keep_freed_memory_for_reuse() {
#if defined(__GLIBC__)
  // Blocks up to 32 MiB (glibc's largest allowed threshold on 64-bit) come from the heap, and the
  // heap is not trimmed while less than 1 GiB of it is free.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

}  // namespace topocut
