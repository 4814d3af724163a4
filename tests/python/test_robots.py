"""Robots from files through Python (kinestat.robots, docs/python.md "Robots from files"): a file read
with parameters, its kinematics at home, its kernel's map equal to the CLI's and to the kernel
evaluated point by point, the reader's messages as InputError, and a posture kernel written in
Python (a subclass of mechanisms.PostureKernel) in the map machinery."""
import json
import os
import pathlib
import subprocess
import threading

import numpy as np
import pytest

import kinestat as ks
from conftest import SOURCE_DIR

mech = ks.mechanisms
ROBOTS = SOURCE_DIR / "models" / "robots"
DELTA_BOX = [(-0.2, 0.2), (-0.2, 0.2), (-0.9, -0.7)]  # m: the CLI's --box -200:200,-200:200,-900:-700
DELTA_STEP = 0.05                                     # m: --step 50


def weakest_translational_stiffness(C):
    # k_t_min (docs/maps.md): the smallest eigenvalue of C_tt^-1, from the 6x6 compliance (SI).
    return np.linalg.eigvalsh(np.linalg.inv(C[:3, :3])).min()


@pytest.fixture(scope="module")
def delta():
    return ks.robots.load(ROBOTS / "delta.yaml")


@pytest.fixture(scope="module")
def delta_map(delta):
    grid = mech.make_map_grid(DELTA_BOX, DELTA_STEP)
    return mech.compute_workspace_map(delta.kernel(), grid)


def test_load_reads_the_file_with_parameters():
    m = ks.robots.load(str(ROBOTS / "delta.yaml"), params={"arm": 320})
    assert isinstance(m, mech.RobotModel)
    assert m.name == "Delta (Clavel)" and m.task == ["x", "y", "z"] and m.num_legs == 3
    assert m.params["arm"] == 320.0 and m.params["forearm"] == 800.0  # the file's units (mm)
    assert m.params["reach"] == 200 + 320 - 50                          # later parameters follow the override
    # Home: the arms horizontal, the platform at -sqrt(forearm^2 - reach^2) below the base (m).
    np.testing.assert_allclose(m.home_task, [0, 0, -np.sqrt(0.8**2 - 0.47**2)], atol=1e-15)
    np.testing.assert_allclose(m.home_tool[:3, 3], m.home_task, atol=1e-15)
    assert m.workspace == [(-0.4, 0.4), (-0.4, 0.4), (-1.0, -0.5)]
    assert m.default_map_axes == [0, 1, 2]
    assert len(m.coordinate_names) == m.num_coordinates == 15 and sum(m.actuated) == 3
    assert ks.robots.read_robot_params(str(ROBOTS / "delta.yaml"))[1] == "mm"
    assert ks.robots.is_robot_file(str(ROBOTS / "delta.yaml"))


def test_hexapod_solves_at_home():
    h = ks.robots.load(ROBOTS / "hexapod.yaml")
    assert h.task == ["x", "y", "z", "rx", "ry", "rz"] and h.num_legs == 6
    s = h.solve(h.home_task)
    assert s.status == "ok" and s.ok and s.message == ""
    assert s.q.shape == (h.num_coordinates,)
    np.testing.assert_allclose(s.q, 0.0, atol=1e-12)
    np.testing.assert_allclose(s.tool, h.home_tool, atol=1e-12)
    assert 0 < s.singularity_measure <= 1
    # A pose away from home: the tool reaches it, and its task values are the ones asked for.
    task = h.home_task + [0.05, -0.03, 0.02, np.radians(3), np.radians(-2), np.radians(5)]
    s = h.solve(task)
    assert s.status == "ok"
    np.testing.assert_allclose(mech.task_values(h, s.tool), task, atol=1e-12)
    # From that solution, a neighbour by one Newton solve.
    t = h.solve(task + 1e-3, start=s, continuation=False)
    assert t.status == "ok"


def test_overconstrained_robot_names_its_redundant_equations():
    # The 3-PRPaR's legs each hold the platform against two rotations: three of the nine constraint
    # equations on rotations are redundant; its solutions close every equation (the kinematics checks
    # the redundant ones), so the platform keeps its orientation.
    p = ks.robots.load(ROBOTS / "orthoglide_prpar.yaml")
    assert len(p.redundant_equations) == 3
    assert all(e.split()[-1] in ("rx", "ry", "rz") for e in p.redundant_equations)
    assert ks.robots.load(ROBOTS / "hexapod.yaml").redundant_equations == []
    s = p.solve([0.05, -0.03, 0.02])
    assert s.status == "ok"
    np.testing.assert_allclose(s.tool[:3, :3], np.eye(3), atol=1e-12)
    np.testing.assert_allclose(s.tool[:3, 3], [0.05, -0.03, 0.02], atol=1e-12)


def test_load_computes_fea_link_springs(tmp_path):
    # A 3-RPR whose links are meshes/bar.off (docs/robots.md, `fea:` link springs): robots.load meshes
    # and solves it (coarse: a fraction of a second) between reading and building; a missing mesh is
    # the reader's InputError with FILE:LINE.
    (tmp_path / "bar.off").write_bytes((SOURCE_DIR / "meshes" / "bar.off").read_bytes())
    text = """robot: 3-RPR of bars
units: mm-N-s
params: {px: 25, py: 43.30127, a: px + sqrt(200^2 - py^2)}
planar: true
task: [x, y, rz]
tool: [0, 0, 0]
legs:
  - copies: 3
    chain:
      - revolute: {at: [a, 0, 0], axis: [0, 0, 1]}
      - prismatic: {at: [a, 0, 0], axis: [px - a, py, 0], actuated: true}
      - link: {to: [px, py, 0], spring: {fea: {mesh: MESH, material: steel, clamp: x=0, reference: x=200, size: 20}}}
      - revolute: {at: [px, py, 0], axis: [0, 0, 1]}
"""
    (tmp_path / "fea.yaml").write_text(text.replace("MESH", "bar.off"))
    r = ks.robots.load(tmp_path / "fea.yaml")
    s = r.solve(r.home_task)
    assert s.ok
    K = ks.vjm.platform_unloaded_stiffness(r.vjm_chains(s)).stiffness
    assert np.all(np.isfinite(K)) and np.all(np.diag(K) > 0)
    (tmp_path / "missing.yaml").write_text(text.replace("MESH", "missing.off"))
    with pytest.raises(ks.InputError, match=r"missing\.yaml:12: .*no such mesh file"):
        ks.robots.load(tmp_path / "missing.yaml")


def test_solve_reports_failures_as_statuses(delta):
    s = delta.solve([0, 0, -2.0])  # 2 m below the base: out of reach
    assert s.status == "unreachable" and not s.ok and s.message and not s.closed
    assert s.kinematics_status == mech.KinematicsStatus.UNREACHABLE
    s = delta.solve([0.4, 0.4, -0.55])  # closes, with leg 3's shoulder at 81 deg (limits +-80)
    assert s.status == "unreachable" and s.closed and "outside its limits" in s.message
    with pytest.raises(ks.InputError, match="3 task coordinates"):
        delta.solve([0, 0])
    with pytest.raises(ks.InputError, match="not finite"):
        delta.solve([0, np.nan, -0.8])
    with pytest.raises(ks.InputError, match="solved posture"):
        delta.vjm_chains(s)


def test_delta_map_is_the_clis(delta_map):
    m = delta_map
    assert m.shape == (5, 9, 9) and m.description == "Delta (Clavel) (VJM, unloaded)"
    assert m.status_counts["ok"] == m.grid.num_points()
    cli = pathlib.Path(os.environ.get("KINESTAT_BINARY_DIR", SOURCE_DIR / "build")) / "src/cli/kinestat"
    if not cli.exists():
        pytest.skip(f"{cli} is not built")
    run = subprocess.run([str(cli), "map", str(ROBOTS / "delta.yaml"), "--box", "-200:200,-200:200,-900:-700",
                          "--step", "50", "--quiet", "--json", "-"], capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    j = json.loads(run.stdout)
    assert j["grid"]["dimensions"] == [9, 9, 5] and j["status"] == m.status.ravel().tolist()
    for field in ["k_t_min", "k_r_min", "trace", "singularity_measure"]:
        np.testing.assert_allclose(np.array(j["fields"][field]), m.field(field).ravel(), rtol=1e-12, atol=0)


def test_delta_map_equals_the_kernel_point_by_point(delta, delta_map):
    m, kernel = delta_map, delta.kernel()
    x, y, z = m.grid.axes
    points = np.stack(np.meshgrid(x, y, z, indexing="xy"), axis=-1)  # (ny, nx, nz, 3)
    points = np.moveaxis(points, 2, 0)                                  # (nz, ny, nx, 3): the map's order
    r = mech.evaluate_postures(kernel, points)
    assert (r.status == 0).all()
    kt = np.vectorize(lambda k, j, i: weakest_translational_stiffness(r.compliance[k, j, i]))(*np.indices(m.shape))
    # The map's first point is solved from home, as evaluate_postures solves every point: the same
    # value; the others continue from their grid neighbour (one Newton solve), equal to its tolerance.
    assert m.field("k_t_min")[0, 0, 0] == pytest.approx(kt[0, 0, 0], rel=1e-12)
    np.testing.assert_allclose(m.field("k_t_min"), kt, rtol=1e-9)
    np.testing.assert_allclose(m.field("trace"), np.trace(r.stiffness, axis1=-2, axis2=-1), rtol=1e-9)
    # One point three ways: the kernel, evaluate_postures, and the VJM engine on the model's chains.
    k, j, i = 2, 3, 6
    p = np.array([x[i], y[j], z[k]])
    K = kernel.evaluate(p).stiffness
    np.testing.assert_array_equal(K, r.stiffness[k, j, i])
    Kv = ks.vjm.platform_unloaded_stiffness(delta.vjm_chains(p)).stiffness
    np.testing.assert_allclose(Kv, K, rtol=1e-12, atol=1e-12 * np.abs(K).max())


def test_loaded_kernel_gives_deflections(delta):
    grid = mech.make_map_grid([(-0.1, 0.1), 0.0, (-0.85, -0.75)], 0.05)
    options = mech.MapOptions()
    options.with_deflection = True
    m = mech.compute_workspace_map(delta.kernel(wrench=[0, 0, -100, 0, 0, 0]), grid, options)
    assert m.status_counts["ok"] == grid.num_points()
    assert "deflection_t" in m.field_names and (m.field("deflection_t") > 0).all()
    with pytest.raises(ks.InputError, match="not both"):
        delta.kernel(wrench=np.zeros(6), displacement=np.zeros(6))
    with pytest.raises(ks.InputError, match="task coordinates"):
        delta.kernel(task=[0, 0])


def test_bad_files_raise_the_readers_messages(tmp_path):
    with pytest.raises(ks.InputError, match="no parameter 'armx'"):
        ks.robots.load(ROBOTS / "delta.yaml", params={"armx": 300})
    with pytest.raises(ks.InputError, match="not a number"):
        ks.robots.load(ROBOTS / "delta.yaml", params={"arm": "long"})
    with pytest.raises(ks.InputError, match="cannot open"):
        ks.robots.load(tmp_path / "missing.yaml")
    bad = tmp_path / "delta_bad.yaml"
    bad.write_text((ROBOTS / "delta.yaml").read_text().replace("axis: [0, 1, 0]", "axis: [0, 0, 0]"))
    with pytest.raises(ks.InputError, match=r"delta_bad\.yaml:\d+"):
        ks.robots.load(bad)


class QuadraticKernel(mech.PostureKernel):
    """A Python kernel: a stiffness that grows with x^2, its own 'kinematics' (unreachable beyond
    |x| > 0.1); it records the points in the order it sees them."""

    def __init__(self):
        super().__init__()
        self.points = []
        self.next_calls = 0

    def evaluate_next(self, point):
        self.next_calls += 1
        return self.evaluate(point)

    def evaluate(self, point):
        self.points.append(np.array(point))
        if abs(point[0]) > 0.1 + 1e-12:
            return mech.PostureResult(mech.PostureStatus.UNREACHABLE)
        k = 1e6 * (1 + point[0] ** 2)
        return mech.PostureResult(mech.PostureStatus.OK, stiffness=np.diag([k, 2 * k, 3 * k, 1e3, 1e3, 1e3]),
                                  singularity_measure=0.5)


def test_python_kernel_maps():
    kernel = QuadraticKernel()
    grid = mech.make_map_grid([(-0.2, 0.2), (0.0, 0.1), 0.0], 0.05)
    options = mech.MapOptions()
    options.threads = 2  # a Python kernel runs on one thread whatever is asked
    m = mech.compute_workspace_map(kernel, grid, options)
    assert m.description == "QuadraticKernel (Python)"
    assert len(kernel.points) == grid.num_points()
    # One thread, in the map's order: a serpentine path (each point a grid neighbour of the one before,
    # so evaluate_next after the first) within one chunk of 256 points.
    assert kernel.next_calls == grid.num_points() - 1
    steps = np.abs(np.diff(np.array(kernel.points), axis=0)).sum(axis=1)
    np.testing.assert_allclose(steps, 0.05, rtol=1e-9)
    x = grid.axes[0]
    reach = np.abs(x) <= 0.1 + 1e-12
    assert m.status_counts["ok"] == reach.sum() * 3 and m.status_counts["unreachable"] == (~reach).sum() * 3
    np.testing.assert_allclose(m.field("k_t_min")[0][:, reach], np.broadcast_to(1e6 * (1 + x[reach] ** 2), (3, reach.sum())),
                               rtol=1e-12)
    assert np.isnan(m.field("k_t_min")[0][:, ~reach]).all()
    r = mech.evaluate_postures(kernel, np.zeros((2, 3)), threads=2)
    np.testing.assert_allclose(r.translational_eigenvalues, [[1e6, 2e6, 3e6]] * 2)
    assert kernel.clone().evaluate([0.05, 0, 0]).status == mech.PostureStatus.OK  # a clone calls the same object


def test_python_kernel_with_the_robots_kinematics(delta):
    """The route a user takes for their own kinematics: solve in Python, stiffness by the vjm engine,
    the map machinery around it. Here it rebuilds the Delta's kernel, so the values must agree."""

    class DeltaInPython(mech.PostureKernel):
        def __init__(self):
            super().__init__()

        def evaluate(self, point):
            s = delta.solve(point)
            if not s.ok:
                return mech.PostureResult(mech.PostureStatus.UNREACHABLE, singularity_measure=s.singularity_measure)
            K = ks.vjm.platform_unloaded_stiffness(delta.vjm_chains(s))
            return mech.PostureResult(mech.PostureStatus.OK, stiffness=K.stiffness, compliance=K.compliance,
                                      singularity_measure=s.singularity_measure)

        def description(self):
            return "Delta in Python"

    grid = mech.make_map_grid([(-0.1, 0.1), (-0.1, 0.1), -0.8], 0.1)
    points = np.array([grid.point(i) for i in range(grid.num_points())])
    mine = mech.evaluate_postures(DeltaInPython(), points)
    theirs = mech.evaluate_postures(delta.kernel(), points)
    assert (mine.status == 0).all() and (theirs.status == 0).all()
    np.testing.assert_allclose(mine.stiffness, theirs.stiffness, rtol=1e-12, atol=1e-12 * np.abs(theirs.stiffness).max())
    assert mech.compute_workspace_map(DeltaInPython(), grid).description == "Delta in Python"


def test_python_kernel_errors_reach_the_caller():
    class Raises(mech.PostureKernel):
        def evaluate(self, point):
            raise ZeroDivisionError("my kinematics failed")

    class ForgetsStiffness(mech.PostureKernel):
        def evaluate(self, point):
            return mech.PostureResult(mech.PostureStatus.OK)

    class NoInit(mech.PostureKernel):
        def __init__(self):
            pass

    grid = mech.make_map_grid([(0.0, 0.1), (0.0, 0.1), 0.0], 0.05)
    with pytest.raises(ZeroDivisionError, match="my kinematics failed"):
        mech.compute_workspace_map(Raises(), grid)
    with pytest.raises(ks.InputError, match="needs the stiffness"):
        mech.evaluate_postures(ForgetsStiffness(), np.zeros((1, 3)))
    with pytest.raises(ks.InputError, match="NEAR_SINGULAR is a map's verdict"):
        mech.PostureResult(mech.PostureStatus.NEAR_SINGULAR, stiffness=np.eye(6))
    with pytest.raises(TypeError, match="__init__"):
        NoInit()


def test_python_kernels_in_two_threads(delta):
    """Each map takes the GIL per point of its Python kernel and releases it between: two threads each
    mapping (one a Python kernel, one the C++ robot kernel) both finish, with the values of one alone."""
    grid = mech.make_map_grid([(-0.2, 0.2), (0.0, 0.1), 0.0], 0.01)
    alone = mech.compute_workspace_map(QuadraticKernel(), grid).field("k_t_min")
    delta_grid = mech.make_map_grid([(-0.1, 0.1), (-0.1, 0.1), -0.8], 0.02)
    delta_alone = mech.compute_workspace_map(delta.kernel(), delta_grid).field("k_t_min")
    results, errors = {}, []

    def run(name, kernel, g):
        try:
            results[name] = mech.compute_workspace_map(kernel, g).field("k_t_min")
        except Exception as e:  # noqa: BLE001 (reported below)
            errors.append(e)

    threads = [threading.Thread(target=run, args=("python", QuadraticKernel(), grid)),
               threading.Thread(target=run, args=("delta", delta.kernel(), delta_grid))]
    for t in threads:
        t.start()
    run("python 2", QuadraticKernel(), grid)
    for t in threads:
        t.join(timeout=120)
        assert not t.is_alive()
    assert not errors
    np.testing.assert_array_equal(results["python"], alone)
    np.testing.assert_array_equal(results["python 2"], alone)
    np.testing.assert_array_equal(results["delta"], delta_alone)
