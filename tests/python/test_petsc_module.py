"""PETSc, SLEPc and MPI as a module loaded on first use (docs/architecture.md, src/solver/petsc_module.hpp):
a run that uses no PETSc backend never maps their libraries, and one that asks for them finds the module."""
import os
import pathlib
import subprocess

import kinestat
import pytest


def loaded_libraries(command):
    # glibc's loader names every shared object it maps (LD_DEBUG=files) on stderr.
    env = dict(os.environ, LD_DEBUG="files")
    run = subprocess.run(command, capture_output=True, text=True, env=env, check=True)
    return run.stderr


def test_a_map_maps_no_petsc_library(kinestat_program, source_dir):
    log = loaded_libraries([str(kinestat_program), "map", str(source_dir / "models/orthoglide_puu.yaml"),
                            "--box", "-100:100,-100:100,-100:100", "--step", "50", "--quiet"])
    assert "libc.so" in log  # the log is the loader's
    for library in ("libpetsc", "libslepc", "libmpi", "libkinestat_petsc"):
        assert library not in log


def test_the_version_names_the_module_it_loaded(kinestat_program):
    versions = kinestat.solver.petsc_versions()
    if versions == "not built in":
        pytest.skip("PETSc not built in")
    assert versions.startswith("PETSc 3.") and ", SLEPc 3." in versions
    module = versions[versions.index("(module ") + len("(module "):-1]
    assert pathlib.Path(module).is_file()
    log = loaded_libraries([str(kinestat_program), "--version"])
    assert "libpetsc" in log and module in log
