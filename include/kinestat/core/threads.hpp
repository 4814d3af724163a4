// How many threads a parallel loop should start when the caller says "all cores".
#pragma once

namespace kinestat {

// The CPUs this process may run on: its affinity mask (what `nproc` prints), limited by the CPU
// quota of its cgroup when one is set (a container given 2 CPUs of a larger host, whose
// std::thread::hardware_concurrency() would be the host's count). At least 1. The default of every
// `threads = 0` option, so that a sweep never starts more threads than it can run at once.
int available_cpus();

}  // namespace kinestat
