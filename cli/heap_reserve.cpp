#include "cli/heap_reserve.h"

#include <cstdint>
#include <cstdlib>

#if defined(__linux__) && defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#endif

namespace csgray::detail {

void reserveHugePageHeap(std::size_t bytes) {
#if defined(__linux__) && defined(__GLIBC__) && defined(MADV_HUGEPAGE)
  // One block from the top of the heap (not from mmap, which malloc uses
  // for large blocks), freed again: it joins the heap's free top, which
  // later small blocks are cut from. Without trimming, the heap keeps it.
  mallopt(M_TRIM_THRESHOLD, int(bytes * 2 > std::size_t(INT32_MAX) ? INT32_MAX : bytes * 2));
  mallopt(M_MMAP_MAX, 0);
  void* block = std::malloc(bytes);
  mallopt(M_MMAP_MAX, 65536);  // glibc's default
  // Blocks up to 32 MiB (an image, a mesh's arrays) come from the heap
  // too, rather than each from a fresh mapping of 4 KiB pages.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  if (!block) return;
  constexpr std::uintptr_t kHugePage = std::uintptr_t(2) << 20;
  const auto begin = (reinterpret_cast<std::uintptr_t>(block) + kHugePage - 1) & ~(kHugePage - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(block) + bytes) & ~(kHugePage - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
  std::free(block);
#else
  (void)bytes;
#endif
}

}  // namespace csgray::detail
