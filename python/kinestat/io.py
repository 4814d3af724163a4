"""Files (C++ kinestat::io): structure, VJM model and target files; JSON results (as dicts) and VTK output."""
from ._kinestat.io import *  # noqa: F401,F403
