"""Buckling, vibration modes and the second-order solve through Python (kinestat.msa.buckling,
modal_analysis, solve_second_order): the oracles of the C++ tests (Euler's load, the simply
supported beam's first frequency, the beam-column closed form) and the errors they raise."""
import math

import numpy as np
import pytest

import kinestat as ks

E = 210e9


def test_buckling_euler_column(source_dir):
    # models/euler_column.yaml: pinned-pinned, L = 2 m, E Iz = 4200 N m^2, 1 kN: lambda_1 = pi^2 EI / L^2 / P
    # = 10.363; 8 cubic beams overestimate it by 3.28e-5 (tests/msa/buckling_test.cpp): asserted 2x that.
    s = ks.io.read_structure_yaml(str(source_dir / "models/euler_column.yaml"))
    opt = ks.msa.BucklingOptions()
    opt.count = 2
    r = ks.msa.buckling(s, opt)
    exact = math.pi**2 * E * 2e-8 / 4.0 / 1000.0
    assert r.modes[0].load_factor > exact
    assert r.modes[0].load_factor == pytest.approx(exact, rel=2 * 3.28e-5)
    assert r.modes[0].residual < 1e-8
    assert r.modes[0].shape.shape == (len(s.nodes), 6)
    assert r.modes[0].shape[4, 1] == pytest.approx(1.0, abs=1e-12)  # midspan, normalized translation
    np.testing.assert_allclose(r.axial_force, -1000.0, rtol=1e-9)
    assert r.load_case_name == "axial"


def test_modes_simply_supported_first_frequency(source_dir):
    # The same column: f_1 = pi^2 sqrt(E Iz / (rho A L^4)) / (2 pi) = 11.7266 Hz (Euler-Bernoulli).
    # 8 consistent beams are 1.6e-5 high, the rotary inertia lowers it by 4e-5
    # (docs/stability-and-modes.md): asserted within 1e-4 of the closed form.
    s = ks.io.read_structure_yaml(str(source_dir / "models/euler_column.yaml"))
    opt = ks.msa.ModalOptions()
    opt.count = 2
    r = ks.msa.modal_analysis(s, opt)
    A, I, rho, L = 0.02 * 0.03, 2e-8, 7850.0, 2.0
    f1 = math.pi**2 * math.sqrt(E * I / (rho * A * L**4)) / (2 * math.pi)
    assert r.modes[0].frequency == pytest.approx(f1, rel=1e-4)
    assert r.modes[0].omega == pytest.approx(2 * math.pi * r.modes[0].frequency, rel=1e-15)
    assert r.modes[0].shape.shape == (len(s.nodes), 6)
    assert r.modes[0].residual < 1e-8
    assert r.total_mass[0] == pytest.approx(rho * A * L, rel=1e-12)


def test_modes_prestressed_by_the_axial_load(source_dir):
    # The same column under its load case (1 kN compression = P_cr / 10.363): the sine mode vibrates at
    # omega_0 sqrt(1 + P / P_cr) (docs/stability-and-modes.md), f_1 = 11.146 Hz. 8 consistent beams
    # without rotary inertia: measured 1.82e-5 above it (tests/msa/modes_test.cpp gives the
    # convergence); asserted within twice that.
    s = ks.io.read_structure_yaml(str(source_dir / "models/euler_column.yaml"))
    opt = ks.msa.ModalOptions()
    opt.count = 1
    opt.rotary_inertia = False
    opt.prestress = ks.msa.ModalPrestress(load_case=0)
    r = ks.msa.modal_analysis(s, opt)
    A, I, rho, L = 0.02 * 0.03, 2e-8, 7850.0, 2.0
    f0 = math.pi**2 * math.sqrt(E * I / (rho * A * L**4)) / (2 * math.pi)
    pcr = math.pi**2 * E * I / L**2
    exact = f0 * math.sqrt(1.0 - 1000.0 / pcr)
    print(f"prestressed Euler column: f_1 = {r.modes[0].frequency:.6f} Hz, {r.modes[0].frequency / exact - 1:+.2e}")
    assert r.modes[0].frequency > exact
    assert r.modes[0].frequency == pytest.approx(exact, rel=2 * 1.82e-5)
    assert r.prestress.load_case_name == "axial"
    assert not r.prestress.second_order
    np.testing.assert_allclose(r.prestress.axial_force, -1000.0, rtol=1e-9)
    assert ks.msa.modal_analysis(s).prestress is None
    # Past the critical load (11 kN > 10.363 kN): no frequency, InputError naming the case.
    s.add_load_case(ks.msa.LoadCase("crushing", [ks.msa.NodalLoad(8, [-11000.0, 0, 0, 0, 0, 0])]))
    opt.prestress = ks.msa.ModalPrestress(load_case=1)
    with pytest.raises(ks.InputError) as e:
        ks.msa.modal_analysis(s, opt)
    assert "prestress of load case 'crushing'" in str(e.value)
    assert "past the critical (buckling) load" in str(e.value)


def cantilever(n, P, H=100.0, L=2.0):
    """A cantilever along x in n beams, clamped at x = 0, P along x (tension positive) and H along y at the tip."""
    s = ks.msa.Structure()
    nodes = [s.add_node(str(i), [L * i / n, 0, 0]) for i in range(n + 1)]
    steel = s.add_material(ks.Material.from_E_nu("steel", E, 0.3))
    bar = ks.rectangle_section(0.02, 0.03)
    bar.id = "bar"
    sec = s.add_section(bar)
    for i in range(n):
        s.add_beam(ks.msa.Beam(f"b{i}", nodes[i], nodes[i + 1], material=steel, section=sec))
    s.add_support(ks.msa.Support(nodes[0]))
    s.add_load_case(ks.msa.LoadCase("P and H", [ks.msa.NodalLoad(nodes[-1], [P, H, 0, 0, 0, 0])]))
    return s, bar


def test_second_order_cantilever_closed_form():
    n, L, H = 8, 2.0, 100.0
    _, bar = cantilever(n, 0.0)
    EI = E * bar.Iz
    P = -0.5 * math.pi**2 * EI / (4 * L * L)  # half Euler's load, compression
    s, _ = cantilever(n, P)
    sol = ks.msa.solve_second_order(s)
    k = math.sqrt(-P / EI)
    exact = H * (math.tan(k * L) - k * L) / (k**3 * EI)
    # 8 cubic elements: 1.03e-6 below the closed form (tests/msa/second_order_test.cpp): asserted 2e-6.
    assert sol.cases[0].displacement[n, 1] == pytest.approx(exact, rel=2e-6)
    assert sol.second_order.iterations[0] >= 1
    assert sol.second_order.relative_change[0] <= sol.second_order.tolerance
    assert sol.second_order.axial_force[0][0] == pytest.approx(P, rel=1e-9)
    assert ks.msa.solve(s).second_order is None
    # The first-mode estimate of the amplification, 1 / (1 - P/Pcr) = 2, is within 1 % (exact: 1.986).
    linear = H * L**3 / (3 * EI)
    assert sol.cases[0].displacement[n, 1] / linear == pytest.approx(2.0, rel=0.01)
    opt = ks.msa.SecondOrderOptions()
    opt.max_iterations = 1
    with pytest.raises(ks.NotConvergedError):
        ks.msa.solve_second_order(s, opt)


def test_errors_raise():
    n, L = 4, 2.0
    _, bar = cantilever(n, 0.0)
    pcr = math.pi**2 * E * bar.Iz / (4 * L * L)
    s, _ = cantilever(n, -1.2 * pcr)
    with pytest.raises(ks.NotConvergedError) as e:
        ks.msa.solve_second_order(s)
    assert "critical (buckling) load" in str(e.value)
    pulled, _ = cantilever(n, 1000.0, H=0.0)
    with pytest.raises(ks.InputError) as e:
        ks.msa.buckling(pulled)
    assert "compresses no beam" in str(e.value)
    with pytest.raises(ks.InputError) as e:
        ks.msa.modal_analysis(pulled)  # the material has no density and there are no nodal masses
    assert "density" in str(e.value)


def test_geometric_stiffness_convention(source_dir):
    # The structure's K_G convention (docs/stability-and-modes.md): KINESTAT by default, FRAME3DD as the
    # .3dd reader sets it. On the straight column (no load along the members) the first end's axial
    # force is the mean, and the axial term does not couple to the lateral buckling: the same lambda_1.
    s = ks.io.read_structure_yaml(str(source_dir / "models/euler_column.yaml"))
    assert s.geometric_stiffness_convention == ks.msa.GeometricStiffnessConvention.KINESTAT
    ours = ks.msa.buckling(s).modes[0].load_factor
    s.geometric_stiffness_convention = ks.msa.GeometricStiffnessConvention.FRAME3DD
    assert s.geometric_stiffness_convention == ks.msa.GeometricStiffnessConvention.FRAME3DD
    r = ks.msa.buckling(s)
    assert r.modes[0].load_factor == pytest.approx(ours, rel=1e-12)
    np.testing.assert_allclose(r.axial_force, -1000.0, rtol=1e-9)
