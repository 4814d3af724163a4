"""The long calls release the GIL. Asserted: Python code of another thread runs while a sweep is in
C++ (it could not if the call held the GIL). Printed as a figure, not asserted (the machine may be
busy): two threads running a sweep each take about as long as one when two cores are free."""
import threading
import time

import numpy as np

import kinestat as ks

mech = ks.mechanisms


def sweep(kernel, points, out, k):
    out[k] = mech.evaluate_postures(kernel, points, threads=1).stiffness


def test_python_runs_during_a_sweep():
    kernel = mech.make_reference_five_bar_kernel()
    x, y = np.meshgrid(np.linspace(-0.06, 0.06, 40), np.linspace(0.0, 0.15, 25))
    points = np.stack([x, y, 0 * x], axis=-1)
    count, stop = [0], threading.Event()

    def counter():
        while not stop.is_set():
            count[0] += 1

    t = threading.Thread(target=counter)
    t.start()
    try:
        for _ in range(3):
            before = count[0]
            mech.evaluate_postures(kernel, points, threads=1)
            during = count[0] - before
            if during > 1000:
                break
    finally:
        stop.set()
        t.join()
    # Holding the GIL, the call would leave the counter where it was (a few steps at most).
    assert during > 1000, during


def test_two_threads_run_sweeps_side_by_side():
    kernel = mech.make_reference_five_bar_kernel()
    x, y = np.meshgrid(np.linspace(-0.06, 0.06, 40), np.linspace(0.0, 0.15, 25))
    points = np.stack([x, y, 0 * x], axis=-1)
    out = [None, None]
    t0 = time.perf_counter()
    sweep(kernel, points, out, 0)
    one = time.perf_counter() - t0
    threads = [threading.Thread(target=sweep, args=(kernel, points, out, k)) for k in range(2)]
    t0 = time.perf_counter()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    two = time.perf_counter() - t0
    print(f"\nGIL figure: one sweep {one:.3f} s, two sweeps on two threads {two:.3f} s, ratio {two / one:.2f} "
          f"(1.0 = fully parallel, 2.0 = serialized; {points.size // 3} postures per sweep)")
    np.testing.assert_array_equal(out[0], out[1])
