"""What the MPI test scripts share: Open MPI's settings for CI, a checked run, and the check that the
ranks shared a distributed assembly."""
import os
import subprocess
import sys


def allow_mpi_runs():
    """As root (CI containers) Open MPI wants both the flag and the environment variables; on a
    one-core machine, oversubscription."""
    os.environ.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                      OMPI_MCA_rmaps_base_oversubscribe="1")


def run(command):
    """The command's stdout; the test fails with its stderr when it exits non-zero."""
    done = subprocess.run(command, capture_output=True, text=True, timeout=300)
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)}: exit {done.returncode}\n{done.stderr}")
    return done.stdout


def check_shared_assembly(result, ranks):
    """link-stiffness's JSON: one entry per rank in solver.elements_per_rank, adding up to the mesh's
    elements."""
    per_rank, elements = result["solver"]["elements_per_rank"], result["mesh"]["elements"]
    print(f"elements assembled per rank: {per_rank} of {elements}")
    if len(per_rank) != int(ranks) or sum(per_rank) != elements:
        sys.exit(f"elements per rank {per_rank}: want {ranks} ranks sharing the {elements} elements")
    return per_rank, elements
