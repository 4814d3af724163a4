"""Robots from files (docs/robots.md, models/robots/): any parallel robot written as a YAML file of
legs, joints and links, with its closed-loop kinematics and its posture kernel for workspace maps.

    import kinestat as ks
    robot = ks.robots.load("models/robots/delta.yaml", params={"arm": 320})   # params in the file's units
    s = robot.solve([0.1, 0, -0.8])          # task values (m, rad): s.status, s.q, s.tool (4x4)
    kernel = robot.kernel()                   # a mechanisms.PostureKernel (VJM), as `kinestat map` runs
    grid = ks.mechanisms.make_map_grid([(-0.2, 0.2), (-0.2, 0.2), (-0.9, -0.7)], 0.05)
    smap = ks.mechanisms.compute_workspace_map(kernel, grid)

The C++ API it wraps is mechanisms.RobotModel (robot_model.hpp, robot_kernel.hpp) and
io.read_robot_model (robot_yaml.hpp); the names here are those."""
from ._kinestat.mechanisms import (RobotModel, RobotSolution, RobotKernelOptions, KinematicsStatus,  # noqa: F401
                                   make_robot_kernel, task_values)
from ._kinestat.io import read_robot_model, read_robot_params, is_robot_file  # noqa: F401


def load(path, params=None):
    """Reads and checks a robot file into a RobotModel, its links' `fea:` springs computed (meshing
    and FEA, or their cache). params: {name: value} in the file's units
    (its `units:`), replacing the file's values (a design's parameters). Raises InputError with the
    CLI's message ("FILE:LINE: ...", or "no parameter 'NAME' to set; ...")."""
    return read_robot_model(str(path), params)
