"""The harmonic sweep's sparse LDLᵀ compiled in C++ (asterlite.dynamics.native._ldl)
against numba's kernels of asterlite.harmonic.ldl, bit for bit: the symbolic
analysis (elimination tree, column counts, fill, a fill limit that stops it),
the numeric factor (li, lx, d; a vanishing pivot) and the solves, on random
complex symmetric matrices of several sizes and patterns, under several
permutations, with int32 and int64 indices in any mix, on full and upper
patterns; then through physical.solve and a DYNA_VIBRA HARM PHYS deck."""

from __future__ import annotations

import os

import numpy as np
import pytest
import scipy.sparse as sp

from asterlite.dynamics import native
from asterlite.fem.constraints import eliminate
from asterlite.harmonic import ldl, physical
from asterlite.io.export import describe_run
from asterlite.runtime.session import Session

pytestmark = [
    pytest.mark.usefixtures("needs_native", "needs_ldl"),
    pytest.mark.xdist_group("numba-reference"),
]

I32, I64 = np.int32, np.int64


@pytest.fixture()
def needs_ldl():
    """The C++ module built (needs_native checks the time loops')."""
    if ldl._ldl is not None:
        return
    if os.environ.get("CI", "").lower() == "true":
        pytest.fail("CI: asterlite.dynamics.native._ldl is not built")
    pytest.skip("asterlite.dynamics.native._ldl is not built")


def same_bits(a, b) -> bool:
    a, b = np.ascontiguousarray(a), np.ascontiguousarray(b)
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


# ----------------------------------------------------------------------------- matrices


def pattern(kind: str, n: int, rng) -> sp.csc_matrix:
    """A symmetric pattern (ones) of n columns."""
    if kind == "random":
        a = sp.random(n, n, density=min(1.0, 4.0 / n), random_state=rng, format="csc")
        a = a + a.T + sp.identity(n)
    elif kind == "band":
        a = sp.diags([np.ones(n - abs(k)) for k in range(-3, 4)], range(-3, 4))
    elif kind == "grid":  # the 5-point Laplacian of a k x k grid (n = k * k)
        k = int(round(np.sqrt(n)))
        one = sp.diags([np.ones(k - 1), np.ones(k), np.ones(k - 1)], [-1, 0, 1])
        a = sp.kron(one, sp.identity(k)) + sp.kron(sp.identity(k), one)
    elif kind == "arrow":  # a dense last row and column: no fill
        a = sp.identity(n, format="lil")
        a[n - 1, :] = 1.0
        a[:, n - 1] = 1.0
    elif kind == "dense_first":  # a dense first row and column: L is full
        a = sp.identity(n, format="lil")
        a[0, :] = 1.0
        a[:, 0] = 1.0
    elif kind == "diagonal":
        a = sp.identity(n)
    elif kind == "holes":  # random, without some diagonal terms (fill makes them)
        a = sp.random(n, n, density=min(1.0, 6.0 / n), random_state=rng, format="lil")
        a = a + a.T
        a.setdiag(1.0)
        a = sp.lil_matrix(a)
        for i in range(1, n, 3):
            a[i, i] = 0.0
    else:
        raise ValueError(kind)
    a = sp.csc_matrix(a)
    a.eliminate_zeros()
    a.data[:] = 1.0
    return a


def values_on(a: sp.csc_matrix, rng) -> sp.csc_matrix:
    """Complex symmetric values on a's pattern, diagonally dominant (both
    branches of Smith's division: |re| >= |im| and |im| > |re|)."""
    upper = sp.triu(a, format="coo")
    data = rng.standard_normal(upper.nnz) + 1j * rng.standard_normal(upper.nnz)
    on_diagonal = upper.row == upper.col
    data[on_diagonal] *= 10.0
    upper = sp.coo_matrix((data, (upper.row, upper.col)), shape=a.shape)
    strict = sp.triu(upper, k=1)
    whole = sp.csc_matrix(upper + strict.T)
    whole.sort_indices()
    return whole


def permutation(kind: str, n: int, rng) -> np.ndarray:
    if kind == "identity":
        return np.arange(n)
    if kind == "reversed":
        return np.arange(n)[::-1].copy()
    return rng.permutation(n)


@pytest.fixture()
def numba_route(monkeypatch):
    """Run a block of ldl.py's public functions on numba's kernels, or on the
    C++ ones: ``with numba_route(True): ...``."""

    class Route:
        def __init__(self, numba: bool):
            self.numba = numba

        def __enter__(self):
            monkeypatch.setenv(native.SWITCH, "0" if self.numba else "1")
            assert ldl._compiled() is not self.numba

        def __exit__(self, *exc):
            monkeypatch.delenv(native.SWITCH, raising=False)

    return Route


def analyses(numba_route, a, perm, upper, limit=None):
    """ldl.analyse on numba's kernels and on the C++ ones."""
    caller = sp.csc_matrix(sp.triu(a)) if upper else a
    found = []
    for numba in (True, False):
        with numba_route(numba):
            found.append(
                ldl.analyse(caller.indptr, caller.indices, a.shape[0], perm, limit, upper=upper)
            )
    return caller, found


def assert_same_analysis(numba, compiled):
    for field in ("perm", "upper_ptr", "upper_idx", "source", "parent", "lp"):
        assert same_bits(getattr(numba, field), getattr(compiled, field)), field
    assert numba.n == compiled.n


# ----------------------------------------------------------------------------- kernels

CASES = [
    (kind, n, order)
    for kind, n in [
        ("random", 1),
        ("random", 2),
        ("random", 9),
        ("random", 80),
        ("random", 500),
        ("band", 40),
        ("grid", 196),
        ("arrow", 30),
        ("dense_first", 25),
        ("diagonal", 12),
        ("holes", 60),
    ]
    for order in ("identity", "reversed", "random")
]


@pytest.mark.parametrize("upper", [False, True], ids=["full", "upper"])
@pytest.mark.parametrize(("kind", "n", "order"), CASES)
def test_analysis_factor_and_solve_give_numbas_bits(numba_route, kind, n, order, upper):
    rng = np.random.default_rng([n, len(kind), len(order), upper])
    a = values_on(pattern(kind, n, rng), rng)
    perm = permutation(order, n, rng)
    caller, (reference, analysis) = analyses(numba_route, a, perm, upper)
    assert_same_analysis(reference, analysis)
    assert reference.upper_ptr.dtype == np.int32  # ldl.analyse's own index type here
    data = caller.data
    rhs = rng.standard_normal(n) + 1j * rng.standard_normal(n)
    results = []
    for numba in (True, False):
        with numba_route(numba):
            try:
                factor = ldl.factorise(analysis, data)
            except ldl.ZeroPivot as pivot:
                results.append(("pivot", pivot.args))
                continue
            results.append((factor.li, factor.lx, factor.d, factor.solve(rhs)))
    if isinstance(results[0][0], str):
        assert kind == "holes" and results[1] == results[0]
        return
    for numba_array, compiled_array in zip(*results, strict=True):
        assert same_bits(numba_array, compiled_array)
    x = results[1][-1]
    np.testing.assert_allclose(a @ x, rhs, atol=1e-9 * np.abs(rhs).max())


# every mix of index types numba compiles a specialisation for: (ap and ai,
# lp, parent, li)
MIXES = [
    (I32, I64, I64, I32),
    (I64, I64, I64, I64),
    (I32, I64, I64, I64),
    (I64, I64, I64, I32),
    (I32, I32, I32, I32),
    (I64, I32, I32, I64),
]


def direct_kernels(a, perm, mix, rng):
    """The three kernels called directly on both sides with the index types
    ``mix``: their returns and every array they write."""
    pointers, lps, parents, rows = mix
    analysis = ldl.analyse(a.indptr, a.indices, a.shape[0], perm)
    n, fill = analysis.n, analysis.fill
    ap = analysis.upper_ptr.astype(pointers)
    ai = analysis.upper_idx.astype(pointers)
    values = np.ascontiguousarray(a.data[analysis.source])
    rhs = rng.standard_normal(n) + 1j * rng.standard_normal(n)
    out = []
    for kernels in (
        (ldl._symbolic, ldl._numeric, ldl._solve),
        (ldl._ldl.symbolic, ldl._ldl.numeric, ldl._ldl.solve),
    ):
        symbolic, numeric, solve = kernels
        parent, lnz, total = symbolic(n, ap, ai, np.iinfo(np.int64).max)
        assert parent.dtype == lnz.dtype == np.int64 and isinstance(total, int)
        lp = np.zeros(n + 1, dtype=lps)
        np.cumsum(lnz, out=lp[1:])
        li = np.zeros(fill, rows)
        lx = np.zeros(fill, np.complex128)
        d = np.zeros(n, np.complex128)
        status = numeric(n, ap, ai, values, lp, parent.astype(parents), li, lx, d)
        x = rhs.copy()
        if status < 0:
            assert solve(n, lp, li, lx, d, x) is None
        out.append((parent, lnz, total, status, li, lx, d, x))
    return out


@pytest.mark.parametrize("mix", MIXES, ids=lambda m: "-".join(t.__name__[3:] for t in m))
@pytest.mark.parametrize(("kind", "n"), [("random", 150), ("grid", 100), ("holes", 40)])
def test_the_kernels_on_every_mix_of_index_types(kind, n, mix):
    rng = np.random.default_rng([n, len(kind)])
    a = values_on(pattern(kind, n, rng), rng)
    reference, compiled = direct_kernels(a, rng.permutation(n), mix, rng)
    for numba_value, compiled_value in zip(reference, compiled, strict=True):
        if isinstance(numba_value, np.ndarray):
            assert same_bits(numba_value, compiled_value)
        else:
            assert type(numba_value) is type(compiled_value) and numba_value == compiled_value
    assert compiled[3] == -1 or kind == "holes"


@pytest.mark.parametrize("upper", [False, True], ids=["full", "upper"])
@pytest.mark.parametrize("share", [0.0, 0.3, 0.7, 0.95])
def test_a_fill_limit_stops_the_analysis_where_numbas_does(numba_route, share, upper):
    rng = np.random.default_rng(7)
    n = 300
    a = values_on(pattern("random", n, rng), rng)
    perm = rng.permutation(n)
    _, (whole, _) = analyses(numba_route, a, perm, upper)
    limit = int(share * whole.fill)
    _, found = analyses(numba_route, a, perm, upper, limit)
    assert found == [None, None]
    # the kernels themselves: total -1, the same counts, the same tree on
    # the columns reached (numba's parent is np.empty past them)
    ap, ai = whole.upper_ptr, whole.upper_idx
    parent, lnz, total = ldl._symbolic(n, ap, ai, limit)
    parent_cpp, lnz_cpp, total_cpp = ldl._ldl.symbolic(n, ap, ai, limit)
    assert total == total_cpp == -1
    assert same_bits(lnz, lnz_cpp) and lnz.sum() > limit
    # each column k adds L's row k: the analysis stops at the first column
    # whose predecessors exceed the limit
    caller = sp.csc_matrix(sp.triu(a)) if upper else a
    row_counts = np.bincount(ldl.factorise(whole, caller.data).li, minlength=n)
    reached = int(np.searchsorted(np.cumsum(row_counts), limit, side="right")) + 1
    assert reached < n
    assert same_bits(parent[:reached], parent_cpp[:reached])
    # a limit at the fill keeps the analysis; so does one that only the
    # last column's terms exceed (the fill is compared before each column)
    for kept_limit in (whole.fill, whole.fill - row_counts[-1]):
        _, kept = analyses(numba_route, a, perm, upper, kept_limit)
        assert_same_analysis(*kept)
        assert_same_analysis(whole, kept[1])


def factor_with_a_zero_pivot(n: int, column: int, rng) -> sp.csc_matrix:
    """A = L D Lᵀ in exact integer arithmetic with D[column] = 0 (the other
    pivots ±1, ±i: every quotient of the factorisation is exact), so that
    both factorisations meet an exact zero pivot at ``column``."""
    lower = np.tril(rng.integers(-1, 2, (n, n)) * (rng.random((n, n)) < 0.4), -1)
    lower = lower + 1j * np.tril(rng.integers(-1, 2, (n, n)) * (rng.random((n, n)) < 0.2), -1)
    lower += np.eye(n)
    pivots = rng.choice(np.array([1.0, -1.0, 1j, -1j]), n)
    pivots[column] = 0.0
    whole = lower @ np.diag(pivots) @ lower.T
    assert np.array_equal(whole, whole.T)
    return sp.csc_matrix(whole)


@pytest.mark.parametrize("column", [0, 5, 13])
def test_a_zero_pivot_raises_zero_pivot_as_numbas_does(numba_route, column):
    rng = np.random.default_rng(column)
    n = 14
    a = factor_with_a_zero_pivot(n, column, rng)
    _, (reference, analysis) = analyses(numba_route, a, np.arange(n), False)
    assert_same_analysis(reference, analysis)
    raised = []
    for numba in (True, False):
        with numba_route(numba), pytest.raises(ldl.ZeroPivot) as pivot:
            ldl.factorise(analysis, a.data)
        raised.append(pivot.value.args)
    assert raised == [(column,), (column,)]
    # the arrays written up to the zero pivot, by both
    mix = (I32, I64, I64, I32)
    reference, compiled = direct_kernels(a, np.arange(n), mix, rng)
    assert reference[3] == compiled[3] == column
    for numba_value, compiled_value in zip(reference[4:7], compiled[4:7], strict=True):
        assert same_bits(numba_value, compiled_value)
    d = compiled[6]
    assert d[column] == 0 and np.all(d[:column] != 0)


def test_a_zero_of_d_in_solve_raises_zero_division_as_numbas_does():
    """_solve divides by d: numba raises ZeroDivisionError at an exact zero
    (either sign), x solved up to there; the C++ does the same. (_numeric
    cannot divide by zero: d[i] is a pivot checked nonzero at column i.)"""
    rng = np.random.default_rng(3)
    n = 30
    a = values_on(pattern("random", n, rng), rng)
    analysis = ldl.analyse(a.indptr, a.indices, n, np.arange(n))
    factor = ldl.factorise(analysis, a.data)
    d = factor.d.copy()
    d[17] = complex(-0.0, 0.0)
    b = rng.standard_normal(n) + 1j * rng.standard_normal(n)
    after = []
    for solve in (ldl._solve, ldl._ldl.solve):
        x = b.copy()
        with pytest.raises(ZeroDivisionError, match="complex division by zero"):
            solve(n, analysis.lp, factor.li, factor.lx, d, x)
        after.append(x)
    assert same_bits(*after) and not np.array_equal(after[0], b)


def test_infinities_and_nans_give_numbas_values():
    """Non-finite values in the matrix: the same bits but NaNs' signs (see
    same_values)."""
    rng = np.random.default_rng(11)
    n = 40
    a = values_on(pattern("random", n, rng), rng)
    a.data[3] = complex(np.inf, 1.0)
    a.data[11] = complex(np.nan, 0.0)
    a.data[20] = complex(1.0, -np.inf)
    analysis = ldl.analyse(a.indptr, a.indices, n, np.arange(n))
    values = np.ascontiguousarray(a.data[analysis.source])
    out = []
    for numeric in (ldl._numeric, ldl._ldl.numeric):
        li = np.zeros(analysis.fill, np.int32)
        lx = np.zeros(analysis.fill, complex)
        d = np.zeros(n, complex)
        status = numeric(n, analysis.upper_ptr, analysis.upper_idx, values, analysis.lp,
                         analysis.parent, li, lx, d)  # fmt: skip
        out.append((status, li, lx, d))
    assert out[0][0] == out[1][0]
    assert same_bits(out[0][1], out[1][1])
    for numba_array, compiled_array in zip(out[0][2:], out[1][2:], strict=True):
        assert same_values(numba_array, compiled_array)
        assert np.isnan(numba_array).any()


def same_values(a, b) -> bool:
    """The same bits, NaNs aside: both NaN at the same places. Which of two
    NaNs an addition or product passes on is the compiler's choice of operand
    order (LLVM's and GCC's differ); IEEE 754 leaves it open."""
    a, b = np.ascontiguousarray(a), np.ascontiguousarray(b)
    nan = np.isnan(a.view(np.float64))
    return bool(
        np.array_equal(nan, np.isnan(b.view(np.float64)))
        and np.array_equal(a.view(np.uint64)[~nan], b.view(np.uint64)[~nan])
    )


SPECIAL = [0.0, -0.0, 1.0, -3.0, 0.25, np.inf, -np.inf, np.nan, 2.5e300, 1e-300]


def test_special_values_divide_and_multiply_as_numbas_do():
    """Every pair of complex numbers made of zeros of either sign, infinities,
    NaN, huge and tiny values: quotients (x / d in _solve, both branches of
    Smith's algorithm and its NaN one; ZeroDivisionError at the same pairs)
    and products (x[i] -= lx * x[j])."""
    numbers = [complex(r, i) for r in SPECIAL for i in SPECIAL]
    pairs = [(a, b) for a in numbers for b in numbers]
    empty = (np.zeros(0, np.int64), np.zeros(0, complex))
    results = []
    for solve in (ldl._solve, ldl._ldl.solve):
        quotients, products, zero = np.zeros(len(pairs), complex), np.zeros(len(pairs), complex), []
        for k, (a, b) in enumerate(pairs):
            x = np.array([a])
            try:
                solve(1, np.zeros(2, np.int64), *empty, np.array([b]), x)
            except ZeroDivisionError:
                zero.append(k)
            quotients[k] = x[0]
            x = np.array([a, 0.0])
            solve(2, np.array([0, 1, 1]), np.array([1]), np.array([b]), np.ones(2, complex), x)
            products[k] = x[1]
        results.append((quotients, products, zero))
    (q0, p0, z0), (q1, p1, z1) = results
    assert z0 == z1 and len(z0) == 4 * len(numbers)  # by +-0 +-0j
    assert same_values(q0, q1) and same_values(p0, p1)
    assert np.isnan(q0).any() and np.isinf(q0).any() and np.isinf(p0).any()


def test_arrays_the_kernels_cannot_take_are_refused():
    n = 3
    ap = np.array([0, 1, 2, 3], dtype=np.int64)
    ai = np.array([0, 1, 2], dtype=np.int64)
    with pytest.raises(TypeError, match="int32 or int64"):
        ldl._ldl.symbolic(n, ap.astype(float), ai, 10)
    with pytest.raises(TypeError, match="C-ordered"):
        ldl._ldl.symbolic(n, ap, np.arange(6)[::2], 10)
    with pytest.raises(ValueError, match="inconsistent arrays: ai"):
        ldl._ldl.symbolic(n, ap, np.array([0, 1, 3]), 10)
    with pytest.raises(ValueError, match="inconsistent arrays: ap"):
        ldl._ldl.symbolic(n, np.array([0, 2, 1, 3]), ai, 10)
    values = np.ones(3, complex)
    lp = np.zeros(4, np.int64)
    out = (np.zeros(0, np.int32), np.zeros(0, complex), np.zeros(3, complex))
    parent = np.full(3, -1, dtype=np.int64)
    with pytest.raises(TypeError, match="complex128"):
        ldl._ldl.numeric(n, ap, ai, values.real.copy(), lp, parent, *out)
    with pytest.raises(TypeError, match="writable"):
        ldl._ldl.numeric(n, ap, ai, values, lp, parent, out[0], out[1], np.broadcast_to(0j, 3))
    assert ldl._ldl.numeric(n, ap, ai, values, lp, parent, *out) == -1
    # a tree that is not this pattern's: stopped, not read out of bounds
    full = np.array([0, 1, 3, 6]), np.array([0, 0, 1, 0, 1, 2])
    with pytest.raises(ValueError, match="not the analysis"):
        lp = np.array([0, 2, 3, 3])
        out = (np.zeros(3, np.int32), np.zeros(3, complex), np.zeros(3, complex))
        ldl._ldl.numeric(n, *full, np.ones(6, complex), lp, parent, *out)


# ----------------------------------------------------------------------------- physical sweeps


class Counting:
    """The C++ module, counting the calls of its functions."""

    def __init__(self, module):
        self.module, self.calls = module, 0

    def __getattr__(self, name):
        function = getattr(self.module, name)

        def call(*args):
            self.calls += 1
            return function(*args)

        return call


def _grid_laplacian(k: int) -> sp.csc_matrix:
    one = sp.diags([-np.ones(k - 1), 2 * np.ones(k), -np.ones(k - 1)], [-1, 0, 1])
    eye = sp.identity(k)
    lap = sp.kron(sp.kron(one, eye), eye) + sp.kron(sp.kron(eye, one), eye)
    return sp.csc_matrix(lap + sp.kron(sp.kron(eye, eye), one))


@pytest.fixture()
def ldl_sweeps(monkeypatch):
    """physical's LDLᵀ at every size and frequency (no SuperLU timing, no
    MUMPS, no ordering kept from an earlier sweep), the C++ calls counted."""
    monkeypatch.setattr(physical, "SUPERLU_MAX_FILL", -1)
    monkeypatch.setattr(physical.sparse_direct, "choose_backend", lambda n, definite=False: "x")
    monkeypatch.setattr(physical, "_KNOWN_ORDERINGS", [])
    counting = Counting(ldl._ldl)
    monkeypatch.setattr(ldl, "_ldl", counting)
    return counting


@pytest.mark.parametrize("upper", [True, False], ids=["upper", "full"])
def test_physical_sweeps_give_numbas_bits(numba_route, ldl_sweeps, monkeypatch, upper):
    """physical.solve on a 1331-unknown 3D grid with a viscous damping, one
    unknown clamped: the upper pencil in the factor's order (n >= LDL_MIN_SIZE)
    and the full pattern (LDL_MIN_SIZE lowered after prepare)."""
    k_matrix = _grid_laplacian(11) * complex(1.0e4, 3.0e2)
    n = k_matrix.shape[0]
    m_matrix = sp.csc_matrix(sp.identity(n) * 2.0 + sp.eye(n, k=1) * 0.1 + sp.eye(n, k=-1) * 0.1)
    c_matrix = sp.csc_matrix(
        sp.identity(n) * 0.5 + sp.eye(n, k=11) * 0.05 + sp.eye(n, k=-11) * 0.05
    )
    clamped = sp.csr_matrix(([1.0], ([0], [0])), shape=(1, n))
    elimination = eliminate(clamped, np.zeros(1), n)
    force = np.random.default_rng(5).standard_normal((2, n))
    frequencies = np.array([0.5, 3.0, 11.0, 27.0])
    coefficients = np.array([[1.0, 0.5j], [2.0, -1.0], [1j, 1.0], [0.3, 0.3]])
    solved = []
    for numba in (True, False):
        monkeypatch.setattr(physical, "_KNOWN_ORDERINGS", [])
        monkeypatch.setattr(physical, "LDL_MIN_SIZE", 1 if upper else 2 * n)
        sweep = physical.prepare(elimination, k_matrix, m_matrix, c_matrix)
        monkeypatch.setattr(physical, "LDL_MIN_SIZE", 1)
        assert sweep.symmetric and sweep.pencil.upper is upper and sweep.use_ldl
        calls = ldl_sweeps.calls
        with numba_route(numba):
            depl, info = physical.solve(sweep, frequencies, force, coefficients)
        assert info["ldl"] == 4 and info["superlu"] == 0 and info["mumps"] == 0
        assert (ldl_sweeps.calls > calls) is not numba
        solved.append((depl, info["fill"], info["refined"]))
    assert same_bits(solved[0][0], solved[1][0])
    assert solved[0][1:] == solved[1][1:]


def test_a_dyna_vibra_harm_phys_deck_gives_numbas_bits(numba_route, ldl_sweeps, monkeypatch,
                                                        tmp_path):  # fmt: skip
    """tests/test_harmonic.py's deck (viscous and hysteretic physical sweeps,
    the generalized ones beside them) with the LDLᵀ serving every size."""
    from tests.test_harmonic import DECK, MESH

    monkeypatch.setattr(physical, "LDL_MIN_SIZE", 1)
    (tmp_path / "d.mail").write_text(MESH)
    (tmp_path / "d.comm").write_text(DECK)
    export = tmp_path / "d.export"
    export.write_text("P time_limit 300\nF comm d.comm D 1\nF mail d.mail D 20\n")
    runs = []
    for numba in (True, False):
        calls = ldl_sweeps.calls
        with numba_route(numba):
            session = Session(describe_run(export), output_dir=tmp_path / f"out{numba}")
            session.run_all()
        assert (ldl_sweeps.calls > calls) is not numba
        runs.append(session)
    for name in ("VISC", "HYST"):
        fields = [run.namespace[name].fields for run in runs]
        assert fields[0].keys() == fields[1].keys() and "DEPL" in fields[0]
        for field in fields[0]:
            assert same_bits(fields[0][field], fields[1][field]), (name, field)
    values = [[record.value for record in run.tests] for run in runs]
    assert values[0] == values[1] and values[0]
