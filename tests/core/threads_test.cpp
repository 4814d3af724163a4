// available_cpus(): the CPUs a process may run on, not the host's count.
#include "kinestat/core/threads.hpp"

#include <gtest/gtest.h>
#include <sched.h>

#include <thread>

namespace kinestat {
namespace {

TEST(AvailableCpus, FollowsTheAffinityMask) {
  const int all = available_cpus();
  EXPECT_GE(all, 1);
  EXPECT_LE(all, static_cast<int>(std::thread::hardware_concurrency()));
  // Pinned to one CPU (as `taskset -c 0` would), the count is one: a container's cpuset is seen.
  cpu_set_t saved, one;
  ASSERT_EQ(sched_getaffinity(0, sizeof(saved), &saved), 0);
  int first = 0;
  while (!CPU_ISSET(first, &saved)) ++first;
  CPU_ZERO(&one);
  CPU_SET(first, &one);
  ASSERT_EQ(sched_setaffinity(0, sizeof(one), &one), 0);
  const int pinned = available_cpus();
  ASSERT_EQ(sched_setaffinity(0, sizeof(saved), &saved), 0);
  EXPECT_EQ(pinned, 1);
  EXPECT_EQ(available_cpus(), all);
}

}  // namespace
}  // namespace kinestat
