"""Example 1: a stiffness map of the five-bar (Goncalves et al. 2010) with matplotlib.

The smallest translational stiffness of the platform point P over the plane, for the ++ working mode
and the up assembly mode: the eigenvalue of the 3x3 translational block of the 6x6 Cartesian
stiffness, in N/mm. Blank where P is out of reach; it falls to zero at the singularities.
evaluate_postures runs the MSA posture kernel on every point of the grid (all cores, GIL released)
and returns arrays shaped like the grid.

Run: PYTHONPATH=build/python /usr/bin/python3 examples/python/1_five_bar_stiffness_map.py
Writes five_bar_stiffness_map.png in the current folder.
"""
import matplotlib.pyplot as plt
import numpy as np

import kinestat as ks

x, y = np.meshgrid(np.linspace(-0.11, 0.11, 221), np.linspace(-0.03, 0.17, 201))  # m
kernel = ks.mechanisms.make_reference_five_bar_kernel()  # paper's five-bar, mode ++, assembly up, MSA
r = ks.mechanisms.evaluate_postures(kernel, np.stack([x, y, 0 * x], axis=-1))
plt.pcolormesh(x * 1e3, y * 1e3, r.translational_eigenvalues[..., 0] / 1e3, shading="auto", cmap="viridis")
plt.colorbar(label="smallest translational stiffness (N/mm)")
plt.gca().set(xlabel="x (mm)", ylabel="y (mm)", title="Five-bar ++ up: stiffness at P", aspect="equal")
plt.savefig("five_bar_stiffness_map.png", dpi=120)
print("five_bar_stiffness_map.png:", np.count_nonzero(r.status == 0), "of", r.status.size, "points reachable")
