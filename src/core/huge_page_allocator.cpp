#include "kinestat/core/huge_page_allocator.hpp"

#include <sys/mman.h>

#include <algorithm>
#include <cstdlib>
#include <thread>
#include <vector>

#include "kinestat/core/threads.hpp"

namespace kinestat {
namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

// Touches every page of [p, p + bytes) on all cores: a fresh page costs its first touch (zeroing,
// and in this VM the host backing memory it was given back: ~2 s per GB on one thread after 20 s
// idle, benchmarks/README.md, "First touch in this VM"); spread over the cores it costs that time
// divided by their number, and the factorization that fills the block then runs without page
// faults. The block is fresh (uninitialized), so writing zeros changes nothing it promises.
void touch_in_parallel(char* p, std::size_t bytes) {
  const std::size_t threads = static_cast<std::size_t>(available_cpus());
  const std::size_t chunk = (bytes / threads + kHugePage - 1) / kHugePage * kHugePage;
  auto touch = [p, bytes](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < std::min(end, bytes); k += 4096) p[k] = 0;
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads && t * chunk < bytes; ++t) pool.emplace_back(touch, t * chunk, (t + 1) * chunk);
  touch(0, chunk);
  for (std::thread& t : pool) t.join();
}

}  // namespace

void* allocate_large(std::size_t bytes) {
  if (bytes < kHugePageThreshold) return std::malloc(bytes == 0 ? 1 : bytes);
  void* p = nullptr;
  if (posix_memalign(&p, kHugePage, bytes) != 0) return nullptr;
  // Advice only: without transparent huge pages (enabled = never) the block keeps 4 kB pages.
  madvise(p, bytes, MADV_HUGEPAGE);
  if (bytes >= kPrefaultThreshold) touch_in_parallel(static_cast<char*>(p), bytes);
  return p;
}

}  // namespace kinestat
