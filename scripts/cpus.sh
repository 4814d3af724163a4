#!/usr/bin/env bash
# Prints how many CPUs this job may use: `nproc` (the affinity mask), limited by the cgroup's CPU
# quota when one is set (a container given 2 CPUs of a larger host), as core/threads.hpp does for
# kinestat's own threads. The -j of the build and test scripts.
n=$(nproc 2>/dev/null || echo 2)
quota=""
if [ -r /sys/fs/cgroup/cpu.max ]; then
  read -r q p < /sys/fs/cgroup/cpu.max
  [ "$q" != max ] && quota=$(( (q + p - 1) / p ))
elif [ -r /sys/fs/cgroup/cpu/cpu.cfs_quota_us ]; then
  q=$(cat /sys/fs/cgroup/cpu/cpu.cfs_quota_us) p=$(cat /sys/fs/cgroup/cpu/cpu.cfs_period_us)
  [ "$q" -gt 0 ] && quota=$(( (q + p - 1) / p ))
fi
if [ -n "$quota" ] && [ "$quota" -lt "$n" ]; then n=$quota; fi
echo $(( n > 0 ? n : 1 ))
