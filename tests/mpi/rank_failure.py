#!/usr/bin/env python3
"""MPI ranks that disagree end together, in seconds, with the reason (docs/reliability.md, "MPI").

Two two-rank jobs of `kinestat link-stiffness --solver petsc-mumps`, each rank started with its own
command (mpiexec's `A : B` form), as happens on a cluster whose nodes see different files:
1. rank 1 is given another --size than rank 0: both ranks refuse, exit 2, naming the difference;
2. the same command on both ranks, but in two working folders and the mesh present only in rank 0's:
   the job ends (non-zero) within the time limit and stderr names the missing file;
3. the mesh in both folders and a cache entry in rank 0's folder only (node-local caches): every
   rank computes, the job succeeds and gives the cached 6x6 (to 1e-9 of its diagonal).
A hang fails the test through the subprocess timeout (60 s; a job that works takes about 2 s).

usage: rank_failure.py KINESTAT MPIEXEC MESH
"""
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

from mpi_runs import allow_mpi_runs


def run_job(command, cwd=None):
    start = time.monotonic()
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=60, cwd=cwd)
    except subprocess.TimeoutExpired:
        sys.exit(f"{' '.join(command)}: still running after 60 s (a hang)")
    return done, time.monotonic() - start


def main():
    kinestat, mpiexec, mesh = os.path.abspath(sys.argv[1]), sys.argv[2], os.path.abspath(sys.argv[3])
    allow_mpi_runs()
    common = ["link-stiffness", "--clamp", "x=0", "--reference", "x=200", "--solver", "petsc-mumps", "--quiet"]

    done, seconds = run_job([mpiexec, "-np", "1", kinestat, *common, mesh, "--size", "20", ":",
                             "-np", "1", kinestat, *common, mesh, "--size", "30"])
    if done.returncode != 2 or "differs from rank 0's" not in done.stderr:
        sys.exit(f"different options: exit {done.returncode}, stderr:\n{done.stderr}")
    print(f"different options on two ranks: exit 2 in {seconds:.1f} s, the difference named")

    with tempfile.TemporaryDirectory() as top:
        a, b = os.path.join(top, "a"), os.path.join(top, "b")
        os.makedirs(a), os.makedirs(b)
        shutil.copy(mesh, os.path.join(a, "link.off"))  # rank 1's folder has no mesh
        args = [kinestat, *common, "link.off", "--size", "20", "--cache", "cache"]
        done, seconds = run_job([mpiexec, "-np", "1", "-wdir", a, *args, ":", "-np", "1", "-wdir", b, *args])
        if done.returncode == 0 or "link.off" not in done.stderr:
            sys.exit(f"mesh on one rank only: exit {done.returncode}, stderr:\n{done.stderr}")
        print(f"mesh on rank 0 only: exit {done.returncode} in {seconds:.1f} s, the file named")

        shutil.copy(mesh, os.path.join(b, "link.off"))
        json_args = [kinestat, *common, "link.off", "--size", "20", "--cache", "cache", "--json", "-"]
        first, _ = run_job([mpiexec, "-np", "1", "-wdir", a, *json_args])  # fills rank 0's cache only
        done, seconds = run_job([mpiexec, "-np", "1", "-wdir", a, *json_args, ":", "-np", "1", "-wdir", b, *json_args])
        if first.returncode != 0 or done.returncode != 0:
            sys.exit(f"cache on rank 0 only: exits {first.returncode}, {done.returncode}, stderr:\n{done.stderr}")
        cached, computed = json.loads(first.stdout)["compliance"], json.loads(done.stdout)["compliance"]
        worst = max(abs(computed[i][j] - cached[i][j]) / math.sqrt(cached[i][i] * cached[j][j])
                    for i in range(6) for j in range(6))
        if worst > 1e-9:
            sys.exit(f"cache on rank 0 only: the 6x6 differs from the cached one by {worst:.2e}")
        print(f"cache on rank 0 only: exit 0 in {seconds:.1f} s, 6x6 equal to the cached one to {worst:.1e}")


if __name__ == "__main__":
    main()
