"""kinestat: stiffness of robots and frames (MSA, VJM, FEA, the five-bar and the Orthoglide).

The Python API mirrors the C++ API (docs/python.md): the C++ namespaces are submodules

    kinestat            core and elements: Material, Section, stiffness_indices, ... and the exceptions
    kinestat.solver     linear-solver options and reports
    kinestat.msa        Structure -> solve() -> Solution, Workspace for posture sweeps
    kinestat.vjm        Chain, equilibrium, unloaded and loaded stiffness
    kinestat.fea        meshes and the FEA link stiffness (with the result cache)
    kinestat.mechanisms five-bar, Orthoglide, posture kernels and evaluate_postures
    kinestat.io         structure/model files, JSON and VTK output
    kinestat.robots     robots from files: robots.load(path) -> RobotModel (solve, kernel for maps)

Units are SI (m, N, rad, Pa) in and out; vectors and matrices are NumPy arrays. Failures raise
InputError (bad input, the CLI's "FILE:LINE: ..." message), SingularError (with .diagnosis) or
NotConvergedError, all subclasses of KinestatError.

    import kinestat as ks
    s = ks.io.read_structure_yaml("models/five_bar.yaml")
    sol = ks.msa.solve(s)
    print(sol.case("Fx").displacement[4, :3])   # node '5' moves (m)
"""
from ._kinestat import *  # noqa: F401,F403  (core and elements)
from ._kinestat import (KinestatError, InputError, SingularError, NotConvergedError,  # noqa: F401
                        __version__)

# The star import brought the extension's submodules; the package's own modules (which add the
# pure-Python helpers) take their names.
del solver, msa, vjm, fea, mechanisms, io  # noqa: F821
from . import solver, msa, vjm, fea, mechanisms, io, robots  # noqa: E402,F401
