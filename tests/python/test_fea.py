"""FEA link stiffness through Python: a box mesh against the beam formula, a mesh file through the
result cache, and the arrays of a mesh."""
import numpy as np
import pytest

import kinestat as ks

fea = ks.fea


def test_box_link_against_the_cantilever_formula():
    # A 200 x 20 x 20 mm steel bar clamped at x = 0, loaded through x = 0.2: C_zz ~ L^3 / 3EI.
    mesh = fea.to_quadratic(fea.make_box_mesh([0, 0, 0], [0.2, 0.02, 0.02], 10, 2, 2))
    assert mesh.nodes.shape == (mesh.num_nodes, 3) and mesh.connectivity.shape == (mesh.num_elements, 10)
    steel = ks.Material.from_E_nu("steel", 210e9, 0.3)
    options = fea.LinkStiffnessOptions()
    options.clamp = fea.Region.plane([0, 0, 0], [1, 0, 0])
    options.reference = fea.Region.plane([0.2, 0, 0], [1, 0, 0])
    options.keep_fields = True  # the six displacement fields (off by default)
    r = fea.link_stiffness(mesh, steel, options)
    assert r.compliance.shape == (6, 6) and len(r.displacement) == 6 and r.displacement[0].shape == (mesh.num_nodes, 3)
    I = 0.02**4 / 12
    beam = 0.2**3 / (3 * steel.E * I)
    # Coarse quadratic mesh plus the clamp's 3D effects and shear: within 10 % of Euler-Bernoulli.
    assert r.compliance[2, 2] == pytest.approx(beam, rel=0.1)
    assert r.compliance_symmetry_error < 1e-9


def test_mesh_file_through_the_cache(source_dir, tmp_path):
    # link_stiffness_from_file is fea.compute_link_stiffness on the request the CLI builds.
    args = dict(clamp="x=0", reference="x=200", size=20.0, cache=str(tmp_path / "cache"))
    first = fea.link_stiffness_from_file(str(source_dir / "meshes/bar.off"), **args)
    assert not first.from_cache and first.mesh is None and first.mesh_size == pytest.approx(0.02)
    assert "reference" in first.report and first.cache_file.startswith(str(tmp_path))
    second = fea.link_stiffness_from_file(str(source_dir / "meshes/bar.off"), **args)
    assert second.from_cache and second.cache_file == first.cache_file
    np.testing.assert_allclose(second.result.compliance, first.result.compliance, rtol=1e-12)
    # With the fields kept the link is solved again, and the mesh comes back for VTK.
    fields = fea.link_stiffness_from_file(str(source_dir / "meshes/bar.off"), keep_fields=True, **args)
    assert not fields.from_cache and fields.mesh is not None and len(fields.result.displacement) == 6
    # Equal to round-off of a parallel solve (the tiny off-diagonal terms carry it).
    tol = dict(rtol=1e-9, atol=1e-12 * np.abs(first.result.compliance).max())
    np.testing.assert_allclose(fields.result.compliance, first.result.compliance, **tol)
    j = ks.io.link_stiffness_to_json("bar.off", fields.mesh_size, fields.result)
    np.testing.assert_allclose(np.array(j["compliance"]), first.result.compliance, **tol)


def test_bad_mesh_inputs_raise_input_error(source_dir, tmp_path):
    with pytest.raises(ks.InputError, match="missing.off"):
        fea.link_stiffness_from_file(str(tmp_path / "missing.off"), clamp="x=0", reference="x=200")
    with pytest.raises(ks.InputError, match="clamp"):
        fea.link_stiffness_from_file(str(source_dir / "meshes/bar.off"), clamp="q=0", reference="x=200")


def test_damaged_cache_entry_is_refused_with_the_reason(tmp_path):
    steel = ks.Material.from_E_nu("steel", 210e9, 0.3)
    options = fea.LinkStiffnessOptions()
    key = fea.link_stiffness_cache_key("mesh bytes", steel, options)
    assert fea.is_link_stiffness_cache_key(key) and len(key) == 32
    mesh = fea.to_quadratic(fea.make_box_mesh([0, 0, 0], [0.2, 0.02, 0.02], 4, 1, 1))
    options.clamp = fea.Region.plane([0, 0, 0], [1, 0, 0])
    options.reference = fea.Region.plane([0.2, 0, 0], [1, 0, 0])
    r = fea.link_stiffness(mesh, steel, options)
    fea.store_cached_link_stiffness(str(tmp_path), key, r)
    np.testing.assert_array_equal(fea.load_cached_link_stiffness(str(tmp_path), key).compliance, r.compliance)
    entry = tmp_path / (key + ".txt")
    entry.write_bytes(entry.read_bytes()[:-10])  # cut 10 bytes short
    with pytest.warns(RuntimeWarning, match="cut short"):
        assert fea.load_cached_link_stiffness(str(tmp_path), key) is None
    assert fea.load_cached_link_stiffness(str(tmp_path / "absent"), key) is None  # absent: no warning


def test_cache_keys_cannot_leave_the_folder(tmp_path):
    mesh = fea.to_quadratic(fea.make_box_mesh([0, 0, 0], [0.2, 0.02, 0.02], 4, 1, 1))
    options = fea.LinkStiffnessOptions()
    options.clamp = fea.Region.plane([0, 0, 0], [1, 0, 0])
    options.reference = fea.Region.plane([0.2, 0, 0], [1, 0, 0])
    r = fea.link_stiffness(mesh, ks.Material.from_E_nu("steel", 210e9, 0.3), options)
    with pytest.raises(ks.InputError, match="hex digits"):
        fea.store_cached_link_stiffness(str(tmp_path / "a" / "cache"), "../../escaped", r)
    with pytest.raises(ks.InputError, match="hex digits"):
        fea.load_cached_link_stiffness(str(tmp_path), "../x")
    assert not (tmp_path / "escaped.txt").exists() and not (tmp_path / "a").exists()


def test_link_modes_of_a_box_bar(tmp_path):
    # The 200 x 20 x 30 mm steel bar of tests/fea/link_modes_test.cpp, coarse: its first mode bends
    # about the weak axis, Euler-Bernoulli 1.8751^2/(2 pi L^2) sqrt(E Iz/(rho A)) = 417.8 Hz; shear,
    # rotary inertia and the coarse mesh move it by a few % (measured in the C++ test).
    mesh = fea.to_quadratic(fea.make_box_mesh([0, -0.01, -0.015], [0.2, 0.01, 0.015], 10, 1, 2))
    steel = fea.parse_material("steel", "material")
    assert steel.density == 7850.0
    options = fea.LinkStiffnessOptions()
    options.clamp = fea.Region.plane([0, 0, 0], [1, 0, 0])
    options.reference = fea.Region.plane([0.2, 0, 0], [1, 0, 0])
    options.modes = 3
    options.keep_fields = True
    r = fea.link_stiffness(mesh, steel, options)
    assert len(r.modes) == 3 and r.mass == pytest.approx(7850 * 0.2 * 0.02 * 0.03, rel=1e-12)
    assert r.modes[0].frequency == pytest.approx(417.8, rel=0.05)
    assert r.modes[0].frequency < r.modes[1].frequency < r.modes[2].frequency
    assert r.modes[0].shape.shape == (mesh.num_nodes, 3) and r.modes[0].residual < 1e-6
    written = ks.io.write_link_mode_vtu_files(str(tmp_path), "bar", mesh, r)
    assert written[-1].endswith("bar_modes.pvd") and len(written) == 4
    # Element mass: a rigid translation carries rho V.
    x = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    M = fea.tet_mass(x, 1000.0)
    assert M[0::3, 0::3].sum() == pytest.approx(1000.0 / 6, rel=1e-14)
    # A link without density asking for modes is refused, naming the fix.
    with pytest.raises(ks.InputError, match="has no density"):
        fea.link_stiffness(mesh, ks.Material.from_E_nu("bare", 210e9, 0.3), options)
