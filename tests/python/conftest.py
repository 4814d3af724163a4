"""Shared by the pytest suite of the Python module: where the bundled models and meshes are.

ctest runs each file with PYTHONPATH=build/python (the build tree's package), MPLBACKEND=Agg and
KINESTAT_SOURCE_DIR set (tests/CMakeLists.txt)."""
import os
import pathlib

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("KINESTAT_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture
def source_dir():
    return SOURCE_DIR


@pytest.fixture
def kinestat_program():
    """The build tree's kinestat program (KINESTAT_BINARY_DIR, default build/); the test is skipped
    when it is not built."""
    cli = pathlib.Path(os.environ.get("KINESTAT_BINARY_DIR", "build")) / "src/cli/kinestat"
    if not cli.exists():
        pytest.skip(f"{cli} is not built")
    return cli
