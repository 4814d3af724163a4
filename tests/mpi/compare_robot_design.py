#!/usr/bin/env python3
"""A robot design sweep split across MPI ranks gives what one process gives: runs `kinestat design
ROBOT.yaml ... --json -` under `MPIEXEC -np 1` and `MPIEXEC -np 2` and checks that the two JSON
documents name the same best design and hold the same measures for every design (to 1e-12
relative: each design's map is computed the same way on any rank), that only rank 0 wrote (one
JSON document on stdout) and that the second run says it ran on 2 ranks. One design of the sweep
cannot be built (forearm 500 from arm 600): its failure, found on rank 1, reaches rank 0's table.
Then a job whose rank 1 runs in a folder without the robot file ends on both ranks, in seconds, with
rank 1's reason (the setup's outcome is agreed before the sweep).

usage: compare_robot_design.py KINESTAT MPIEXEC ROBOT [design options...]
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

from mpi_runs import allow_mpi_runs, run


def run_json(command):
    return json.loads(run(command))  # fails on two documents


def main():
    kinestat, mpiexec, robot, *options = sys.argv[1:]
    allow_mpi_runs()
    base = [kinestat, "design", robot, *options, "--json", "-", "--quiet", "--threads", "1"]
    one = run_json([mpiexec, "-np", "1", *base])
    two = run_json([mpiexec, "-np", "2", *base])
    if two["ranks"] != 2 or one["ranks"] != 1:
        sys.exit(f"ranks: {one['ranks']} and {two['ranks']}, expected 1 and 2")
    if one["best"] != two["best"]:
        sys.exit(f"best design differs:\n-np 1: {one['best']}\n-np 2: {two['best']}")
    if len(one["designs_table"]) != len(two["designs_table"]):
        sys.exit("design counts differ")
    failed = 0
    for a, b in zip(one["designs_table"], two["designs_table"]):
        if a["status"] != b["status"] or a.get("message") != b.get("message") or a["values"] != b["values"]:
            sys.exit(f"design {a['index']} differs:\n{a}\n{b}")
        failed += a["status"] != "ok"
        for key in ("stiff_measure", "reachable_measure"):
            if abs(a[key] - b[key]) > 1e-12 * max(abs(a[key]), 1e-300):
                sys.exit(f"design {a['index']}: {key} {a[key]} on 1 rank, {b[key]} on 2")
    if failed != 1:
        sys.exit(f"{failed} failed designs, expected 1 (arm 600, forearm 500)")
    best = two["best"]
    with tempfile.TemporaryDirectory() as top:
        a, b = os.path.join(top, "a"), os.path.join(top, "b")
        os.makedirs(a), os.makedirs(b)
        shutil.copy(robot, os.path.join(a, "robot.yaml"))  # rank 1's folder has none
        args = [kinestat, "design", "robot.yaml", *options, "--quiet"]
        try:
            done = subprocess.run([mpiexec, "-np", "1", "-wdir", a, *args, ":", "-np", "1", "-wdir", b, *args],
                                  capture_output=True, text=True, timeout=60)
        except subprocess.TimeoutExpired:
            sys.exit("robot file on rank 0 only: still running after 60 s (a hang)")
        if done.returncode == 0 or "MPI rank 1: robot.yaml" not in done.stderr:
            sys.exit(f"robot file on rank 0 only: exit {done.returncode}, stderr:\n{done.stderr}")
    print(f"{len(two['designs_table'])} designs on 1 and 2 ranks agree; best {best['parameters']}, "
          f"stiff {best['stiff_measure']:.6g} m^3; the failed design's message came through")


if __name__ == "__main__":
    main()
