#!/usr/bin/env python3
"""The link's natural frequencies on petsc-mumps (SLEPc on its distributed factor) against CHOLMOD
(Spectra): runs `kinestat link-stiffness --modes COUNT` once with --solver cholmod, once under
`MPIEXEC -np RANKS` with --solver petsc-mumps, and checks that every frequency agrees to TOL
relative, that each mode's residual ||K q - omega^2 M q|| / ||K q|| is small on the ranks (their K
and M are summed over the ranks: the residual checks that the sums were formed), that only rank 0
wrote the JSON, and that the ranks shared the assembly (solver.elements_per_rank).

usage: compare_link_modes.py KINESTAT MPIEXEC RANKS COUNT TOL MESH [link-stiffness options...]
"""
import json
import sys

from mpi_runs import allow_mpi_runs, check_shared_assembly, run


def main():
    kinestat, mpiexec, ranks, count, tol, mesh, *options = sys.argv[1:]
    tol = float(tol)
    base = [kinestat, "link-stiffness", mesh, *options, "--modes", count, "--json", "-", "--quiet"]
    reference = json.loads(run([*base, "--solver", "cholmod"]))["vibration"]["modes"]
    allow_mpi_runs()
    result = json.loads(run([mpiexec, "-np", ranks, *base, "--solver", "petsc-mumps"]))  # one document: rank 0's
    modes = result["vibration"]["modes"]
    if len(modes) != len(reference) or len(modes) != int(count):
        sys.exit(f"{len(modes)} modes on petsc-mumps, {len(reference)} on cholmod; {count} asked for")
    worst = max(abs(m["frequency"] - r["frequency"]) / r["frequency"] for m, r in zip(modes, reference))
    residual = max(m["residual"] for m in modes)
    print(f"petsc-mumps on {ranks} rank(s): {result['solver']['backend']}; frequencies (Hz) "
          f"{[round(m['frequency'], 4) for m in modes]}; max |df| / f against cholmod = {worst:.3e} "
          f"(tolerance {tol:g}); max residual {residual:.2e}")
    if not worst <= tol:
        sys.exit(f"petsc-mumps's frequencies differ from cholmod's by {worst:.3e} > {tol:g}")
    if not residual <= 1e-8:
        sys.exit(f"a mode's residual is {residual:.2e} > 1e-8")
    check_shared_assembly(result, ranks)


if __name__ == "__main__":
    main()
