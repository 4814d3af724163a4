"""Matrix structural analysis (C++ kinestat::msa): build or read a Structure, solve() it into a Solution;
a Workspace keeps the symbolic factorization across the solves of a posture sweep."""
from ._kinestat.msa import *  # noqa: F401,F403
