#pragma once
// Allocator for the per-cell arrays of a curvature field (tens to hundreds of
// MB at 1000 x 1000 cells and more).
//
// Why: such an array is written once, right after allocation, and the kernel
// then maps it 4 kB at a time: at 1000 x 1000 cells that is over 20,000 page
// faults, which cost as much as evaluating the surface (measured with perf on
// bench_partition). Blocks of at least kLargeBlockBytes are therefore aligned
// to 2 MB and marked MADV_HUGEPAGE, so that Linux backs them with huge pages
// where it can (512 times fewer faults); smaller blocks and other systems use
// the ordinary heap. The advice only changes speed, never contents: element
// construction and lifetime are exactly std::allocator's.
#include <cstddef>
#include <memory>
#include <new>

namespace furrow {

constexpr std::size_t kLargeBlockBytes = std::size_t{4} << 20;

// Raw storage of `bytes` bytes (>= kLargeBlockBytes), huge-page advised where
// supported; throws std::bad_alloc when the memory is not available.
void* allocate_large_block(std::size_t bytes);
void free_large_block(void* p);

template <class T>
struct LargeBlockAllocator {
  using value_type = T;

  LargeBlockAllocator() = default;
  template <class U>
  LargeBlockAllocator(const LargeBlockAllocator<U>&) {}

  T* allocate(std::size_t n) {
    if (n > std::size_t(-1) / sizeof(T)) throw std::bad_alloc();
    if (n * sizeof(T) >= kLargeBlockBytes)
      return static_cast<T*>(allocate_large_block(n * sizeof(T)));
    return std::allocator<T>().allocate(n);
  }
  void deallocate(T* p, std::size_t n) {
    if (n * sizeof(T) >= kLargeBlockBytes)
      free_large_block(p);
    else
      std::allocator<T>().deallocate(p, n);
  }

  template <class U>
  bool operator==(const LargeBlockAllocator<U>&) const { return true; }
  template <class U>
  bool operator!=(const LargeBlockAllocator<U>&) const { return false; }
};

}  // namespace furrow
