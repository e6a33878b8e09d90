"""The eigen solve of one pencil on PETSc/SLEPc, across MPI ranks.

A self-contained script: it needs only numpy, petsc4py, slepc4py and mpi4py
(never asterlite), so it runs under whatever Python has those, e.g. a
distribution's /usr/bin/python3 or a cluster's module. asterlite
(``asterlite.modal.slepc_mpi``) launches it as

    mpirun -n N PYTHON slepc_worker.py FOLDER

where FOLDER holds ``K.petsc`` and ``M.petsc`` (PETSc binary matrices, the
pencil after constraint elimination, symmetric, on one sparsity pattern)
and ``request.json``: ``sigma`` (the shift), ``count`` (eigenpairs wanted,
those nearest the shift) and ``tolerance``. The ranks read the matrices
(rank 0 reads, PETSc distributes the rows), SLEPc's Krylov-Schur method
iterates on shift-and-invert with a MUMPS factorisation of K - σM, and
rank 0 writes ``values.npy`` (the eigenvalues), ``vectors.npy`` (the
eigenvectors gathered, one per column) and ``info.json`` (iterations,
seconds, peak resident memory of every rank). Any failure leaves
``error.txt`` and a non-zero exit status.
"""

from __future__ import annotations

import json
import resource
import sys
import time
import traceback
from pathlib import Path


def _libraries():
    """numpy, PETSc and SLEPc, initialised (before PETSc's module is loaded)."""
    try:
        import numpy as np
        import petsc4py
        import slepc4py

        petsc4py.init(sys.argv[:1])
        slepc4py.init(sys.argv[:1])
        from petsc4py import PETSc
        from slepc4py import SLEPc
    except ImportError as exc:
        raise RuntimeError(f"this Python ({sys.executable}) cannot import {exc.name}") from exc
    return np, PETSc, SLEPc


def solve(folder: Path) -> None:
    np, PETSc, SLEPc = _libraries()
    comm = PETSc.COMM_WORLD
    rank = comm.getRank()
    request = json.loads((folder / "request.json").read_text())
    sigma, count = float(request["sigma"]), int(request["count"])
    start = time.perf_counter()
    matrices = []
    for name in ("K", "M"):
        viewer = PETSc.Viewer().createBinary(str(folder / f"{name}.petsc"), "r", comm=comm)
        matrix = PETSc.Mat().create(comm=comm)
        matrix.setType(PETSc.Mat.Type.AIJ)
        matrix.load(viewer)
        viewer.destroy()
        matrix.setOption(PETSc.Mat.Option.SYMMETRIC, True)
        matrices.append(matrix)
    k, m = matrices
    read_seconds = time.perf_counter() - start

    eps = SLEPc.EPS().create(comm=comm)
    eps.setOperators(k, m)
    eps.setProblemType(SLEPc.EPS.ProblemType.GHEP)
    eps.setType(SLEPc.EPS.Type.KRYLOVSCHUR)
    eps.setDimensions(nev=count, ncv=max(2 * count, count + 16))
    eps.setTarget(sigma)
    eps.setWhichEigenpairs(SLEPc.EPS.Which.TARGET_MAGNITUDE)
    eps.setTolerances(tol=float(request["tolerance"]), max_it=int(request.get("max_it", 200)))
    st = eps.getST()
    st.setType(SLEPc.ST.Type.SINVERT)
    st.setShift(sigma)
    # K and M share their pattern (the writer's union): K - σM is formed in place
    st.setMatStructure(PETSc.Mat.Structure.SAME_NONZERO_PATTERN)
    ksp = st.getKSP()
    ksp.setType(PETSc.KSP.Type.PREONLY)
    pc = ksp.getPC()
    # MUMPS's LDLᵀ: symmetric indefinite when σ lies inside the spectrum
    pc.setType(PETSc.PC.Type.CHOLESKY)
    pc.setFactorSolverType("mumps")
    eps.setFromOptions()  # PETSC_OPTIONS / -eps_* from the environment may refine these
    start = time.perf_counter()
    eps.solve()
    solve_seconds = time.perf_counter() - start
    converged = eps.getConverged()
    if converged < count:
        raise RuntimeError(
            f"SLEPc converged {converged} of {count} eigenpairs in {eps.getIterationNumber()} "
            f"iterations (reason {eps.getConvergedReason()})"
        )
    values = []
    vectors = []
    vector = k.createVecs(side="right")
    scatter, gathered = PETSc.Scatter.toZero(vector)
    for i in range(converged):
        value = eps.getEigenpair(i, vector)
        scatter.scatter(vector, gathered, PETSc.InsertMode.INSERT, PETSc.ScatterMode.FORWARD)
        if rank == 0:
            values.append(value.real)
            vectors.append(gathered.getArray().copy())
    peak_kb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    peaks = comm.tompi4py().gather(peak_kb / 1024.0, root=0)
    if rank == 0:
        order = np.argsort(np.abs(np.asarray(values) - sigma), kind="stable")[:count]
        np.save(folder / "values.npy", np.asarray(values)[order])
        np.save(folder / "vectors.npy", np.column_stack([vectors[i] for i in order]))
        info = {
            "ranks": comm.getSize(),
            "converged": converged,
            "iterations": eps.getIterationNumber(),
            "dimension": eps.getDimensions()[1],
            "read_seconds": read_seconds,
            "solve_seconds": solve_seconds,
            "peak_mb": peaks,
            "petsc": ".".join(map(str, PETSc.Sys.getVersion())),
            "slepc": ".".join(map(str, SLEPc.Sys.getVersion())),
        }
        (folder / "info.json").write_text(json.dumps(info))


def main(argv: list[str]) -> int:
    if len(argv) != 2:
        print("usage: slepc_worker.py FOLDER", file=sys.stderr)
        return 2
    folder = Path(argv[1])
    try:
        solve(folder)
    except Exception:  # the caller reads error.txt: report, then fail every rank
        text = traceback.format_exc()
        print(text, file=sys.stderr)
        try:
            (folder / "error.txt").write_text(text)
        except OSError:
            pass
        try:  # the other ranks may wait in a collective call: end them all
            from mpi4py import MPI

            MPI.COMM_WORLD.Abort(1)
        except ImportError:
            pass
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
