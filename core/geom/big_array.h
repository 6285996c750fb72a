// BigArrayAllocator: the allocator of the BVH's two large query arrays (wide nodes, leaf
// triangles). On Linux an array of 4 MB or more is placed on 2 MB boundaries and marked
// MADV_HUGEPAGE before its first use, so the kernel may back it with 2 MB pages: a 4 M-triangle
// tree is ~180 MB of such arrays, and a query at that size pays a TLB miss at most tree levels
// with 4 kB pages (measured in bvh.h). Elsewhere (WASM, other systems) and below 4 MB it is
// std::allocator. Does not: change any value (a hint to the kernel; if refused, nothing changes).
#pragma once

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace niwa::geom {

#if defined(__linux__) && defined(MADV_HUGEPAGE)
#define NIWA_GEOM_HUGE_PAGES 1
#else
#define NIWA_GEOM_HUGE_PAGES 0
#endif

template <typename T>
struct BigArrayAllocator {
  using value_type = T;
  static constexpr std::size_t kHugePage = std::size_t{2} << 20;

  BigArrayAllocator() = default;
  template <typename U>
  BigArrayAllocator(const BigArrayAllocator<U>&) noexcept {
  }  // NOLINT: rebinding, as std::allocator

  // The same rule in allocate and deallocate (vector passes the same n to both).
  static bool Huge(std::size_t n) { return NIWA_GEOM_HUGE_PAGES && n * sizeof(T) >= 2 * kHugePage; }

  T* allocate(std::size_t n) {
    if (!Huge(n)) return std::allocator<T>().allocate(n);
    const std::size_t bytes = (n * sizeof(T) + kHugePage - 1) / kHugePage * kHugePage;
    void* p = std::aligned_alloc(kHugePage, bytes);
    if (p == nullptr) throw std::bad_alloc();
#if NIWA_GEOM_HUGE_PAGES
    (void)madvise(p, bytes, MADV_HUGEPAGE);  // a hint: refused, the array stays on 4 kB pages
#endif
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (Huge(n))
      std::free(p);
    else
      std::allocator<T>().deallocate(p, n);
  }
  friend bool operator==(const BigArrayAllocator&, const BigArrayAllocator&) { return true; }
  friend bool operator!=(const BigArrayAllocator&, const BigArrayAllocator&) { return false; }
};

}  // namespace niwa::geom
