"""CALC_MODES on PETSc/SLEPc across MPI ranks, in a separate solver process.

Selected with ``asterlite run --mpi "mpirun -n 4" [--mpi-python PYTHON]``,
which sets :data:`LAUNCHER_VARIABLE` and :data:`PYTHON_VARIABLE` (the same
variables select it for the Python API). Every sparse modal solve of the run
(more than ``eigen.DENSE_LIMIT`` unknowns) that asks for the modes nearest a
shift (PLUS_PETITE, CENTRE, BANDE) then goes to ``slepc_worker.py``:

1. the reduced pencil (after constraint elimination, the matrices the other
   large-model solvers get) is written as two PETSc binary matrices on one
   sparsity pattern, with a ``request.json``, into a folder of its own
   (under :data:`FOLDER_VARIABLE`, which ``asterlite run`` sets to the run's
   output folder, else the system's temporary folder), removed afterwards;
2. ``LAUNCHER PYTHON slepc_worker.py FOLDER`` runs; the worker imports only
   numpy, petsc4py, slepc4py and mpi4py, so PYTHON may be any interpreter
   that has them (a distribution's, a cluster's), not asterlite's;
3. rank 0's ``values.npy`` and ``vectors.npy`` come back, and CALC_MODES
   sorts, normalises and checks them as it does any solver's modes.

A run as root gets OpenMPI's consent variables (OMPI_ALLOW_RUN_AS_ROOT);
each rank runs one thread (OMP_NUM_THREADS=1, OPENBLAS_NUM_THREADS=1) unless
the environment says otherwise (:func:`worker_environment`).
"""

from __future__ import annotations

import glob
import json
import os
import shlex
import shutil
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np
import scipy.sparse as sp

LAUNCHER_VARIABLE = "ASTERLITE_MPI"
PYTHON_VARIABLE = "ASTERLITE_MPI_PYTHON"
FOLDER_VARIABLE = "ASTERLITE_MPI_FOLDER"
DEFAULT_PYTHON = "python3"
WORKER = Path(__file__).with_name("slepc_worker.py")
#: SLEPc's relative residual ||K x - λ M x|| / (|λ| ||x||) at convergence
TOLERANCE = 1e-10
PETSC_MAT_CLASSID = 1211216
WORKER_IMPORTS = ("numpy", "petsc4py", "slepc4py", "mpi4py")
DEBIAN_TREES = (
    ("PETSC_DIR", "/usr/lib/petsc", "/usr/lib/petscdir/petsc3.*/*-real"),
    ("SLEPC_DIR", "/usr/lib/slepc", "/usr/lib/slepcdir/slepc3.*/*-real"),
)


class MpiSolveError(RuntimeError):
    """The MPI solver could not be launched or did not finish."""


def launcher() -> list[str] | None:
    """The launch command (e.g. ``["mpirun", "-n", "4"]``), None when the
    MPI solver is not selected."""
    text = os.environ.get(LAUNCHER_VARIABLE, "").strip()
    return shlex.split(text) if text else None


def python() -> str:
    return os.environ.get(PYTHON_VARIABLE, "").strip() or DEFAULT_PYTHON


def worker_environment() -> dict:
    """The ranks' environment: asterlite's, with one thread per rank, root's
    consent for OpenMPI when run as root, and PETSC_DIR / SLEPC_DIR pointing
    at Debian's real-scalar trees when only its runtime packages are there
    (their petsc4py and slepc4py find PETSc through /usr/lib/petsc and
    /usr/lib/slepc, links that only the -dev packages make)."""
    env = dict(os.environ)
    for variable, link, pattern in DEBIAN_TREES:
        found = sorted(glob.glob(pattern))
        if not env.get(variable) and not os.path.exists(link) and found:
            env[variable] = found[-1]
    env.setdefault("OMP_NUM_THREADS", "1")
    env.setdefault("OPENBLAS_NUM_THREADS", "1")
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
        env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    return env


def unavailable(command: list[str], interpreter: str) -> str | None:
    """Why the MPI solver cannot run with this launch command and Python
    (a sentence), or None when the launcher is found and the interpreter
    imports what the worker needs."""
    if not command:
        return "--mpi needs a launch command, e.g. --mpi 'mpirun -n 4'"
    if shutil.which(command[0]) is None:
        return f"--mpi: the launcher {command[0]!r} is not found"
    if shutil.which(interpreter) is None:
        return f"--mpi-python: {interpreter!r} is not found"
    probe = "import " + ", ".join(WORKER_IMPORTS)
    try:
        done = subprocess.run(
            [interpreter, "-c", probe],
            capture_output=True,
            text=True,
            timeout=120,
            env=worker_environment(),
        )
    except (OSError, subprocess.TimeoutExpired) as exc:
        return f"--mpi-python {interpreter}: cannot run it ({exc})"
    if done.returncode != 0:
        last = (done.stderr.strip().splitlines() or ["?"])[-1]
        return (
            f"--mpi-python {interpreter} cannot import the worker's modules "
            f"({', '.join(WORKER_IMPORTS)}): {last}; on Debian/Ubuntu: apt-get install "
            "python3-petsc4py python3-slepc4py python3-mpi4py openmpi-bin"
        )
    return None


def common_pattern(k, m):
    """(K, M) as CSR matrices on the union of their patterns (explicit zeros
    kept), so that the worker forms K - σM in place."""
    k, m = sp.coo_matrix(k), sp.coo_matrix(m)
    where = (np.concatenate([k.row, m.row]), np.concatenate([k.col, m.col]))
    k_u = sp.csr_matrix((np.concatenate([k.data, np.zeros(m.nnz)]), where), shape=k.shape)
    m_u = sp.csr_matrix((np.concatenate([np.zeros(k.nnz), m.data]), where), shape=k.shape)
    k_u.sort_indices()
    m_u.sort_indices()
    if not (np.array_equal(k_u.indptr, m_u.indptr) and np.array_equal(k_u.indices, m_u.indices)):
        raise MpiSolveError("K and M could not be put on one sparsity pattern")
    return k_u, m_u


def write_petsc_matrix(path: Path, matrix) -> None:
    """``matrix`` in PETSc's binary format: big-endian int32 class id, rows,
    columns, non-zeros, the row lengths and the column indices, then the
    float64 values (32-bit indices: fewer than 2**31 non-zeros)."""
    csr = sp.csr_matrix(matrix)
    if csr.nnz >= 2**31:
        raise MpiSolveError(f"{csr.nnz} non-zeros: PETSc binary matrices hold fewer than 2**31")
    header = np.array([PETSC_MAT_CLASSID, *csr.shape, csr.nnz], dtype=">i4")
    with open(path, "wb") as out:
        out.write(header.tobytes())
        out.write(np.diff(csr.indptr).astype(">i4").tobytes())
        out.write(csr.indices.astype(">i4").tobytes())
        out.write(csr.data.astype(">f8").tobytes())


def nearest(k, m, sigma: float, count: int):
    """(values, vectors, how) of the ``count`` eigenpairs of K φ = λ M φ
    nearest ``sigma``, from the MPI worker; ``how`` describes the solve for
    the log (the keys ``eigen._large_shift_invert`` gives, plus ``summary``)."""
    command = launcher()
    if command is None:
        raise MpiSolveError(f"the MPI solver is not selected ({LAUNCHER_VARIABLE} is empty)")
    parent = os.environ.get(FOLDER_VARIABLE) or None
    if parent is not None:
        Path(parent).mkdir(parents=True, exist_ok=True)
    folder = Path(tempfile.mkdtemp(prefix="mpi-solve-", dir=parent))
    try:
        start = time.perf_counter()
        k_u, m_u = common_pattern(k, m)
        write_petsc_matrix(folder / "K.petsc", k_u)
        write_petsc_matrix(folder / "M.petsc", m_u)
        del k_u, m_u
        request = {"sigma": float(sigma), "count": int(count), "tolerance": TOLERANCE}
        (folder / "request.json").write_text(json.dumps(request))
        write_seconds = time.perf_counter() - start
        start = time.perf_counter()
        argv = [*command, python(), str(WORKER), str(folder)]
        done = subprocess.run(
            argv, capture_output=True, text=True, env=worker_environment(), stdin=subprocess.DEVNULL
        )
        wall = time.perf_counter() - start
        if done.returncode != 0 or not (folder / "info.json").exists():
            error = folder / "error.txt"
            text = error.read_text() if error.exists() else (done.stderr or done.stdout)
            last = (text.strip().splitlines() or ["no message"])[-1]
            raise MpiSolveError(
                f"the MPI eigen solver ({shlex.join(argv[:-1])}) failed "
                f"(exit {done.returncode}): {last}"
            )
        info = json.loads((folder / "info.json").read_text())
        values = np.load(folder / "values.npy")
        vectors = np.load(folder / "vectors.npy")
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    peaks = ", ".join(f"{mb:.0f}" for mb in info["peak_mb"])
    how = {
        "method": f"SLEPc Krylov-Schur on {info['ranks']} MPI ranks",
        "backend": "mumps",
        "factor_seconds": 0.0,
        "iteration_seconds": info["solve_seconds"],
        "ranks": info["ranks"],
        "peak_mb": info["peak_mb"],
        "summary": (
            f"SLEPc {info['slepc']} Krylov-Schur, shift-invert on MUMPS, "
            f"{info['ranks']} MPI ranks: {info['iterations']} restarts, "
            f"{info['converged']} converged; files {write_seconds:.1f} s, "
            f"worker {wall:.1f} s (solve {info['solve_seconds']:.1f} s), "
            f"peak MB per rank {peaks}"
        ),
    }
    return values, vectors, how
