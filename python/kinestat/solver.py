"""Linear-solver options and factorization reports (C++ kinestat::solver)."""
from ._kinestat.solver import *  # noqa: F401,F403
