#include "partition/large_block_allocator.hpp"

#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace furrow {

namespace {
constexpr std::size_t kHugePage = std::size_t{2} << 20;
}

void* allocate_large_block(std::size_t bytes) {
  // aligned_alloc wants a size that is a multiple of the alignment.
  const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  void* p = std::aligned_alloc(kHugePage, rounded);
  if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Advice only: failure (no THP support) leaves ordinary pages.
  madvise(p, rounded, MADV_HUGEPAGE);
#endif
  return p;
}

void free_large_block(void* p) { std::free(p); }

}  // namespace furrow
