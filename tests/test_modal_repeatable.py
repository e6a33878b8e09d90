"""The modes of a large model are the same on every run, to the last bit.

ARPACK starts from a vector; scipy draws it from fresh entropy when none is
given, which moves the modes within the solver's tolerance from one run to
the next (and every transient computed on them). asterlite gives the same
start every time (:func:`asterlite.modal.eigen.start_vector`).
"""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import scipy.sparse as sp

from asterlite.modal.eigen import _shift_invert, start_vector

# a chain of springs and masses, large enough for ARPACK
N = 400
CHAIN = (
    "import numpy as np, scipy.sparse as sp\n"
    "from asterlite.modal.eigen import _shift_invert\n"
    f"n = {N}\n"
    "k = sp.diags([-np.ones(n - 1), 2.0 * np.ones(n), -np.ones(n - 1)], [-1, 0, 1]).tocsr()\n"
    "m = sp.diags(1.0 + 0.01 * np.arange(n)).tocsr()\n"
    "vals, vecs = _shift_invert(k, m, 0.0, 6)\n"
    "print(vals.tobytes().hex(), vecs.tobytes().hex()[:2000])\n"
)


def test_the_start_vector_is_fixed():
    np.testing.assert_array_equal(start_vector(50), start_vector(50))
    assert np.all(np.abs(start_vector(50)) <= 1.0) and np.ptp(start_vector(50)) > 1.0


def test_two_processes_find_the_same_modes():
    """Each process has its own entropy: the runs must agree anyway."""
    runs = [
        subprocess.run(
            [sys.executable, "-c", CHAIN], capture_output=True, text=True, check=True
        ).stdout
        for _ in range(2)
    ]
    assert runs[0] == runs[1]


def test_the_modes_are_those_of_the_chain():
    n = N
    k = sp.diags([-np.ones(n - 1), 2.0 * np.ones(n), -np.ones(n - 1)], [-1, 0, 1]).tocsr()
    m = sp.identity(n, format="csr")
    vals, _ = _shift_invert(k, m, 0.0, 4)
    exact = 2.0 - 2.0 * np.cos(np.pi * np.arange(1, 5) / (n + 1))
    np.testing.assert_allclose(np.sort(vals), exact, rtol=1e-9)
