#!/usr/bin/env python3
"""The PETSc backends against CHOLMOD on a bundled link: runs `kinestat link-stiffness` once with
--solver cholmod, once under `MPIEXEC -np RANKS` with --solver SOLVER, and checks that every entry
of the two 6x6 compliances agrees to TOL relative to the diagonal, |C1_ij - C2_ij| / sqrt(C_ii C_jj)
(unit-free: the SI entries differ by orders of magnitude), that only rank 0 wrote the JSON, and that
the ranks shared the assembly (solver.elements_per_rank: one entry per rank adding up to the mesh's
elements; on two ranks rank 0 assembled 30-70 % of them).

usage: compare_link_stiffness.py KINESTAT MPIEXEC RANKS SOLVER TOL MESH [link-stiffness options...]
"""
import json
import math
import sys

from mpi_runs import allow_mpi_runs, check_shared_assembly, run


def main():
    kinestat, mpiexec, ranks, solver, tol, mesh, *options = sys.argv[1:]
    tol = float(tol)
    base = [kinestat, "link-stiffness", mesh, *options, "--json", "-", "--quiet"]
    reference = json.loads(run(base))["compliance"]
    allow_mpi_runs()
    out = run([mpiexec, "-np", ranks, *base, "--solver", solver])
    # One JSON document on stdout: rank 0's (json.loads fails on two).
    result = json.loads(out)
    worst = 0.0
    for i in range(6):
        for j in range(6):
            scale = math.sqrt(reference[i][i] * reference[j][j])
            worst = max(worst, abs(result["compliance"][i][j] - reference[i][j]) / scale)
    s = result["solver"]
    print(f"{solver} on {ranks} rank(s): {s['backend']}; iterations {s['iterations']}, "
          f"residuals {s['relative_residuals']}; max |dC_ij| / sqrt(C_ii C_jj) = {worst:.3e} (tolerance {tol:g})")
    if not worst <= tol:
        sys.exit(f"{solver} differs from cholmod by {worst:.3e} > {tol:g}")
    per_rank, elements = check_shared_assembly(result, ranks)
    if int(ranks) == 2 and not 0.3 <= per_rank[0] / elements <= 0.7:
        sys.exit(f"rank 0 assembled {per_rank[0]} of {elements} elements: the assembly was not shared")


if __name__ == "__main__":
    main()
