"""Mechanisms through Python: five-bar and Orthoglide kinematics round trips, the design strategies,
and the identification on the paper's declared calibration."""
import math

import numpy as np
import pytest

import kinestat as ks

mech = ks.mechanisms


def test_five_bar_kinematics_round_trip():
    p = mech.FiveBarParams()
    up, down = mech.direct_kinematics(p, math.radians(64), math.radians(75))
    assert up.assembly == mech.Assembly.UP and up.P[1] > down.P[1]
    postures = mech.inverse_kinematics(p, up.P)
    assert len(postures) == 4
    back = mech.inverse_kinematics(p, up.P, up.working_mode)
    assert back.theta1 == pytest.approx(math.radians(64), abs=1e-12)
    assert back.theta2 == pytest.approx(math.radians(75), abs=1e-12)
    with pytest.raises(ks.InputError):
        mech.inverse_kinematics(p, [1.0, 1.0])  # out of reach
    jac = mech.five_bar_jacobians(up)
    assert jac.A.shape == (2, 2) and 0 < jac.parallel_measure <= 1


def test_orthoglide_kinematics_round_trip():
    g = mech.OrthoglideGeometry(0.3106)
    p = np.array([0.02, -0.03, 0.05])
    rho = mech.inverse_kinematics(g, p)
    np.testing.assert_allclose(mech.direct_kinematics(g, rho, mech.ORTHOGLIDE_WORKING_BRANCH), p, atol=1e-12)
    # The isotropic posture: J = I, all transmission factors 1.
    v = mech.velocity_transmission_at(g, [0, 0, 0])
    np.testing.assert_allclose(v.singular_values, [1, 1, 1], atol=1e-12)


def test_design_strategies_table3():
    designs = [mech.design_orthoglide(s, 0.5, 0.2) for s in (1, 2, 3)]
    for d in designs:
        assert d.p_max - d.p_min == pytest.approx(0.2, rel=1e-12)  # the cube edge (m)
    # Strategy 1's prototype link length 310.6 mm (design paper, Table 3; the stiffness model's default).
    assert designs[0].link_length == pytest.approx(mech.OrthoglideStiffnessModel().link_length, rel=1e-3)
    with pytest.raises(ks.InputError):
        mech.design_orthoglide(4, 0.5, 0.2)


def test_identification_recovers_a_known_input():
    # Targets computed from a model with a known actuator stiffness; the identification from another
    # start must find it back.
    truth = mech.OrthoglideStiffnessModel()
    truth.actuator_stiffness = 3.0e7
    arch = mech.OrthoglideArchitecture.PUU
    C = mech.orthoglide_stiffness(truth, arch, [0, 0, 0]).unloaded.compliance
    target = mech.ComplianceTarget("Q0 C_xx", arch, [0, 0, 0], 0, 0, C[0, 0])
    start = mech.OrthoglideStiffnessModel()
    result = mech.identify_orthoglide_inputs(start, [mech.OrthoglideInput.ACTUATOR_STIFFNESS], [target])
    assert result.model.actuator_stiffness == pytest.approx(3.0e7, rel=1e-6)
    assert "actuator" in result.report


def test_orthoglide_frame_equals_vjm():
    model = mech.OrthoglideStiffnessModel()
    arch = mech.OrthoglideArchitecture.PRPAR
    point = [0.01, 0.02, -0.01]
    frame = mech.orthoglide_frame(model, arch, point)
    K_msa = ks.msa.cartesian_stiffness(frame, frame.report_node).stiffness
    K_vjm = mech.orthoglide_stiffness(model, arch, point).unloaded.stiffness
    assert np.abs(K_msa - K_vjm).max() < 1e-8 * np.abs(K_vjm).max()
