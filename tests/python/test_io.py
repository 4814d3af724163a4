"""Writing what the CLI writes: the JSON results document and the ParaView files, from Python."""
import json
import os
import pathlib
import subprocess

import pytest

import kinestat as ks


def test_json_and_vtk_as_the_cli(source_dir, tmp_path):
    model = str(source_dir / "models/cantilever.yaml")
    s = ks.io.read_structure_yaml(model)
    sol = ks.msa.solve(s)
    doc = ks.io.solution_to_json(s, sol)
    assert doc["schema"] == "kinestat-msa-results" and doc["schema_version"] == ks.io.RESULTS_SCHEMA_VERSION
    out = tmp_path / "cantilever.json"
    ks.io.write_json(str(out), doc)
    assert json.loads(out.read_text()) == doc
    written = ks.io.write_vtk(s, sol, str(tmp_path / "vtk"), "cantilever")
    assert [p.rsplit("/", 1)[-1] for p in written][-1] == "cantilever.pvd"
    assert all((tmp_path / "vtk" / p.rsplit("/", 1)[-1]).is_file() for p in written)

    # The CLI, when it is built beside the module, writes the same document.
    cli = pathlib.Path(os.environ.get("KINESTAT_BINARY_DIR", source_dir / "build")) / "src" / "cli" / "kinestat"
    if cli.is_file():
        cli_json = tmp_path / "cli.json"
        subprocess.run([str(cli), "solve", model, "--quiet", "--json", str(cli_json)], check=True)
        from_cli = json.loads(cli_json.read_text())
        for key in ("schema_version", "units", "model", "status", "load_cases", "cartesian_stiffness"):
            assert from_cli[key] == doc[key]


def test_singular_structure_writes_free_motions(source_dir, tmp_path):
    s = ks.io.read_structure_yaml(str(source_dir / "models/released_chain.yaml"))
    sol = ks.msa.solve(s, raise_on_singular=False)
    written = ks.io.write_vtk(s, sol, str(tmp_path), "chain")
    assert any(p.endswith("chain_undeformed.vtu") for p in written)
    assert ks.io.solution_to_json(s, sol)["status"]["code"] == "singular"


def test_unwritable_path_raises_input_error(tmp_path):
    (tmp_path / "file").write_text("")
    with pytest.raises(ks.InputError):
        ks.io.write_json(str(tmp_path / "file" / "x.json"), {"a": 1})
