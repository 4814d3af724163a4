"""Files (C++ kinestat::io): structure, VJM model and target files; JSON results (as dicts) and VTK
output; the files of maps and design sweeps (JSON, VTI, PNG) as the CLI writes them."""
from ._kinestat.io import *  # noqa: F401,F403
