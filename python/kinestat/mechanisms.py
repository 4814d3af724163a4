"""Mechanisms (C++ kinestat::mechanisms): the five-bar and the Orthoglide, their posture kernels and
evaluate_postures (results as NumPy arrays shaped like the grid of points)."""
from ._kinestat.mechanisms import *  # noqa: F401,F403
