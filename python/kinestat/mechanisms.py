"""Mechanisms (C++ kinestat::mechanisms): the five-bar and the Orthoglide, robots from files
(RobotModel, read by kinestat.robots.load), posture kernels (PostureKernel, which a Python class may
subclass) and evaluate_postures (results as NumPy arrays shaped like the grid of points), workspace maps
(compute_workspace_map: fields of shape (nz, ny, nx), NaN where unreachable) and the five-bar design
sweep (sweep_five_bar_designs: shares of shape (r2 steps, r1 steps))."""
from ._kinestat.mechanisms import *  # noqa: F401,F403
