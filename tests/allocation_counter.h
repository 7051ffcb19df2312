// Counts heap allocations, to check that rays allocate nothing. It replaces
// the global operator new, so include it in exactly one file of a test
// binary. (Not inlined, so that the compiler sees new and delete as a pair.)
#pragma once

#include <atomic>
#include <cstdlib>
#include <new>

namespace csgray::detail::test {
inline std::atomic<long> gAllocations{0};
// operator new calls so far.
inline long allocations() { return gAllocations.load(); }
}  // namespace csgray::detail::test

[[gnu::noinline]] void* operator new(std::size_t n) {
  ++csgray::detail::test::gAllocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }
