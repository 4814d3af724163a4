"""The Python examples (examples/python) run as a user runs them, with the non-interactive Agg
backend, and each writes its PNG."""
import os
import pathlib
import subprocess
import sys

import pytest

import kinestat
from conftest import SOURCE_DIR

EXAMPLES = sorted((SOURCE_DIR / "examples" / "python").glob("*.py"))


@pytest.mark.parametrize("script", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_example_writes_its_png(script, tmp_path):
    # The package this test imported, by an absolute path (the script runs in another folder).
    env = dict(os.environ, MPLBACKEND="Agg", KINESTAT_SOURCE_DIR=str(SOURCE_DIR),
               PYTHONPATH=str(pathlib.Path(kinestat.__file__).resolve().parents[1]))
    run = subprocess.run([sys.executable, str(script)], cwd=tmp_path, env=env, capture_output=True, text=True,
                         timeout=300)
    print(run.stdout)
    assert run.returncode == 0, run.stderr
    pngs = list(pathlib.Path(tmp_path).glob("*.png"))
    assert pngs, "no PNG written"
    assert all(p.stat().st_size > 10000 for p in pngs)
