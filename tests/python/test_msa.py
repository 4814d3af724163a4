"""MSA through Python: the same oracles as the C++ tests (Table 1 row 14 of Goncalves et al. 2010,
the cantilever formula), the errors and the arrays' shapes and units."""
import math
import os
import pathlib
import subprocess

import numpy as np
import pytest

import kinestat as ks


def test_five_bar_table1_row14(source_dir):
    s = ks.io.read_structure_yaml(str(source_dir / "models/five_bar.yaml"))
    sol = ks.msa.solve(s)
    p = s.find_node("5")
    fx, fy = sol.case("Fx"), sol.case("Fy")
    # Table 1, row 14 (theta1 = 64, theta2 = 75 deg), node 5 under Fx = 1 N and Fy = 1 N (m).
    assert fx.displacement[p, 0] == pytest.approx(2.3946e-5, rel=1e-4)
    assert fx.displacement[p, 1] == pytest.approx(-2.5246e-5, rel=1e-4)
    assert fy.displacement[p, 1] == pytest.approx(1.0635e-4, rel=1e-4)
    # The report node's compliance holds the same numbers (C = K^-1, m/N).
    C = sol.cartesian.compliance
    assert C[0, 0] == pytest.approx(2.3946e-5, rel=1e-4)
    np.testing.assert_allclose(C @ sol.cartesian.stiffness, np.eye(6), atol=1e-6)


def cantilever(P=1000.0, L=1.0):
    s = ks.msa.Structure()
    a = s.add_node("A", [0, 0, 0])
    b = s.add_node("B", [L, 0, 0])
    steel = s.add_material(ks.Material.from_E_nu("steel", 210e9, 0.3))
    bar = ks.rectangle_section(0.02, 0.04)
    bar.id = "bar"
    sec = s.add_section(bar)
    s.add_beam(ks.msa.Beam("arm", a, b, material=steel, section=sec))
    s.add_support(ks.msa.Support(a))
    s.add_load_case(ks.msa.LoadCase("tip_down", [ks.msa.NodalLoad(b, [0, 0, -P, 0, 0, 0])]))
    s.set_report_node(b)
    return s, bar


def test_cantilever_tip_deflection_PL3_over_3EI():
    P, L, E = 1000.0, 1.0, 210e9
    s, bar = cantilever(P, L)
    sol = ks.msa.solve(s)
    uz = sol.cases[0].displacement[1, 2]
    assert uz == pytest.approx(-P * L**3 / (3 * E * bar.Iy), rel=1e-12)
    # The reaction balances the load; the rotation at the tip is P L^2 / 2EI about +y.
    assert sol.cases[0].reaction[0, 2] == pytest.approx(P, rel=1e-12)
    assert sol.cases[0].displacement[1, 4] == pytest.approx(P * L**2 / (2 * E * bar.Iy), rel=1e-12)
    assert sol.cases[0].equilibrium_error < 1e-12


def test_solve_tells_its_stages_in_order():
    # The stages kinestat solve prints for a large structure, told for any size to a callable.
    s, _ = cantilever()
    stages = []
    options = ks.msa.SolveOptions()
    options.progress = stages.append
    ks.msa.solve(s, options=options)
    assert [st.split(":")[0] for st in stages] == [
        "assembling the stiffness matrix", "factorizing", "searching for free motions (inverse iteration on the factor)",
        "solving 1 load case and checking equilibrium", "the report node's Cartesian stiffness"]
    assert "2 nodes, 1 beams, 0 joints (12 dofs)" in stages[0]


def test_arrays_shapes_and_units(source_dir):
    s = ks.io.read_structure_yaml(str(source_dir / "models/five_bar.yaml"))
    sol = ks.msa.solve(s)
    n, nb, nj = len(s.nodes), len(s.beams), len(s.joints)
    case = sol.cases[0]
    assert case.displacement.shape == (n, 6)
    assert case.reaction.shape == (n, 6)
    assert case.beam_end_forces.shape == (nb, 12)
    assert case.joint_forces.shape == (nj, 6)
    assert sol.cartesian.stiffness.shape == (6, 6) and sol.cartesian.compliance.shape == (6, 6)
    assert case.displacement.dtype == np.float64
    # Units: the beams' axial end forces balance (N), the supports carry the 1 N load.
    np.testing.assert_allclose(case.reaction[:, :3].sum(axis=0), [-1.0, 0.0, 0.0], atol=1e-9)
    assert sol.cartesian.stiffness[0, 0] > 1e3  # N/m: a 5 mm steel five-bar is ~1e5 N/m stiff along x
    ix = sol.cartesian.indices
    assert ix.eigenvalues.shape == (6,) and ix.eigenvectors.shape == (6, 6)
    # Symmetric matrices stay symmetric through the binding.
    K = sol.cartesian.stiffness
    assert np.abs(K - K.T).max() <= 1e-9 * np.abs(K).max()


# A steel beam A-B, 1 m along x, without supports or loads.
BEAM = """units: SI
nodes:
  - {id: A, xyz: [0, 0, 0]}
  - {id: B, xyz: [1, 0, 0]}
materials:
  - {id: steel, E: 210e9, nu: 0.3}
sections:
  - {id: bar, type: rectangle, b: 0.02, h: 0.04}
beams:
  - {id: arm, nodes: [A, B], material: steel, section: bar}
"""


def test_bad_structure_file_raises_input_error_with_line(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text(BEAM.replace("[A, B]", "[A, C]"))
    with pytest.raises(ks.InputError) as e:
        ks.io.read_structure_yaml(str(path))
    message = str(e.value)
    assert message.startswith(f"{path}:10: "), message
    assert "'C'" in message
    assert e.value.code == ks.StatusCode.INVALID_INPUT
    assert isinstance(e.value, ValueError) and isinstance(e.value, ks.KinestatError)


# Free to rotate about z at A (a missing support), with a tip load.
SINGULAR_CANTILEVER = BEAM + """supports:
  - {node: A, fixed: [ux, uy, uz, rx, ry]}
load_cases:
  - {LOAD_CASE: tip, loads: [{node: B, force: [0, 0, -1000]}]}
"""


def test_errors_carry_the_messages_the_cli_prints(tmp_path):
    cli = pathlib.Path(os.environ.get("KINESTAT_BINARY_DIR", "build")) / "src" / "cli" / "kinestat"
    if not cli.exists():
        pytest.skip(f"{cli} is not built")
    # Bad input: the CLI prints "kinestat solve: MESSAGE" and exits 2; Python raises InputError(MESSAGE).
    bad = tmp_path / "bad.yaml"
    bad.write_text(SINGULAR_CANTILEVER.replace("LOAD_CASE", "id"))
    with pytest.raises(ks.InputError) as e:
        ks.io.read_structure_yaml(str(bad))
    run = subprocess.run([str(cli), "solve", str(bad)], capture_output=True, text=True, timeout=60)
    assert run.returncode == 2 and run.stderr == f"kinestat solve: {e.value}\n"
    assert str(e.value).startswith(f"{bad}:14: load case #1: unknown key 'id'")
    # Singular (the rotation about z is free): exit 3 with the diagnosis; Python raises it as SingularError.
    singular = tmp_path / "singular.yaml"
    singular.write_text(SINGULAR_CANTILEVER.replace("LOAD_CASE", "name"))
    with pytest.raises(ks.SingularError) as e:
        ks.msa.solve(ks.io.read_structure_yaml(str(singular)))
    run = subprocess.run([str(cli), "solve", str(singular)], capture_output=True, text=True, timeout=60)
    assert run.returncode == 3 and str(e.value) in run.stdout
    assert "node 'B' translates along +y (1) and rotates about +z" in str(e.value)


def test_structure_in_code_is_validated_like_a_file():
    s, _ = cantilever()
    s.add_beam(ks.msa.Beam("dangling", 0, 7, material=0, section=0))
    with pytest.raises(ks.InputError, match="dangling"):
        s.validate()
    with pytest.raises(ks.InputError, match="dangling"):
        ks.msa.solve(s)


def test_coupled_joint_carries_its_matrix():
    # A node held to a fixed one by a coupled 6x6 (identity frame): u = K^-1 W, solved by NumPy;
    # a coupling that is not symmetric is refused naming the joint.
    K = np.diag([4e6, 5e6, 6e6, 3e3, 2e3, 1e3])
    K[0, 1] = K[1, 0] = 1e6
    K[2, 4] = K[4, 2] = 2e4
    coupling = K - np.diag(np.diag(K))
    W = np.array([100.0, -50.0, 80.0, 3.0, -2.0, 1.0])

    def held(coupling):
        s = ks.msa.Structure()
        g = s.add_node("g", [0.0, 0.0, 0.0])
        t = s.add_node("t", [0.0, 0.0, 0.0])
        s.add_support(ks.msa.Support(g))
        s.add_joint(ks.msa.Joint("link", g, t, stiffness=np.diag(K), coupling=coupling))
        s.add_load_case(ks.msa.LoadCase("W", [ks.msa.NodalLoad(t, W)]))
        return s

    u = ks.msa.solve(held(coupling)).cases[0].displacement[1]
    np.testing.assert_allclose(u, np.linalg.solve(K, W), rtol=1e-10)
    coupling[1, 0] = 0.0
    with pytest.raises(ks.InputError, match="joint 'link': its stiffness with its coupling is not symmetric"):
        held(coupling).validate()


def test_singular_posture_raises_singular_error_with_free_motion():
    # theta1 = theta2: B1, P, B2 aligned, a parallel singularity (README: node 5 translates along y).
    theta = math.radians(30)
    s = ks.mechanisms.make_five_bar_structure(ks.mechanisms.FiveBarParams(), theta, theta)
    with pytest.raises(ks.SingularError) as e:
        ks.msa.solve(s)
    d = e.value.diagnosis
    assert isinstance(d, ks.msa.SingularityDiagnosis) and d.singular
    assert "free motion" in str(e.value) and "node '5'" in str(e.value)
    mode = d.modes[0]
    assert mode.node_motion.shape == (len(s.nodes), 6)
    assert mode.rayleigh_ratio < 1e-13
    # B1, P and B2 lie on the line y = r1 sin 30 deg: P is free to move normal to it, along y
    # (the largest translation scaled to 1).
    p = ks.mechanisms.FIVE_BAR_PLATFORM_NODE
    np.testing.assert_allclose(np.abs(mode.node_motion[p, :3]), [0.0, 1.0, 0.0], atol=1e-6)
    # Without raising, the Solution carries the same diagnosis and no load case.
    sol = ks.msa.solve(s, raise_on_singular=False)
    assert sol.status.code == ks.StatusCode.SINGULAR and sol.cases == []
    assert sol.singularity.message == str(e.value)


def test_self_weight_and_member_load_on_a_cantilever():
    # Tip deflection of a cantilever under its weight rho A g L^4 / 8EI, plus a uniform member load
    # w L^4 / 8EI; the free end's true end forces are zero (k u + fixed-end forces).
    L, E, rho, g, w = 1.5, 210e9, 7850.0, 9.81, -300.0
    s = ks.msa.Structure()
    a = s.add_node("A", [0, 0, 0])
    b = s.add_node("B", [L, 0, 0])
    steel = s.add_material(ks.Material("steel", E, E / 2.6, density=rho))
    bar = ks.rectangle_section(0.02, 0.04)
    sec = s.add_section(bar)
    s.add_beam(ks.msa.Beam("arm", a, b, material=steel, section=sec))
    s.add_support(ks.msa.Support(a))
    s.add_load_case(ks.msa.LoadCase("weight", gravity=[0, 0, -g]))
    ml = ks.msa.MemberLoad(0, ks.msa.MemberLoadType.UNIFORM, global_axes=True, w1=[0, 0, w])
    s.add_load_case(ks.msa.LoadCase("udl", member_loads=[ml]))
    sol = ks.msa.solve(s)
    EI = E * bar.Iy
    q = rho * bar.A * g
    assert sol.cases[0].displacement[1, 2] == pytest.approx(-q * L**4 / (8 * EI), rel=1e-9)
    assert sol.cases[1].displacement[1, 2] == pytest.approx(w * L**4 / (8 * EI), rel=1e-9)
    assert sol.cases[1].reaction[0, 2] == pytest.approx(-w * L, rel=1e-9)
    assert np.abs(sol.cases[1].beam_end_forces[0, 6:]).max() < 1e-9 * abs(w) * L * L
