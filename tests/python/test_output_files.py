"""Output files of the kinestat program (docs/reliability.md, atomic outputs): a run killed at any
moment leaves a complete file or none, and a write that fails (a file size limit, as a full disk
fails it) is exit status 2 naming the file, leaving no file or the earlier one."""
import json
import resource
import signal
import subprocess
import time

import numpy as np


def test_a_killed_map_run_leaves_a_complete_json_or_none(kinestat_program, tmp_path):
    # SIGKILL at times spread over the computation and the writing of a ~7 MB JSON: the final path
    # holds no file, or the earlier complete one, or the new complete one; never a truncated file
    # (docs/reliability.md, atomic outputs). The tests of core/atomic_file.hpp kill a writer at a
    # known point; this one kills the real program wherever it is.
    cli = kinestat_program
    out = tmp_path / "map.json"
    command = [str(cli), "map", "fivebar", "--step", "1", "--json", str(out), "--quiet"]
    for earlier in (False, True):
        for delay in np.linspace(0.0, 0.5, 21):  # the write took from ~0.3 to ~0.4 s here
            if out.exists():
                out.unlink()
            if earlier:
                out.write_text('{"earlier": true}\n')
            run = subprocess.Popen(command)
            time.sleep(delay)
            run.kill()
            run.wait()
            if out.exists():
                j = json.loads(out.read_text())  # raises on a truncated file
                assert j == {"earlier": True} or j["schema"] == "kinestat-workspace-map"
            else:
                assert not earlier, "the earlier file was destroyed"


def run_with_file_size_limit(cli, args, limit_bytes):
    # RLIMIT_FSIZE makes writes past the limit fail (EFBIG) like a full disk does, without root or a
    # mount; SIGXFSZ, which would kill the process instead, is ignored.
    def limit():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit_bytes, limit_bytes))
    return subprocess.run([str(cli)] + args, capture_output=True, text=True, timeout=300,
                          preexec_fn=limit)


def test_a_write_past_the_file_size_limit_is_exit_2_and_leaves_no_file(kinestat_program, source_dir, tmp_path):
    # Each .vtu of the bar at 10 mm is ~120 KB: the first one fails. VTK 9.1 crashed writing it to a
    # full disk itself; its text now goes through kinestat's checked writer.
    run = run_with_file_size_limit(kinestat_program, [
        "link-stiffness", str(source_dir / "meshes/bar.off"), "--clamp", "x=0", "--reference", "x=200", "--size",
        "10", "--vtk", str(tmp_path / "vtk"), "--quiet"], 50_000)
    assert run.returncode == 2, run.stderr
    assert "bar_Fx.vtu" in run.stderr and "File too large" in run.stderr
    assert list((tmp_path / "vtk").iterdir()) == []  # neither a truncated file nor a temporary one
    # A map (~1.7 MB of JSON, its PNG, its VTI) over an earlier complete JSON: each fails, the JSON stays.
    earlier = tmp_path / "map.json"
    earlier.write_text('{"earlier": true}\n')
    for option, path in (("--json", earlier), ("--vti", tmp_path / "map.vti"), ("--png", tmp_path / "map.png")):
        run = run_with_file_size_limit(kinestat_program, ["map", "fivebar", "--step", "2", option, str(path), "--quiet"], 20_000)
        assert run.returncode == 2, (option, run.stderr)
        assert str(path) in run.stderr
    assert json.loads(earlier.read_text()) == {"earlier": True}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["map.json", "vtk"]
