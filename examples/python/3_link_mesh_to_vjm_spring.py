"""Example 3: a link mesh turned into a VJM spring, and what it changes for the robot.

The Orthoglide's parallelogram bar (meshes/parallelogram_bar.off: 310.6 mm between its bores, a
20 x 10 mm section with end bosses) is meshed with quadratic tetrahedra and solved by FEA for the 6x6
stiffness of its distal bore relative to the clamped proximal bore (docs/fea.md), through the result
cache. That 6x6, turned from the mesh axes into the chain's (x along the bar, y the pin axis:
a rotation of -90 deg about x), replaces the default beam spring of the model's tube bars
(OrthoglideStiffnessModel.bar_spring). The plot compares the 3-PRPaR's weakest translational and
rotational stiffness at Q0, Q1 and Q2 with both springs. The mesh is coarse (size 8 mm) so that the
example runs in seconds; docs/fea.md shows how the answer converges.

Run: PYTHONPATH=build/python /usr/bin/python3 examples/python/3_link_mesh_to_vjm_spring.py
Writes link_mesh_to_vjm_spring.png in the current folder.
"""
import os
import pathlib

import matplotlib.pyplot as plt
import numpy as np

import kinestat as ks

mech, fea = ks.mechanisms, ks.fea
source = pathlib.Path(os.environ.get("KINESTAT_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))

model = mech.OrthoglideStiffnessModel()
run = fea.link_stiffness_from_file(str(source / "meshes/parallelogram_bar.off"), material=model.bar_material,
                                   clamp="box:-6.5,-6.5,-8,6.5,6.5,8", reference="box:304.1,-6.5,-8,317.1,6.5,8",
                                   reference_point=[310.6, 0, 0], size=8.0, cache=".kinestat_cache")
bar = run.result
print(f"bar FEA: {bar.num_elements} elements, {bar.num_dofs} dofs{' (from the cache)' if run.from_cache else ''}")
print("bar stiffness diagonal (mesh axes; N/m, N m/rad):", np.array2string(np.diag(bar.stiffness), precision=4))

T = ks.rotation6(ks.axis_angle([1, 0, 0], -np.pi / 2))  # mesh axes -> chain axes (pin axis z -> y)
with_fea = mech.OrthoglideStiffnessModel()
with_fea.bar_spring = T @ bar.stiffness @ T.T

points = {"Q0": mech.paper_table_point(0.0), "Q1": mech.paper_table_point(-73.65), "Q2": mech.paper_table_point(126.35)}
values = {}
for label, m in (("beam spring (tube bars)", model), ("FEA spring (mesh)", with_fea)):
    values[label] = []
    for p in points.values():
        K = mech.orthoglide_stiffness(m, mech.OrthoglideArchitecture.PRPAR, p).unloaded.stiffness
        values[label].append([np.linalg.eigvalsh(K[:3, :3])[0] / 1e3, np.linalg.eigvalsh(K[3:, 3:])[0]])
    print(label + ": k_t,min (N/mm) / k_r,min (N m/rad) at Q0, Q1, Q2 =",
          "; ".join(f"{t:.4g} / {r:.4g}" for t, r in values[label]))

fig, axes = plt.subplots(1, 2, figsize=(9, 4))
for j, (ax, what) in enumerate(zip(axes, ["smallest translational stiffness (N/mm)",
                                          "smallest rotational stiffness (N m/rad)"])):
    for i, (label, v) in enumerate(values.items()):
        ax.bar(np.arange(3) + (i - 0.5) * 0.38, np.array(v)[:, j], width=0.38, label=label)
    ax.set_xticks(range(3), list(points))
    ax.set_ylabel(what)
axes[0].legend()
fig.suptitle("Orthoglide 3-PRPaR: parallelogram bar as a beam or from its FEA mesh")
fig.tight_layout()
fig.savefig("link_mesh_to_vjm_spring.png", dpi=120)
