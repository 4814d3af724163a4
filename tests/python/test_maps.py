"""Workspace maps and the five-bar design sweep through Python: the map's values equal the
single-posture bindings (the five-bar's MSA structure, the Orthoglide's VJM model) at sampled points,
unreachable points are NaN and masked where the geometry says P is out of reach, the files are the
CLI's, and the sweep's best design is the one `kinestat design fivebar` picks."""
import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import kinestat as ks

mech = ks.mechanisms


def weakest_translational_stiffness(C):
    # k_t_min: the smallest eigenvalue of C_tt^-1, the stiffness a force meets with the tool free to
    # rotate (docs/maps.md), from the 6x6 compliance (SI).
    return np.linalg.eigvalsh(np.linalg.inv(C[:3, :3])).min()


# The sweep kernels (what `kinestat map` runs) and the reference kernels (posture by posture).
@pytest.fixture(scope="module", params=["sweep", "reference"])
def five_bar_map(request):
    grid = mech.make_map_grid([(-0.1, 0.1), (-0.03, 0.17), 0.0], 0.01)  # m
    make = mech.make_five_bar_kernel if request.param == "sweep" else mech.make_reference_five_bar_kernel
    return mech.compute_workspace_map(make(), grid)


def test_map_arrays_have_the_grid_shape(five_bar_map):
    m = five_bar_map
    assert m.grid.dimensions == [21, 21, 1] and m.shape == (1, 21, 21) == m.grid.shape
    x, y, z = m.grid.axes
    assert x[0] == pytest.approx(-0.1) and x[-1] == pytest.approx(0.1) and y[1] - y[0] == pytest.approx(0.01)
    assert m.status.shape == m.shape and m.status.dtype == np.uint8
    assert m.field("k_t_min").shape == m.shape and m.field(mech.MapField.TRACE).shape == m.shape
    assert "deflection_t" not in m.field_names  # no load: no deflection fields
    with pytest.raises(ks.InputError, match="deflection_t"):
        m.field("deflection_t")
    with pytest.raises(ks.InputError, match="k_t_min, k_t_max"):
        m.field("stiffness")
    counts = m.status_counts
    assert sum(counts.values()) == m.grid.num_points()
    assert counts["ok"] == np.count_nonzero(m.status == mech.PostureStatus.OK.value)


def test_map_values_equal_single_posture_solves(five_bar_map):
    m, params = five_bar_map, mech.FiveBarParams()
    x, y, _ = m.grid.axes
    kt, trace = m.field("k_t_min")[0], m.field("trace")[0]
    ok = np.argwhere(m.status[0] == mech.PostureStatus.OK.value)
    assert len(ok) > 100
    # The reference kernel is the nodal MSA path itself; the sweep kernel solves the same model without
    # the ~7 digits the nodal form loses to the 2e11 N/m joint springs (five_bar_kernel.hpp), so it
    # meets the nodal MSA within that accuracy and the VJM route (which loses none) closely.
    sweep = "reference" not in m.description
    for j, i in ok[:: len(ok) // 7]:
        s = mech.make_five_bar_structure(params, [x[i], y[j]], mech.WorkingMode(1, 1))
        c = ks.msa.cartesian_stiffness(s, mech.FIVE_BAR_PLATFORM_NODE)
        rel = 1e-6 if sweep else 1e-9
        assert kt[j, i] == pytest.approx(weakest_translational_stiffness(c.compliance), rel=rel)
        assert trace[j, i] == pytest.approx(np.trace(c.stiffness), rel=rel)
        if sweep:
            posture = mech.inverse_kinematics(params, [x[i], y[j]], mech.WorkingMode(1, 1))
            v = ks.vjm.platform_unloaded_stiffness(mech.five_bar_vjm_chains(params, posture))
            assert kt[j, i] == pytest.approx(weakest_translational_stiffness(v.compliance), rel=1e-9)


def test_unreachable_points_are_nan_and_masked(five_bar_map):
    m, params = five_bar_map, mech.FiveBarParams()
    x, y, _ = m.grid.axes
    X, Y = np.meshgrid(x, y)
    # P is out of reach where it is farther than r1 + r2 from a base joint A_i = (-+r3, 0).
    far = (np.hypot(X + params.r3, Y) > params.r1 + params.r2 + 1e-9) | (np.hypot(X - params.r3, Y) > params.r1 + params.r2 + 1e-9)
    assert far.any()
    unreachable = m.status[0] == mech.PostureStatus.UNREACHABLE.value
    assert unreachable[far].all()
    for name in m.field_names:
        assert np.isnan(m.field(name)[0][unreachable]).all(), name
    # Points with values have them; the mask is exactly the points without.
    has = (m.status[0] == mech.PostureStatus.OK.value) | (m.status[0] == mech.PostureStatus.NEAR_SINGULAR.value)
    np.testing.assert_array_equal(m.mask[0], ~has)
    assert np.isfinite(m.field("k_t_min")[0][has]).all()
    assert m.reachable_measure == pytest.approx(np.count_nonzero(~unreachable) * 0.01 * 0.01)
    s = m.summary("k_t_min")
    assert s.count == np.count_nonzero(has) and s.min == pytest.approx(np.nanmin(m.field("k_t_min")))


@pytest.mark.parametrize("make", [mech.make_orthoglide_kernel, mech.make_reference_orthoglide_kernel],
                         ids=["sweep", "reference"])
def test_orthoglide_map_equals_the_vjm_model(source_dir, make):
    model = ks.io.read_vjm_model_yaml(str(source_dir / "models/orthoglide_puu.yaml"))
    options = mech.OrthoglideKernelOptions()
    options.model, options.architecture = model.orthoglide, model.architecture
    grid = mech.make_map_grid([(-0.04, 0.04), (-0.04, 0.04), (-0.02, 0.02)], 0.02)  # a 3D box (m)
    m = mech.compute_workspace_map(make(options), grid)
    assert m.shape == (3, 5, 5)
    kt = m.field("k_t_min")
    for k, j, i in [(0, 0, 0), (1, 2, 2), (2, 4, 1)]:
        p = grid.point(i + 5 * (j + 5 * k))
        np.testing.assert_allclose(p, [grid.axes[0][i], grid.axes[1][j], grid.axes[2][k]])
        C = mech.orthoglide_stiffness(model.orthoglide, model.architecture, p).unloaded.compliance
        assert kt[k, j, i] == pytest.approx(weakest_translational_stiffness(C), rel=1e-9)


def test_map_files_are_the_clis(five_bar_map, tmp_path):
    m = five_bar_map
    m.curves = mech.five_bar_singular_loci(mech.FiveBarParams(), mech.WorkingMode(1, 1), mech.Assembly.UP)
    assert [c.label for c in m.curves] == ["workspace boundary", "parallel singularity"]
    assert m.curves[0].lines[0].shape[1] == 3
    j = ks.io.workspace_map_to_json(m)
    assert j["schema"] == "kinestat-workspace-map" and j["grid"]["dimensions"] == [21, 21, 1]
    flat = m.field("k_t_min").ravel()  # x fastest, as the JSON's flat arrays
    values = np.array([np.nan if v is None else v for v in j["fields"]["k_t_min"]])
    np.testing.assert_array_equal(values, flat)
    assert j["status"] == m.status.ravel().tolist()
    ks.io.write_map_vti(str(tmp_path / "map.vti"), m)
    ks.io.write_workspace_map_png(str(tmp_path / "map.png"), m, "k_t_min")
    assert b'Name="k_t_min"' in (tmp_path / "map.vti").read_bytes()
    assert (tmp_path / "map.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert ks.io.map_field_display("k_t_min") == ("N/mm", pytest.approx(1e-3))


def test_bad_grids_raise_input_error():
    with pytest.raises(ks.InputError, match="reversed"):
        mech.make_map_grid([(0.1, -0.1), (0, 0.1), 0.0], 0.01)
    with pytest.raises(ks.InputError, match="more than the limit"):
        mech.make_map_grid([(-1, 1), (-1, 1), 0.0], 1e-5)
    with pytest.raises(ks.InputError, match="y axis's dimension -1"):
        mech.MapGrid([0, 0, 0], [1, 1, 1], [10, -1, 1])
    with pytest.raises(ks.InputError, match="above the limit"):
        mech.MapGrid([0, 0, 0], [1, 1, 1], [100000, 100000, 1])
    with pytest.raises(ks.InputError, match="z axis's spacing"):
        mech.MapGrid([0, 0, 0], [1, 1, float("nan")], [10, 10, 1])


def small_sweep():
    # The C++ test's sweep (tests/mechanisms/five_bar_design_sweep_test.cpp): 3 x 3 designs about the paper's.
    o = mech.FiveBarDesignSweepOptions()
    o.r1, o.r2, o.steps = (0.07, 0.13), (0.08, 0.14), 3
    o.region = mech.make_map_grid([(-0.1, 0.1), (0.04, 0.2), 0.0], 0.01)
    o.min_stiffness = 3.0e4  # N/m
    return o


@pytest.fixture(scope="module")
def sweep():
    return mech.sweep_five_bar_designs(small_sweep())


def test_design_sweep_counts_equal_separate_maps(sweep):
    o = small_sweep()
    assert sweep.share.shape == (3, 3) and sweep.r1.shape == (3, 3)
    np.testing.assert_allclose(sweep.r1[0], [0.07, 0.10, 0.13])
    np.testing.assert_allclose(sweep.r2[:, 0], [0.08, 0.11, 0.14])
    n = o.region.num_points()
    for j in range(3):
        for i in range(3):
            design = mech.FiveBarKernelOptions()
            design.params.r1, design.params.r2 = sweep.r1[j, i], sweep.r2[j, i]
            m = mech.compute_workspace_map(mech.make_five_bar_kernel(design), o.region)  # the sweep's kernel
            ok = m.status == mech.PostureStatus.OK.value
            assert sweep.reachable_share[j, i] == np.count_nonzero(m.status != mech.PostureStatus.UNREACHABLE.value) / n
            assert sweep.singularity_free_share[j, i] == np.count_nonzero(ok) / n
            assert sweep.share[j, i] == np.count_nonzero(ok & (m.field("k_t_min") >= o.min_stiffness)) / n
            if ok.any():
                assert sweep.k_t_min_worst[j, i] == pytest.approx(m.field("k_t_min")[ok].min(), rel=1e-12)


def test_design_sweep_best_is_the_clis(sweep, tmp_path):
    # The largest share, then the stiffest weakest point.
    order = sorted(range(9), key=lambda k: (sweep.results[k].stiff, sweep.results[k].k_t_min_worst))
    assert sweep.best == order[-1] and sweep.best_design.stiff == sweep.results[order[-1]].stiff
    assert sweep.results[order[0]].stiff < sweep.best_design.stiff  # the choice means something
    j = ks.io.design_sweep_to_json(sweep)
    assert j["best"]["index"] == sweep.best and j["best"]["r1"] == sweep.best_design.r1
    ks.io.write_design_sweep_vti(str(tmp_path / "designs.vti"), sweep)
    ks.io.write_design_sweep_png(str(tmp_path / "designs.png"), sweep)
    assert (tmp_path / "designs.png").stat().st_size > 10000
    # The C++ program on the same sweep (mm and N/mm on its command line) picks the same design.
    cli = pathlib.Path(os.environ.get("KINESTAT_BINARY_DIR", "build")) / "src/cli/kinestat"
    if not cli.exists():
        pytest.skip(f"{cli} is not built")
    run = subprocess.run([str(cli), "design", "fivebar", "--r1", "70:130", "--r2", "80:140", "--steps", "3",
                          "--region", "-100:100,40:200", "--step", "10", "--min-stiffness", "30", "--json", "-"],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    best = json.loads(run.stdout)["best"]
    assert best["index"] == sweep.best
    assert best["share"] == sweep.share.ravel()[sweep.best]
    assert best["k_t_min_worst"] == pytest.approx(sweep.best_design.k_t_min_worst, rel=1e-12)


def test_bad_sweeps_raise_input_error():
    o = small_sweep()
    o.r1 = (0.13, 0.07)
    with pytest.raises(ks.InputError, match="r1"):
        mech.sweep_five_bar_designs(o)



def test_plot_curve_style_is_an_enum(tmp_path):
    # PlotCurve's style is io.CurveStyle (it was an int 0..2): a number is refused, a style is drawn.
    curve = ks.io.PlotCurve(np.array([[0.0, 0.0], [3.0, 2.0]]), "diagonal", ks.io.CurveStyle.DASHED_RED)
    assert curve.style == ks.io.CurveStyle.DASHED_RED and curve.label == "diagonal"
    assert ks.io.PlotCurve(np.zeros((2, 2))).style == ks.io.CurveStyle.SOLID_BLACK
    with pytest.raises(TypeError):
        ks.io.PlotCurve(np.zeros((2, 2)), "", 1)
    options = ks.io.PlotOptions()
    options.curves = [curve]
    ks.io.write_png_map(str(tmp_path / "curve.png"), ks.io.PlotField2D(np.arange(12.0).reshape(3, 4)), options)
    assert (tmp_path / "curve.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
