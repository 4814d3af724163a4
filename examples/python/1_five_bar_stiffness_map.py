"""Example 1: a stiffness map of the five-bar (Goncalves et al. 2010) with matplotlib.

k_t_min, the stiffness of the platform point P in its weakest direction (N/mm), over the plane, for
the ++ working mode and the up assembly mode: what `kinestat map fivebar --step 1` computes.
compute_workspace_map runs the MSA sweep kernel on every point of the grid (all cores, the GIL
released) and returns fields as NumPy arrays of shape (nz, ny, nx), NaN (blank) where P is out of
reach. The same map is also written as the CLI writes it (PNG with the singular loci drawn over
it, VTI for ParaView, JSON).

Run: PYTHONPATH=build/python /usr/bin/python3 examples/python/1_five_bar_stiffness_map.py
Writes five_bar_stiffness_map.png (matplotlib) and five_bar_map.png/.vti/.json (kinestat's) in the current folder.
"""
import matplotlib.pyplot as plt

import kinestat as ks

m = ks.mechanisms
grid = m.make_map_grid([(-0.11, 0.11), (-0.03, 0.17), 0.0], step=0.001)         # x, y ranges and z (m)
stiffness_map = m.compute_workspace_map(m.make_five_bar_kernel(), grid)  # ++ up, MSA (the sweep kernel)
x, y, _ = grid.axes
plt.pcolormesh(x * 1e3, y * 1e3, stiffness_map.field("k_t_min")[0] / 1e3, shading="auto", cmap="viridis")
plt.colorbar(label="k_t_min: stiffness in the weakest direction (N/mm)")
plt.gca().set(xlabel="x (mm)", ylabel="y (mm)", title="Five-bar ++ up: stiffness at P", aspect="equal")
plt.savefig("five_bar_stiffness_map.png", dpi=120)

# The files of `kinestat map fivebar --step 1 --png --vti --json`, from the same library functions.
stiffness_map.curves = m.five_bar_singular_loci(m.FiveBarParams(), m.WorkingMode(1, 1), m.Assembly.UP)
ks.io.write_workspace_map_png("five_bar_map.png", stiffness_map, "k_t_min")
ks.io.write_map_vti("five_bar_map.vti", stiffness_map)
ks.io.write_json("five_bar_map.json", ks.io.workspace_map_to_json(stiffness_map), indent=-1)  # compact
s = stiffness_map.summary("k_t_min")
print(f"{stiffness_map.description}: {stiffness_map.status_counts}; k_t_min {s.min / 1e3:.3g} to {s.max / 1e3:.3g} "
      f"N/mm, reachable area {stiffness_map.reachable_measure * 1e6:.0f} mm^2")
