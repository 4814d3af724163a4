"""The Python API is as strict as the CLI (issue 21, item 5): each input the CLI refuses raises
kinestat.InputError naming the argument, instead of NaN arrays, zeros or a result. The checks are the
library's (core/input_checks and the option structs' validate functions), so each case here is also
one the CLI and C++ callers meet. The size checks must answer before any work: a time bound says so."""
import math
import time

import numpy as np
import pytest

import kinestat as ks

mech = ks.mechanisms
nan = float("nan")


def refused_quickly(match, f, *args, **kwargs):
    # Refused from the size estimate: well under a second (the runs they stand for take minutes).
    start = time.perf_counter()
    with pytest.raises(ks.InputError, match=match):
        f(*args, **kwargs)
    assert time.perf_counter() - start < 2.0


def five_bar_grid():
    return mech.make_map_grid([(-0.05, 0.05), (0.1, 0.15), 0.0], 0.01)


def test_map_options_negative_threads():
    o = mech.MapOptions()
    o.threads = -5
    with pytest.raises(ks.InputError, match=r"threads = -5: give 0 \(all cores\)"):
        mech.compute_workspace_map(mech.make_five_bar_kernel(), five_bar_grid(), o)
    with pytest.raises(ks.InputError, match="threads = -5"):
        mech.evaluate_postures(mech.make_five_bar_kernel(), np.zeros((2, 3)), threads=-5)


def test_five_bar_params_nan_length():
    o = mech.FiveBarKernelOptions()
    p = o.params
    p.r1 = nan
    o.params = p
    for make in (mech.make_five_bar_kernel, mech.make_reference_five_bar_kernel):
        with pytest.raises(ks.InputError, match="parameter r1 = nan m"):
            make(o)
    with pytest.raises(ks.InputError, match="parameter r1 = nan m"):
        mech.five_bar_singular_loci(p, mech.WorkingMode(), mech.Assembly.UP)


def test_orthoglide_kernel_negative_link_length():
    o = mech.OrthoglideKernelOptions()
    model = o.model
    model.link_length = -1.0
    o.model = model
    for make in (mech.make_orthoglide_kernel, mech.make_reference_orthoglide_kernel):
        with pytest.raises(ks.InputError, match="link_length = -1 m must be positive"):
            make(o)


def test_orthoglide_kernel_wrench_and_displacement_together():
    o = mech.OrthoglideKernelOptions()
    o.wrench = [0, 0, -10, 0, 0, 0]
    o.displacement = [0, 0, 1e-4, 0, 0, 0]
    with pytest.raises(ks.InputError, match="wrench and displacement: the loaded mode takes one"):
        mech.make_orthoglide_kernel(o)
    o.displacement = None
    o.wrench = [0, 0, nan, 0, 0, 0]
    with pytest.raises(ks.InputError, match=r"wrench \(force, N\)\[2\] = nan"):
        mech.make_orthoglide_kernel(o)


def test_link_stiffness_nan_size(source_dir):
    # NaN is not "no size": it used to fall through to the default size silently.
    with pytest.raises(ks.InputError, match="mesh_size = nan m is not a finite number"):
        ks.fea.link_stiffness_from_file(str(source_dir / "meshes/bar.off"), clamp="x=0", reference="x=200",
                                        size=nan)


def test_set_compliance_nan():
    r = ks.fea.LinkStiffness()
    C = np.eye(6) * 1e-6
    C[1, 2] = nan
    with pytest.raises(ks.InputError, match=r"compliance\[1, 2\] = nan"):
        ks.fea.set_compliance(r, C, [0, 0, 0])
    with pytest.raises(ks.InputError, match=r"point\[0\] = inf m"):
        ks.fea.set_compliance(r, np.eye(6) * 1e-6, [math.inf, 0, 0])


def test_box_mesh_without_cells():
    with pytest.raises(ks.InputError, match="nx = 0: give at least 1 cell"):
        ks.fea.make_box_mesh([0, 0, 0], [1, 1, 1], 0, 2, 2)
    with pytest.raises(ks.InputError, match=r"lo\[1\] = 1 m, hi\[1\] = 0 m"):
        ks.fea.make_box_mesh([0, 1, 0], [1, 0, 1], 2, 2, 2)
    # Counted before allocating: 6e9 tetrahedra, with the keyword that raises the limit named.
    refused_quickly("raise max_elements", ks.fea.make_box_mesh, [0, 0, 0], [1, 1, 1], 1000, 1000, 1000)
    assert ks.fea.make_box_mesh([0, 0, 0], [1, 1, 1], 20, 20, 20, max_elements=6e4).num_elements == 48000


def test_tet_stiffness_of_coplanar_points():
    D = ks.fea.elasticity_matrix(ks.Material.from_E_nu("steel", 210e9, 0.3))
    flat = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], dtype=float)
    with pytest.raises(ks.InputError, match="x: the tetrahedron's Jacobian is not positive"):
        ks.fea.tet_stiffness(flat, D)
    good = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    assert ks.fea.tet_stiffness(good, D).shape == (12, 12)


def test_design_sweep_without_region():
    o = mech.FiveBarDesignSweepOptions()
    o.r1, o.r2, o.steps = (0.07, 0.13), (0.08, 0.14), 3
    with pytest.raises(ks.InputError, match=r"region: 1 point\(s\), not a plane of P"):
        mech.sweep_five_bar_designs(o)


def test_convergence_sizes_in_the_wrong_order(source_dir):
    request = ks.fea.link_stiffness_request(str(source_dir / "meshes/bar.off"), clamp="x=0", reference="x=200")
    with pytest.raises(ks.InputError, match=r"sizes\[1\] = 0.004 m after 0.002 m: give the mesh sizes in strictly "
                                            "decreasing order"):
        ks.fea.link_stiffness_convergence(request, [0.002, 0.004, 0.001])
    with pytest.raises(ks.InputError, match=r"sizes\[2\] = nan m"):
        ks.fea.link_stiffness_convergence(request, [0.004, 0.002, nan])


def test_evaluate_at_a_nan_point():
    kernel = mech.make_five_bar_kernel()
    with pytest.raises(ks.InputError, match=r"point\[1\] = nan m is not a finite number"):
        kernel.evaluate([0.0, nan, 0.0])
    with pytest.raises(ks.InputError, match=r"points \(row 1\)\[0\] = nan m"):
        mech.evaluate_postures(kernel, np.array([[0.0, 0.12, 0.0], [nan, 0.12, 0.0]]))
    with pytest.raises(ks.InputError, match=r"points \(row 0\)\[2\] = nan m"):
        mech.evaluate_postures(kernel, np.array([[0.0, 0.12, nan]]))
    with pytest.raises(ks.InputError, match=r"points \(row 0\)\[1\] = 1e\+07 m is too large"):
        mech.evaluate_postures(kernel, np.array([[0.0, 1e7, 0.0]]))
    assert kernel.evaluate([0.0, 0.12, 0.0]).status == mech.PostureStatus.OK


def test_stiffness_indices_of_a_nan_matrix():
    K = np.eye(6)
    K[3, 4] = nan
    with pytest.raises(ks.InputError, match=r"K\[3, 4\] = nan is not a finite number"):
        ks.stiffness_indices(K)
    with pytest.raises(ks.InputError, match=r"K\[3, 4\] = nan"):
        ks.cartesian_indices(K)


def test_check_design_size_is_estimated_first():
    design = mech.design_orthoglide(1, 0.5, 0.2)
    refused_quickly(r"n 1000000: about .* points searched .* raise the limit with max_points", mech.check_design,
                    design, n=10**6)
    refused_quickly("n 1", mech.check_design, design, n=1)
    # The keyword raises the limit as `--max-points` does: the same n is then searched.
    with pytest.raises(ks.InputError, match="n 5: about 177 points"):
        mech.check_design(design, n=5, max_points=100)
    assert mech.check_design(design, n=5, max_points=200).cube.evaluations > 0


def test_search_cube_size_is_estimated_first():
    g = mech.OrthoglideGeometry(1.0)
    refused_quickly(r"n 100000: about .* raise the limit with max_points", mech.search_cube, g, -0.2, 0.2, n=10**5)
    with pytest.raises(ks.InputError, match=r"n 41: about 1.28e\+04 points"):
        mech.search_cube(g, -0.2, 0.2, n=41, max_points=1e4)
    mech.search_cube(g, -0.2, 0.2, n=41, max_points=2e4)


def test_singular_loci_samples_are_bounded():
    p = mech.FiveBarParams()
    refused_quickly(r"samples = 1000000000: the loci take 8 to 1000000", mech.five_bar_singular_loci, p,
                    mech.WorkingMode(), mech.Assembly.UP, samples=10**9)
    with pytest.raises(TypeError):  # a float count is a type error, as for every int argument
        mech.five_bar_singular_loci(p, mech.WorkingMode(), mech.Assembly.UP, samples=1e9)


def solved(n_beams):
    # A cantilever of n_beams along x, loaded at its tip (the report node).
    s = ks.msa.Structure()
    s.add_node("n0", [0, 0, 0])
    mat = s.add_material(ks.Material.from_E_nu("steel", 210e9, 0.3))
    sec = s.add_section(ks.circle_section(0.02))
    for i in range(1, n_beams + 1):
        s.add_node(f"n{i}", [0.5 * i, 0, 0])
        s.add_beam(ks.msa.Beam(f"b{i}", i - 1, i, mat, sec))
    s.add_support(ks.msa.Support(0))
    s.add_load_case(ks.msa.LoadCase("tip", [ks.msa.NodalLoad(n_beams, [0, 0, -1000, 0, 0, 0])]))
    s.set_report_node(n_beams)
    return s, ks.msa.solve(s)


def test_solution_of_another_structure(tmp_path):
    # The memory-safety bug: full_report read past the end of the smaller solution's arrays.
    small, small_solution = solved(2)
    large, _ = solved(3)
    assert small_solution.structure == {"nodes": 3, "beams": 2, "joints": 0, "load_cases": 1}
    match = r"solution: the counts it was solved for \(3 nodes, 2 beams, 0 joints, 1 load cases\) do not match " \
            r"the structure's 4 nodes, 3 beams"
    with pytest.raises(ks.InputError, match=match):
        ks.msa.full_report(large, small_solution)
    with pytest.raises(ks.InputError, match=match):
        ks.io.solution_to_json(large, small_solution)
    with pytest.raises(ks.InputError, match=match):
        ks.io.write_vtk(large, small_solution, str(tmp_path), "x")
    assert not list(tmp_path.iterdir())
    assert "node 'n2'" in ks.msa.full_report(small, small_solution)
