// The memory a factorization may still take, for refusing one that would not fit (any backend).
#pragma once

namespace kinestat::solver {

// MemAvailable of /proc/meminfo (the kernel's estimate of what can be allocated without swapping),
// bytes; 0 when unknown (then nothing is refused).
double available_memory_bytes();

}  // namespace kinestat::solver
