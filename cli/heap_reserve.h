// The export's exact booleans allocate a few hundred thousand small
// objects, and a render its images and the script's solids, touching every
// page of them once; on this kind of virtual machine a page fault costs
// about 12 µs, enough that 4 KiB pages were a tenth of plate(8)'s export
// and a fifth of its render. reserveHugePageHeap grows the heap once and
// asks the kernel for transparent huge pages there (2 MiB pages: one fault
// where there were 512), which glibc's malloc then hands out.
#pragma once

#include <cstddef>

namespace csgray::detail {

// Grows the main heap by about `bytes` and marks it for transparent huge
// pages (madvise); blocks of up to 32 MiB are then taken from it too.
// Memory is only taken as it is touched; freed memory is kept for reuse
// rather than given back. Does nothing where the kernel or the C library
// does not support it.
void reserveHugePageHeap(std::size_t bytes);

}  // namespace csgray::detail
