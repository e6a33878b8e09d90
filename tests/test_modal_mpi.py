"""CALC_MODES on PETSc/SLEPc across MPI ranks (asterlite.modal.slepc_mpi and
its worker): the PETSc binary files, the refusals, and a bar's modes through
2 ranks against the default solver. The MPI run needs mpirun and a Python
importing numpy, petsc4py, slepc4py and mpi4py (Debian's python3-petsc4py
python3-slepc4py python3-mpi4py openmpi-bin): without them it skips, except
in CI (``CI=true``), where .ci/run installs them."""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
import pytest
import scipy.linalg as sla
import scipy.sparse as sp

from asterlite.modal import slepc_mpi
from tests.test_large_modal import _bar_frequencies

#: the interpreter of the ranks: Debian's, whose numpy 1.24 petsc4py is built for
MPI_PYTHON = os.environ.get("ASTERLITE_TEST_MPI_PYTHON", "/usr/bin/python3")
LAUNCHER = "mpirun --oversubscribe -n 2"


@pytest.fixture()
def mpi():
    problem = slepc_mpi.unavailable(LAUNCHER.split(), MPI_PYTHON)
    if problem is None:
        return
    if os.environ.get("CI", "").lower() == "true":
        pytest.fail(f"CI: {problem} (.ci/run installs them)")
    pytest.skip(problem)


def _read_petsc_matrix(path):
    raw = path.read_bytes()
    classid, rows, cols, nnz = np.frombuffer(raw[:16], dtype=">i4")
    assert classid == slepc_mpi.PETSC_MAT_CLASSID
    lengths = np.frombuffer(raw[16 : 16 + 4 * rows], dtype=">i4")
    start = 16 + 4 * rows
    indices = np.frombuffer(raw[start : start + 4 * nnz], dtype=">i4")
    values = np.frombuffer(raw[start + 4 * nnz :], dtype=">f8")
    assert values.size == nnz
    indptr = np.concatenate([[0], np.cumsum(lengths)])
    return sp.csr_matrix((values, indices, indptr), shape=(rows, cols))


def test_the_pencil_is_written_on_one_pattern_in_petsc_binary(tmp_path):
    k = sp.csr_matrix(np.array([[4.0, -1.0, 0.0], [-1.0, 4.0, 0.0], [0.0, 0.0, 2.0]]))
    m = sp.csr_matrix(np.array([[1.0, 0.0, 0.5], [0.0, 1.0, 0.0], [0.5, 0.0, 0.0]]))
    k_u, m_u = slepc_mpi.common_pattern(k, m)
    assert k_u.nnz == m_u.nnz == 7  # the union, explicit zeros kept
    for original, written, name in ((k, k_u, "K"), (m, m_u, "M")):
        slepc_mpi.write_petsc_matrix(tmp_path / name, written)
        back = _read_petsc_matrix(tmp_path / name)
        np.testing.assert_array_equal(back.toarray(), original.toarray())
        np.testing.assert_array_equal(back.indices, k_u.indices)


def test_a_missing_launcher_or_worker_python_stops_the_run_by_name(tmp_path):
    deck = tmp_path / "x.comm"
    deck.write_text("DEBUT()\nFIN()\n")
    for options, said in (
        (["--mpi", "no-such-mpirun -n 2"], "no-such-mpirun"),
        (["--mpi", "mpirun -n 2", "--mpi-python", str(tmp_path / "nopython")], "nopython"),
        (["--mpi-python", sys.executable], "--mpi-python needs --mpi"),
    ):
        done = subprocess.run(
            [sys.executable, "-m", "asterlite", "run", str(deck), "-o", str(tmp_path / "o")]
            + options,
            capture_output=True,
            text=True,
        )
        assert done.returncode == 2, done.stderr
        assert said in done.stderr
        assert "Traceback" not in done.stderr


def test_a_worker_python_without_petsc4py_is_named():
    # asterlite's own interpreter has numpy 2 and no petsc4py
    problem = slepc_mpi.unavailable(["mpirun", "-n", "2"], sys.executable)
    if problem is None:
        pytest.skip("this interpreter imports petsc4py")
    assert "petsc4py" in problem or "mpirun" in problem


def test_calc_modes_through_two_mpi_ranks_equals_the_default_solver(tmp_path, monkeypatch, mpi):
    reference, _ = _bar_frequencies(tmp_path / "default", "auto", monkeypatch)
    monkeypatch.setenv(slepc_mpi.LAUNCHER_VARIABLE, LAUNCHER)
    monkeypatch.setenv(slepc_mpi.PYTHON_VARIABLE, MPI_PYTHON)
    monkeypatch.setenv(slepc_mpi.FOLDER_VARIABLE, str(tmp_path / "work"))
    found, log = _bar_frequencies(tmp_path / "mpi", "auto", monkeypatch)
    assert log.count("Krylov-Schur, shift-invert on MUMPS, 2 MPI ranks") >= 3
    assert [len(f) for f in found] == [len(f) for f in reference] == [20, 6, len(reference[2])]
    for new, old in zip(found, reference, strict=True):
        np.testing.assert_allclose(new, old, rtol=1e-8)
    assert not list((tmp_path / "work").iterdir())  # the solver's files are gone


def test_plus_grande_is_refused_by_name_on_the_mpi_solver(monkeypatch):
    from asterlite.fem.constraints import Elimination
    from asterlite.modal import eigen

    n = 500
    k = sp.diags(np.arange(1.0, n + 1.0)).tocsr()
    m = sp.identity(n, format="csr")
    free = np.arange(n)
    none = np.zeros(0, dtype=int)
    pencil = eigen.ReducedPencil(
        k, m, Elimination(sp.identity(n, format="csr"), np.zeros(n), free, none)
    )
    monkeypatch.setenv(slepc_mpi.LAUNCHER_VARIABLE, "mpirun -n 2")
    with pytest.raises(eigen.EigenError, match="PLUS_GRANDE"):
        pencil.largest(3)


def test_the_worker_finds_the_pairs_nearest_a_shift_inside_the_spectrum(tmp_path, monkeypatch, mpi):
    # K - σM indefinite: MUMPS's LDLᵀ under shift-and-invert, against LAPACK
    from tests.test_large_modal import _grid_pencil

    k, m = _grid_pencil(24, 23)
    m = sp.diags(np.linspace(1.0, 2.0, k.shape[0])) @ m
    exact = sla.eigh(k.toarray(), m.toarray(), eigvals_only=True)
    sigma = 0.5 * (exact[40] + exact[41])
    monkeypatch.setenv(slepc_mpi.LAUNCHER_VARIABLE, LAUNCHER)
    monkeypatch.setenv(slepc_mpi.PYTHON_VARIABLE, MPI_PYTHON)
    monkeypatch.setenv(slepc_mpi.FOLDER_VARIABLE, str(tmp_path))
    values, vectors, how = slepc_mpi.nearest(k, m, sigma, 8)
    assert how["ranks"] == 2 and len(how["peak_mb"]) == 2
    nearest = exact[np.argsort(np.abs(exact - sigma))[:8]]
    np.testing.assert_allclose(np.sort(values), np.sort(nearest), rtol=1e-10)
    residual = k @ vectors - (m @ vectors) * values
    assert np.linalg.norm(residual, axis=0).max() < 1e-8 * np.abs(values).max()
