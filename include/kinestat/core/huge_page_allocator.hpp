// Memory for the big arrays of a large model (the sparse factor, its workspace): blocks of 4 MB
// and more are aligned to 2 MB and marked for transparent huge pages (madvise), so that touching
// them the first time costs one page fault per 2 MB instead of one per 4 kB, and the TLB covers
// them (measured on the 88k-dof bench bar, benchmarks/README.md, "Factorization rate": page faults
// 127 000 -> 2 200 per factorization). Blocks of 64 MB and more are also faulted in at once by all
// cores (first touch of memory new to the process costs up to ~2 s per GB on one core in this VM:
// benchmarks/README.md, "First touch in this VM"), so the factorization does not pay that on one
// thread. Smaller blocks are plain malloc. Release with std::free.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>

namespace kinestat {

// Blocks from this size on get huge pages (at least two of 2 MB; the alignment wastes address
// space, not memory: glibc maps such blocks on their own and untouched pages cost nothing).
inline constexpr std::size_t kHugePageThreshold = std::size_t{4} << 20;
// Blocks from this size on are also touched (faulted in) by all cores at once when allocated.
inline constexpr std::size_t kPrefaultThreshold = std::size_t{64} << 20;

// `bytes` of uninitialized memory (nullptr when the system has none): std::malloc below
// kHugePageThreshold, 2 MB-aligned and madvise(MADV_HUGEPAGE)d from it. Free with std::free.
void* allocate_large(std::size_t bytes);

// Standard allocator over allocate_large, for std::vector of large arrays.
template <class T>
struct HugePageAllocator {
  using value_type = T;
  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}  // NOLINT(google-explicit-constructor): rebinding
  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    void* p = allocate_large(n * sizeof(T));
    if (p == nullptr) throw std::bad_alloc();
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t) noexcept { std::free(p); }
  template <class U>
  bool operator==(const HugePageAllocator<U>&) const noexcept {
    return true;
  }
};

}  // namespace kinestat
