"""The GIL figure of the Python module (issue 10): one workspace map computed in one Python thread,
then two maps in two Python threads at once, each map on one C++ thread. compute_workspace_map
releases the GIL, so on a machine with two free cores the two threads take about as long as one
(ratio ~1.0); a call that held the GIL would serialize them (ratio ~2.0). The quiet-machine figure
is in benchmarks/README.md; tests/python/test_gil.py runs this script without a bound on the ratio
(it depends on free cores: a CI run at load 2.3 read 1.71); the test asserts the GIL's release by
counting another thread's steps during a call instead.

Run: PYTHONPATH=build/python /usr/bin/python3 benchmarks/python/bench_gil.py [--step MM] [--repeat N]
"""
import argparse
import os
import threading
import time

import kinestat as ks

mech = ks.mechanisms


def one_map(kernel, grid, out, k):
    options = mech.MapOptions()
    options.threads = 1  # one C++ thread per Python thread: the parallelism measured is Python's
    out[k] = mech.compute_workspace_map(kernel, grid, options)


def timed(kernel, grid, threads):
    out = [None] * threads
    workers = [threading.Thread(target=one_map, args=(kernel, grid, out, k)) for k in range(threads)]
    start = time.perf_counter()
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    return time.perf_counter() - start, out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--step", type=float, default=2.0, help="grid step in mm (default 2: 11 000 points)")
    parser.add_argument("--repeat", type=int, default=3, help="runs of each case; the fastest is reported")
    args = parser.parse_args()
    # The reference kernel (posture by posture, ~0.1 ms each): long enough in C++ for a figure.
    kernel = mech.make_reference_five_bar_kernel()  # the paper's five-bar, ++ up, MSA
    grid = mech.make_map_grid([(-0.1, 0.1), (-0.03, 0.18), 0.0], args.step * 1e-3)
    one = min(timed(kernel, grid, 1)[0] for _ in range(args.repeat))
    runs = [timed(kernel, grid, 2) for _ in range(args.repeat)]
    two = min(t for t, _ in runs)
    a, b = runs[0][1]
    # Both threads computed the same map: the figure is of real work.
    assert (a.status == b.status).all()
    print(f"kinestat {ks.__version__}, {os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f}")
    print(f"one map of {grid.num_points()} points in one thread:  {one:.3f} s")
    print(f"two maps in two threads at once:          {two:.3f} s")
    print(f"ratio two / one: {two / one:.2f}  (1.0: the threads ran side by side; 2.0: serialized by the GIL)")


if __name__ == "__main__":
    main()
