"""Example 2: the Orthoglide's three design strategies and the stiffness they give.

Pashkevich, Wenger, Chablat (2005) size the Orthoglide for a 200 mm cube and velocity transmission
factors in [0.5, 2] by three strategies (Table 3): they give three leg lengths L and three cubes.
Each design goes into the VJM stiffness model (3-PRPaR, Pashkevich et al. 2009, with the model's
nominal link sections and actuators) and is evaluated at the isotropic point Q0 and at the two
Q-axis corners of its cube, Q1 (p_max) and Q2 (p_min), the points of the stiffness paper's tables.

Run: PYTHONPATH=build/python /usr/bin/python3 examples/python/2_orthoglide_design_strategies.py
Writes orthoglide_design_strategies.png in the current folder.
"""
import matplotlib.pyplot as plt
import numpy as np

import kinestat as ks

mech = ks.mechanisms
mu, cube = 0.5, 0.200  # specification: factors in [mu, 1/mu], cube edge (m)

rows = []
for strategy in (1, 2, 3):
    design = mech.design_orthoglide(strategy, mu, cube)
    model = mech.OrthoglideStiffnessModel()
    model.link_length = design.link_length
    points = {"Q0": 0.0, "Q1": design.p_max, "Q2": design.p_min}
    k_min = []
    for name, c in points.items():
        K = mech.orthoglide_stiffness(model, mech.OrthoglideArchitecture.PRPAR, [c, c, c]).unloaded.stiffness
        k_min.append(np.linalg.eigvalsh(K[:3, :3])[0] / 1e3)  # weakest translation (N/mm)
    rows.append(k_min)
    print(f"strategy {strategy}: L = {design.link_length * 1e3:6.1f} mm, cube [{design.p_min * 1e3:7.2f}, "
          f"{design.p_max * 1e3:6.2f}] mm, joints [{design.rho_min * 1e3:6.1f}, {design.rho_max * 1e3:6.1f}] mm; "
          "k_t,min at Q0/Q1/Q2 = " + " / ".join(f"{k:.3g}" for k in k_min) + " N/mm")

rows = np.array(rows)
fig, ax = plt.subplots(figsize=(7, 4.5))
for i, name in enumerate(["Q0 (p = 0)", "Q1 (cube corner p_max)", "Q2 (cube corner p_min)"]):
    ax.bar(np.arange(3) + (i - 1) * 0.27, rows[:, i], width=0.27, label=name)
ax.set_xticks(range(3), [f"strategy {s}" for s in (1, 2, 3)])
ax.set_ylabel("smallest translational stiffness (N/mm)")
ax.set_title(f"Orthoglide 3-PRPaR, {cube * 1e3:.0f} mm cube, factors in [{mu}, {1 / mu:g}]")
ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=3, fontsize="small")
fig.tight_layout()
fig.savefig("orthoglide_design_strategies.png", dpi=120)
