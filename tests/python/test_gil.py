"""The long calls release the GIL: two Python threads running a posture sweep each take about as
long as one when two cores are free. The ratio is printed as a figure (the machine may be busy);
the test asserts only that both threads finish with the same results as one."""
import threading
import time

import numpy as np

import kinestat as ks

mech = ks.mechanisms


def sweep(kernel, points, out, k):
    out[k] = mech.evaluate_postures(kernel, points, threads=1).stiffness


def test_two_threads_run_sweeps_side_by_side():
    kernel = mech.make_reference_five_bar_kernel()
    x, y = np.meshgrid(np.linspace(-0.1, 0.1, 40), np.linspace(0.05, 0.18, 25))
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
