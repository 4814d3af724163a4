"""VJM through Python: VJM = MSA on a beam chain (the C++ cross-check), the five-bar by both
methods, loaded mode under a displacement and under a wrench, and model files."""
import numpy as np
import pytest

import kinestat as ks

vjm, msa, mech = ks.vjm, ks.msa, ks.mechanisms


def transform(R=np.eye(3), p=(0, 0, 0)):
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, p
    return T


def test_vjm_equals_msa_on_a_beam_chain():
    # Two beams and an elastic joint, clamped at the base: as an MSA frame and as a VJM chain of
    # cantilever springs and rigid links. Both models are exact for beams: the 6x6 agree to round-off.
    steel = ks.Material.from_E_nu("steel", 2.1e11, 0.3)
    p0, p1, p2 = np.array([0, 0, 0.0]), np.array([0.4, 0.05, -0.1]), np.array([0.45, 0.35, 0.2])
    joint_frame = ks.axis_angle(np.array([1, -2, 0.5]) / np.linalg.norm([1, -2, 0.5]), 0.7)
    joint_k = np.array([2e7, 5e7, 8e7, 3e4, 6e4, 9e4])  # N/m, N m/rad in the joint frame
    round_, flat = ks.circle_section(0.02), ks.rectangle_section(0.02, 0.03)
    round_.id, flat.id = "round", "flat"

    s = msa.Structure()
    n0, n1, n1b, n2 = (s.add_node(i, p) for i, p in [("base", p0), ("elbow", p1), ("elbow'", p1), ("tip", p2)])
    mat, s1, s2 = s.add_material(steel), s.add_section(round_), s.add_section(flat)
    s.add_beam(msa.Beam("upper", n0, n1, material=mat, section=s1))
    s.add_beam(msa.Beam("lower", n1b, n2, material=mat, section=s2, orientation=[0.3, 0.2, 1.0]))
    s.add_joint(msa.Joint("elbow joint", n1, n1b, frame=joint_frame, stiffness=joint_k))
    s.add_support(msa.Support(n0))
    K_msa = msa.cartesian_stiffness(s, n2)
    assert K_msa.stiffness_defined

    a1, a2 = s.beam_axes(s.beams[0]), s.beam_axes(s.beams[1])
    L1, L2 = np.linalg.norm(p1 - p0), np.linalg.norm(p2 - p1)
    c = vjm.Chain("frame")
    c.add_transform(transform(a1, p0), "base, upper beam axes")
    c.add_translation([L1, 0, 0], "upper beam")
    c.add_spring(vjm.cantilever_spring(steel, round_, L1), "upper beam")
    c.add_transform(transform(a1.T @ joint_frame), "joint frame")
    c.add_spring(np.diag(joint_k), "elbow joint")
    c.add_transform(transform(joint_frame.T @ a2), "lower beam axes")
    c.add_translation([L2, 0, 0], "lower beam")
    c.add_spring(vjm.cantilever_spring(steel, flat, L2), "lower beam")
    K_vjm = vjm.unloaded_stiffness(c)
    np.testing.assert_allclose(c.nominal_pose()[:3, 3], p2, atol=1e-15)

    Km = K_msa.stiffness
    assert np.abs(K_vjm.stiffness - Km).max() < 1e-9 * np.abs(Km).max()
    Cm = K_msa.compliance
    scale = np.sqrt(np.outer(np.diag(Cm), np.diag(Cm)))
    assert (np.abs(K_vjm.compliance - Cm) <= 1e-9 * scale).all()


def test_five_bar_by_vjm_and_msa():
    p = mech.FiveBarParams()
    q = mech.direct_kinematics(p, np.radians(64), np.radians(75), mech.Assembly.UP)
    kv = vjm.platform_unloaded_stiffness(mech.five_bar_vjm_chains(p, q))
    km = msa.cartesian_stiffness(mech.make_five_bar_structure(p, q), mech.FIVE_BAR_PLATFORM_NODE)
    assert np.abs(kv.stiffness - km.stiffness).max() < 1e-6 * np.abs(km.stiffness).max()


def test_singular_platform_raises_with_the_free_direction():
    p = mech.FiveBarParams()
    q = mech.direct_kinematics(p, np.radians(30), np.radians(30), mech.Assembly.UP)
    with pytest.raises(ks.SingularError) as e:
        vjm.platform_unloaded_stiffness(mech.five_bar_vjm_chains(p, q))
    free = e.value.diagnosis.free_directions
    assert free.shape == (1, 6)
    assert abs(free[0, 1]) == pytest.approx(np.linalg.norm(free[0, :3]), abs=1e-6)  # P along y
    assert "translation" in str(e.value)


def test_loaded_mode_displacement_and_wrench_agree():
    model = mech.OrthoglideStiffnessModel()
    chains = mech.orthoglide_chains(model, mech.OrthoglideArchitecture.PUU, [0.0, 0.0, 0.0])
    d = np.array([-5e-4, -5e-4, -5e-4, 0, 0, 0])  # m, rad
    state = vjm.platform_equilibrium(chains, d)
    assert state.report.converged and len(state.chains) == 3
    back = vjm.platform_equilibrium_under_wrench(chains, state.wrench)
    np.testing.assert_allclose(back.displacement, d, atol=1e-9 * np.linalg.norm(d))
    KF = vjm.platform_loaded_stiffness(chains, state)
    K0 = vjm.platform_unloaded_stiffness(chains)
    assert KF.stiffness.shape == (6, 6)
    # The wrench is about the loaded stiffness times the displacement for a small load (N, N m).
    np.testing.assert_allclose(K0.stiffness @ d, state.wrench, rtol=0.05, atol=1e-6 * np.abs(state.wrench).max())


def test_load_share_reached_brackets_the_last_solvable_load():
    # 200 kN down on the 3-PUU at Q0 has no equilibrium that the solve finds (kinestat vjm: exit 2).
    chains = mech.orthoglide_chains(mech.OrthoglideStiffnessModel(), mech.OrthoglideArchitecture.PUU, [0.0, 0.0, 0.0])
    w = np.array([0, 0, -2e5, 0, 0, 0])
    found, failed = vjm.load_share_reached(chains, wrench=w)
    assert 0 < found < failed < 1 and failed - found <= 1 / 128
    assert vjm.platform_equilibrium_under_wrench(chains, found * w).report.converged
    with pytest.raises(ks.NotConvergedError):
        vjm.platform_equilibrium_under_wrench(chains, failed * w)
    with pytest.raises(ks.InputError):
        vjm.load_share_reached(chains)


def test_model_file_matches_the_model_in_code(source_dir):
    model = ks.io.read_vjm_model_yaml(str(source_dir / "models/orthoglide_puu.yaml"))
    assert model.orthoglide is not None
    point = [0.01, -0.02, 0.03]
    from_file = vjm.platform_unloaded_stiffness(ks.io.vjm_model_chains(model, point))
    in_code = mech.orthoglide_stiffness(model.orthoglide, model.architecture, point).unloaded
    np.testing.assert_array_equal(from_file.stiffness, in_code.stiffness)
    with pytest.raises(ks.InputError, match="orthoglide_bad.yaml:"):
        ks.io.read_vjm_model_yaml_string("mechanism: orthoglide\northoglide: {link_length: -1}\n",
                                         "orthoglide_bad.yaml")


def test_bad_transforms_and_sizes_raise_instead_of_crashing():
    c = vjm.Chain("leg")
    with pytest.raises(ks.InputError, match="rigid transform"):
        c.add_transform(np.diag([2.0, 1, 1, 1]), "not a rotation")
    c.add_passive(vjm.JointType.REVOLUTE, [0, 0, 1], 0.0, "hinge")
    c.add_translation([0.5, 0, 0], "link")
    with pytest.raises(ks.InputError, match="q needs 1 and theta 0"):
        c.forward([0.1, 0.2], [])
    np.testing.assert_allclose(c.forward([np.pi / 2], [])[:3, 3], [0, 0.5, 0], atol=1e-15)
    with pytest.raises(ks.InputError, match="0..5"):
        ks.io.link_load_case_name(6)
