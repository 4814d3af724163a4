#include "kinestat/core/huge_page_allocator.hpp"

#include <sys/mman.h>

#include <cstdlib>

namespace kinestat {

void* allocate_large(std::size_t bytes) {
  if (bytes < kHugePageThreshold) return std::malloc(bytes == 0 ? 1 : bytes);
  constexpr std::size_t kHugePage = std::size_t{2} << 20;
  void* p = nullptr;
  if (posix_memalign(&p, kHugePage, bytes) != 0) return nullptr;
  // Advice only: without transparent huge pages (enabled = never) the block keeps 4 kB pages.
  madvise(p, bytes, MADV_HUGEPAGE);
  return p;
}

}  // namespace kinestat
