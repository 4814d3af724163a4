"""Virtual joint method (C++ kinestat::vjm): serial chains, loaded equilibrium, Cartesian stiffness.
Rigid transforms are 4x4 homogeneous matrices."""
from ._kinestat.vjm import *  # noqa: F401,F403
