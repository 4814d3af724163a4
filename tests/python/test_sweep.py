"""Posture sweeps: one msa.Workspace reused over the five-bar's postures (one symbolic analysis),
and the posture kernel's arrays equal to posture-by-posture solves."""
import math

import numpy as np
import pytest

import kinestat as ks

mech = ks.mechanisms


def test_sweep_reuses_the_workspace():
    params = mech.FiveBarParams()
    ws = ks.msa.Workspace()
    kxx = []
    for theta2 in np.radians(np.arange(70.0, 111.0, 5.0)):
        s = mech.make_five_bar_structure(params, math.radians(64.0), theta2)
        sol = ks.msa.solve(s, ws)
        kxx.append(sol.cartesian.stiffness[0, 0])
        assert sol.factorization.reused_symbolic == (len(kxx) > 1)
    # Nine postures, one symbolic analysis: the pattern depends on the topology only.
    assert ws.num_symbolic_analyses == 1
    assert len(set(kxx)) == len(kxx)  # each posture solved anew


def test_evaluate_postures_equals_single_solves():
    options = mech.FiveBarKernelOptions()
    kernel = mech.make_reference_five_bar_kernel(options)
    x, y = np.meshgrid(np.linspace(-0.03, 0.03, 3), np.linspace(0.05, 0.12, 4))
    points = np.stack([x, y, np.zeros_like(x)], axis=-1)  # (4, 3, 3): a grid of points (m)
    r = mech.evaluate_postures(kernel, points)
    assert r.status.shape == (4, 3) and r.stiffness.shape == (4, 3, 6, 6)
    assert r.translational_eigenvalues.shape == (4, 3, 3) and r.singularity_measure.shape == (4, 3)
    for j, i in [(0, 0), (2, 1), (3, 2)]:
        assert r.status[j, i] == mech.PostureStatus.OK.value
        s = mech.make_five_bar_structure(options.params, points[j, i, :2], options.mode)
        K = ks.msa.cartesian_stiffness(s, mech.FIVE_BAR_PLATFORM_NODE).stiffness
        np.testing.assert_allclose(r.stiffness[j, i], K, rtol=1e-9, atol=1e-9 * np.abs(K).max())
        # The translational eigenvalues are those of K[:3, :3] (N/m).
        np.testing.assert_allclose(r.translational_eigenvalues[j, i], np.linalg.eigvalsh(K[:3, :3]), rtol=1e-9)


def test_unreachable_points_are_nan():
    kernel = mech.make_reference_five_bar_kernel()
    r = mech.evaluate_postures(kernel, np.array([[1.0, 1.0, 0.0], [0.0, 0.12, 0.0]]))
    assert r.status[0] == mech.PostureStatus.UNREACHABLE.value
    assert np.isnan(r.stiffness[0]).all() and np.isnan(r.singularity_measure[0])
    assert r.status[1] == mech.PostureStatus.OK.value and np.isfinite(r.stiffness[1]).all()
    with pytest.raises(ks.InputError, match=r"\(\.\.\., 3\)"):
        mech.evaluate_postures(kernel, np.zeros((4, 2)))
