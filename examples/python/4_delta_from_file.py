"""Example 4: a robot from a file, the Delta (Clavel), with two arm lengths compared.

models/robots/delta.yaml describes the Delta in thirty lines (docs/robots.md); kinestat.robots.load
reads it with a parameter replaced, as `kinestat design --param arm=...` does (values in the file's
units, mm). The robot's kernel (closed-loop kinematics and VJM stiffness) goes into the same
compute_workspace_map as the built-in robots'; the map is the horizontal slice 800 mm below the base,
k_t_min in N/mm, blank where the platform cannot go.

Run: PYTHONPATH=build/python /usr/bin/python3 examples/python/4_delta_from_file.py
Writes delta_arm_lengths.png in the current folder.
"""
import os
import pathlib

import matplotlib.pyplot as plt

import kinestat as ks

source = pathlib.Path(os.environ.get("KINESTAT_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
m = ks.mechanisms
grid = m.make_map_grid([(-0.4, 0.4), (-0.4, 0.4), -0.8], step=0.01)  # x, y ranges and z (m)
x, y, _ = grid.axes
fig, axes = plt.subplots(1, 2, figsize=(11, 4.8), constrained_layout=True)
for ax, arm in zip(axes, [300, 360]):  # mm
    robot = ks.robots.load(source / "models/robots/delta.yaml", params={"arm": arm})
    home = robot.solve(robot.home_task)
    print(f"{robot.name}, arm {arm} mm: home at z = {robot.home_task[2] * 1e3:.1f} mm ({home.status}), "
          f"{robot.num_coordinates} joint coordinates in {robot.num_legs} legs")
    smap = m.compute_workspace_map(robot.kernel(), grid)
    kt = smap.field("k_t_min")[0] / 1e3  # N/mm
    mesh = ax.pcolormesh(x * 1e3, y * 1e3, kt, shading="auto", cmap="viridis")
    fig.colorbar(mesh, ax=ax, label="k_t_min (N/mm)")
    s = smap.summary("k_t_min")
    ax.set(xlabel="x (mm)", ylabel="y (mm)", aspect="equal",
           title=f"arm {arm} mm\nreachable {smap.reachable_measure:.3f} m², k_t_min {s.min / 1e3:.0f} to "
                 f"{s.max / 1e3:.0f} N/mm")
    print(f"  z = -800 mm: {smap.status_counts}; weakest {s.min / 1e3:.1f} N/mm at {s.argmin * 1e3} mm")
fig.suptitle("Delta (Clavel) from models/robots/delta.yaml, z = -800 mm")
fig.savefig("delta_arm_lengths.png", dpi=100)
