#include "kinestat/core/threads.hpp"

#include <sched.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <thread>

namespace kinestat {

namespace {

// The cgroup's CPU quota in CPUs (quota / period, rounded up), or 0 when none is set: cgroup v2's
// cpu.max ("max 100000" or "200000 100000"), else cgroup v1's cfs quota and period.
int cgroup_cpu_quota() {
  double quota = -1.0, period = 0.0;
  if (std::ifstream v2("/sys/fs/cgroup/cpu.max"); v2) {
    std::string q;
    if (v2 >> q >> period && q != "max") quota = std::stod(q);
  } else {
    std::ifstream("/sys/fs/cgroup/cpu/cpu.cfs_quota_us") >> quota;
    std::ifstream("/sys/fs/cgroup/cpu/cpu.cfs_period_us") >> period;
  }
  if (!(quota > 0.0 && period > 0.0)) return 0;
  return static_cast<int>(std::ceil(quota / period));
}

}  // namespace

int available_cpus() {
  int cpus = static_cast<int>(std::thread::hardware_concurrency());
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) cpus = CPU_COUNT(&set);
  if (const int quota = cgroup_cpu_quota(); quota > 0) cpus = std::min(cpus, quota);
  return std::max(1, cpus);
}

}  // namespace kinestat
