#include "cli/allocator.h"

// Any C library header defines __GLIBC__ when glibc is the C library; without one the test below
// is always false and the function silently does nothing.
#include <cstdint>
#include <cstdlib>

#if defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace topocut {

namespace {

#if defined(__GLIBC__)
// Grows the heap by `bytes` of address space now (no memory is touched) and asks the kernel for
// transparent huge pages there: a map-sized buffer then faults in 2 MiB at a time instead of 4 KiB
// (what glibc's glibc.malloc.hugetlb=1 tunable does, which only the environment can set). Where
// huge pages are off, or the heap is not contiguous, madvise fails and nothing changes.
void reserve_huge_page_heap(std::size_t bytes) {
  constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
  const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(sbrk(0));
  mallopt(M_TOP_PAD, static_cast<int>(bytes));
  // More than the heap's free top holds, so that malloc grows the heap (by the block and the pad);
  // volatile, or the compiler drops the unused pair of calls.
  void* volatile block = std::malloc(std::size_t{1} << 20);
  std::free(block);
  mallopt(M_TOP_PAD, 128 << 10);  // glibc's default again for later growth
  const std::uintptr_t end = reinterpret_cast<std::uintptr_t>(sbrk(0));
  const std::uintptr_t first = (start + kHugePage - 1) & ~(kHugePage - 1);
  if (end > first + kHugePage) madvise(reinterpret_cast<void*>(first), end - first, MADV_HUGEPAGE);
}
#endif

}  // namespace

void keep_freed_memory_for_reuse() {
#if defined(__GLIBC__)
  // Blocks up to 32 MiB (glibc's largest allowed threshold on 64-bit) come from the heap, and the
  // heap is not trimmed while less than 1 GiB of it is free.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  reserve_huge_page_heap(std::size_t{256} << 20);
#endif
}

}  // namespace topocut
