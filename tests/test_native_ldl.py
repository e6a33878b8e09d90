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
from tests.numba_reference import assert_same, fingerprint, reference

# numba's side is its stored fingerprints (tests.numba_reference)
pytestmark = pytest.mark.usefixtures("needs_native", "needs_ldl")

I32, I64 = np.int32, np.int64


@pytest.fixture()
def needs_ldl():
    """The C++ module built (needs_native checks the time loops')."""
    if ldl._ldl is not None:
        return
    if os.environ.get("CI", "").lower() == "true":
        pytest.fail("CI: asterlite.dynamics.native._ldl is not built")
    pytest.skip("asterlite.dynamics.native._ldl is not built")


def exact(value):
    """``value`` (arrays in dicts, lists, tuples) for a fingerprint to the
    bit, NaNs aside: a float or complex array as its float parts (each NaN
    part alike, the other part of a complex NaN kept) and the signs of those
    that are not NaN (a fingerprint takes -0.0 for 0.0). Which of two NaNs
    an addition or product passes on is the compiler's choice of operand
    order (LLVM's and GCC's differ); IEEE 754 leaves it open."""
    if isinstance(value, dict):
        return {key: exact(item) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [exact(item) for item in value]
    if not isinstance(value, np.ndarray) or value.dtype.kind not in "fc":
        return value
    array = np.ascontiguousarray(value)
    parts = np.atleast_1d(array).view(array.real.dtype)
    return {
        "dtype": array.dtype.str,
        "shape": list(array.shape),
        "parts": parts,
        "signs": np.signbit(parts) & ~np.isnan(parts),
    }


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


def analysed(caller, perm, upper, limit=None):
    """ldl.analyse of ``caller``'s pattern (on the route of the caller's
    numba_route, if any)."""
    return ldl.analyse(caller.indptr, caller.indices, caller.shape[0], perm, limit, upper=upper)


ANALYSIS = ("perm", "upper_ptr", "upper_idx", "source", "parent", "lp", "n")


def analysis_fields(analysis) -> dict:
    return {field: getattr(analysis, field) for field in ANALYSIS}


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
def test_analysis_factor_and_solve_give_numbas_bits(request, numba_route, kind, n, order, upper):
    rng = np.random.default_rng([n, len(kind), len(order), upper])
    a = values_on(pattern(kind, n, rng), rng)
    perm = permutation(order, n, rng)
    caller = sp.csc_matrix(sp.triu(a)) if upper else a
    rhs = rng.standard_normal(n) + 1j * rng.standard_normal(n)

    def outcome(compiled: bool) -> dict:
        """The analysis, then the factor and the solution, or the zero pivot."""
        with numba_route(not compiled):
            analysis = analysed(caller, perm, upper)
            found = analysis_fields(analysis)
            try:
                factor = ldl.factorise(analysis, caller.data)
            except ldl.ZeroPivot as pivot:
                return {**found, "pivot": pivot.args}
            return {
                **found,
                "li": factor.li,
                "lx": factor.lx,
                "d": factor.d,
                "x": factor.solve(rhs),
            }

    compiled = outcome(True)
    numba = reference(request, lambda: exact(outcome(False)))
    assert_same(exact(compiled), numba, "the analysis, factor and solve")
    assert compiled["upper_ptr"].dtype == np.int32  # ldl.analyse's own index type here
    if "pivot" in compiled:
        assert kind == "holes"
        return
    x = compiled["x"]
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


def kernel_inputs(a, perm, mix, rng) -> dict:
    """The kernels' arguments, with the index types ``mix``, and a right-hand side."""
    pointers, lps, parents, rows = mix
    analysis = ldl.analyse(a.indptr, a.indices, a.shape[0], perm)
    n = analysis.n
    return {
        "n": n,
        "fill": analysis.fill,
        "ap": analysis.upper_ptr.astype(pointers),
        "ai": analysis.upper_idx.astype(pointers),
        "values": np.ascontiguousarray(a.data[analysis.source]),
        "rhs": rng.standard_normal(n) + 1j * rng.standard_normal(n),
        "mix": mix,
    }


def direct_kernels(inputs, compiled: bool) -> dict:
    """The three kernels called directly (the C++ ones, else numba's) on
    ``inputs`` (:func:`kernel_inputs`): their returns (and the types of the
    integers) and every array they write."""
    if compiled:
        symbolic, numeric, solve = ldl._ldl.symbolic, ldl._ldl.numeric, ldl._ldl.solve
    else:
        symbolic, numeric, solve = ldl._symbolic, ldl._numeric, ldl._solve
    n, fill, ap, ai, values = (inputs[name] for name in ("n", "fill", "ap", "ai", "values"))
    _, lps, parents, rows = inputs["mix"]
    parent, lnz, total = symbolic(n, ap, ai, np.iinfo(np.int64).max)
    assert parent.dtype == lnz.dtype == np.int64 and isinstance(total, int)
    lp = np.zeros(n + 1, dtype=lps)
    np.cumsum(lnz, out=lp[1:])
    li = np.zeros(fill, rows)
    lx = np.zeros(fill, np.complex128)
    d = np.zeros(n, np.complex128)
    status = numeric(n, ap, ai, values, lp, parent.astype(parents), li, lx, d)
    x = inputs["rhs"].copy()
    if status < 0:
        assert solve(n, lp, li, lx, d, x) is None
    return {
        "parent": parent, "lnz": lnz, "total": total, "total_type": type(total),
        "status": status, "status_type": type(status), "li": li, "lx": lx, "d": d, "x": x,
    }  # fmt: skip


@pytest.mark.parametrize("mix", MIXES, ids=lambda m: "-".join(t.__name__[3:] for t in m))
@pytest.mark.parametrize(("kind", "n"), [("random", 150), ("grid", 100), ("holes", 40)])
def test_the_kernels_on_every_mix_of_index_types(request, kind, n, mix):
    rng = np.random.default_rng([n, len(kind)])
    a = values_on(pattern(kind, n, rng), rng)
    inputs = kernel_inputs(a, rng.permutation(n), mix, rng)
    compiled = direct_kernels(inputs, True)
    numba = reference(request, lambda: exact(direct_kernels(inputs, False)))
    assert_same(exact(compiled), numba, "the kernels")
    assert compiled["status"] == -1 or kind == "holes"


@pytest.mark.parametrize("upper", [False, True], ids=["full", "upper"])
@pytest.mark.parametrize("share", [0.0, 0.3, 0.7, 0.95])
def test_a_fill_limit_stops_the_analysis_where_numbas_does(request, numba_route, share, upper):
    rng = np.random.default_rng(7)
    n = 300
    a = values_on(pattern("random", n, rng), rng)
    perm = rng.permutation(n)
    caller = sp.csc_matrix(sp.triu(a)) if upper else a
    with numba_route(False):
        whole = analysed(caller, perm, upper)
        row_counts = np.bincount(ldl.factorise(whole, caller.data).li, minlength=n)
    limit = int(share * whole.fill)
    # each column k adds L's row k: the analysis stops at the first column
    # whose predecessors exceed the limit
    reached = int(np.searchsorted(np.cumsum(row_counts), limit, side="right")) + 1
    assert reached < n
    # a limit at the fill keeps the analysis; so does one that only the
    # last column's terms exceed (the fill is compared before each column)
    kept_limits = (whole.fill, whole.fill - int(row_counts[-1]))

    def outcome(compiled: bool) -> dict:
        """The analyses without and with the limits, and the symbolic kernel
        under the limit: its total, its counts, its tree on the columns
        reached (numba's parent is np.empty past them)."""
        with numba_route(not compiled):
            found = {
                "whole": analysis_fields(analysed(caller, perm, upper)),
                "limited": analysed(caller, perm, upper, limit),
                "kept": [analysis_fields(analysed(caller, perm, upper, k)) for k in kept_limits],
            }
        symbolic = ldl._ldl.symbolic if compiled else ldl._symbolic
        parent, lnz, total = symbolic(n, whole.upper_ptr, whole.upper_idx, limit)
        return {**found, "total": total, "lnz": lnz, "parent": parent[:reached]}

    compiled = outcome(True)
    numba = reference(request, lambda: exact(outcome(False)))
    assert_same(exact(compiled), numba, "the analyses and the symbolic kernel")
    assert compiled["limited"] is None
    assert compiled["total"] == -1 and compiled["lnz"].sum() > limit
    for kept in compiled["kept"]:
        assert fingerprint(exact(kept)) == fingerprint(exact(compiled["whole"]))


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
def test_a_zero_pivot_raises_zero_pivot_as_numbas_does(request, numba_route, column):
    rng = np.random.default_rng(column)
    n = 14
    a = factor_with_a_zero_pivot(n, column, rng)
    inputs = kernel_inputs(a, np.arange(n), (I32, I64, I64, I32), rng)

    def outcome(compiled: bool) -> dict:
        """The analysis, the zero pivot factorise raises, and the arrays the
        kernel writes up to it."""
        with numba_route(not compiled):
            analysis = analysed(a, np.arange(n), False)
            with pytest.raises(ldl.ZeroPivot) as pivot:
                ldl.factorise(analysis, a.data)
        kernels = direct_kernels(inputs, compiled)
        written = {name: kernels[name] for name in ("status", "li", "lx", "d")}
        return {**analysis_fields(analysis), "pivot": pivot.value.args, **written}

    compiled = outcome(True)
    numba = reference(request, lambda: exact(outcome(False)))
    assert_same(exact(compiled), numba, "the zero pivot")
    assert compiled["pivot"] == (column,) and compiled["status"] == column
    d = compiled["d"]
    assert d[column] == 0 and np.all(d[:column] != 0)


def test_a_zero_of_d_in_solve_raises_zero_division_as_numbas_does(request):
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

    def after(solve) -> np.ndarray:
        x = b.copy()
        with pytest.raises(ZeroDivisionError, match="complex division by zero"):
            solve(n, analysis.lp, factor.li, factor.lx, d, x)
        return x

    compiled = after(ldl._ldl.solve)
    numba = reference(request, lambda: exact(after(ldl._solve)))
    assert_same(exact(compiled), numba, "x solved up to the zero")
    assert not np.array_equal(compiled, b)


def test_infinities_and_nans_give_numbas_values(request):
    """Non-finite values in the matrix: the same bits but NaNs' signs (see
    exact)."""
    rng = np.random.default_rng(11)
    n = 40
    a = values_on(pattern("random", n, rng), rng)
    a.data[3] = complex(np.inf, 1.0)
    a.data[11] = complex(np.nan, 0.0)
    a.data[20] = complex(1.0, -np.inf)
    analysis = ldl.analyse(a.indptr, a.indices, n, np.arange(n))
    values = np.ascontiguousarray(a.data[analysis.source])

    def outcome(numeric) -> dict:
        li = np.zeros(analysis.fill, np.int32)
        lx = np.zeros(analysis.fill, complex)
        d = np.zeros(n, complex)
        status = numeric(n, analysis.upper_ptr, analysis.upper_idx, values, analysis.lp,
                         analysis.parent, li, lx, d)  # fmt: skip
        return {"status": status, "li": li, "lx": lx, "d": d}

    compiled = outcome(ldl._ldl.numeric)
    numba = reference(request, lambda: exact(outcome(ldl._numeric)))
    assert_same(exact(compiled), numba, "the factor")
    assert np.isnan(compiled["lx"]).any() and np.isnan(compiled["d"]).any()


SPECIAL = [0.0, -0.0, 1.0, -3.0, 0.25, np.inf, -np.inf, np.nan, 2.5e300, 1e-300]


def test_special_values_divide_and_multiply_as_numbas_do(request):
    """Every pair of complex numbers made of zeros of either sign, infinities,
    NaN, huge and tiny values: quotients (x / d in _solve, both branches of
    Smith's algorithm and its NaN one; ZeroDivisionError at the same pairs)
    and products (x[i] -= lx * x[j])."""
    numbers = [complex(r, i) for r in SPECIAL for i in SPECIAL]
    pairs = [(a, b) for a in numbers for b in numbers]
    empty = (np.zeros(0, np.int64), np.zeros(0, complex))

    def outcome(solve) -> dict:
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
        return {"quotients": quotients, "products": products, "zero": zero}

    compiled = outcome(ldl._ldl.solve)
    numba = reference(request, lambda: exact(outcome(ldl._solve)))
    assert_same(exact(compiled), numba, "the quotients and products")
    q, p = compiled["quotients"], compiled["products"]
    assert len(compiled["zero"]) == 4 * len(numbers)  # by +-0 +-0j
    assert np.isnan(q).any() and np.isinf(q).any() and np.isinf(p).any()


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
def test_physical_sweeps_give_numbas_bits(request, numba_route, ldl_sweeps, monkeypatch, upper):
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

    def outcome(compiled: bool) -> dict:
        monkeypatch.setattr(physical, "_KNOWN_ORDERINGS", [])
        monkeypatch.setattr(physical, "LDL_MIN_SIZE", 1 if upper else 2 * n)
        sweep = physical.prepare(elimination, k_matrix, m_matrix, c_matrix)
        monkeypatch.setattr(physical, "LDL_MIN_SIZE", 1)
        assert sweep.symmetric and sweep.pencil.upper is upper and sweep.use_ldl
        calls = ldl_sweeps.calls
        with numba_route(not compiled):
            depl, info = physical.solve(sweep, frequencies, force, coefficients)
        assert info["ldl"] == 4 and info["superlu"] == 0 and info["mumps"] == 0
        assert (ldl_sweeps.calls > calls) is compiled
        return {"depl": depl, "fill": info["fill"], "refined": info["refined"]}

    compiled = outcome(True)
    numba = reference(request, lambda: exact(outcome(False)))
    assert_same(exact(compiled), numba, "the sweep")


def test_a_dyna_vibra_harm_phys_deck_gives_numbas_bits(request, numba_route, ldl_sweeps,
                                                        monkeypatch, tmp_path):  # fmt: skip
    """tests/test_harmonic.py's deck (viscous and hysteretic physical sweeps,
    the generalized ones beside them) with the LDLᵀ serving every size."""
    from tests.test_harmonic import DECK, MESH

    monkeypatch.setattr(physical, "LDL_MIN_SIZE", 1)
    (tmp_path / "d.mail").write_text(MESH)
    (tmp_path / "d.comm").write_text(DECK)
    export = tmp_path / "d.export"
    export.write_text("P time_limit 300\nF comm d.comm D 1\nF mail d.mail D 20\n")

    def outcome(compiled: bool) -> dict:
        """The fields of VISC and HYST, and the deck's test values."""
        calls = ldl_sweeps.calls
        with numba_route(not compiled):
            session = Session(describe_run(export), output_dir=tmp_path / f"out{not compiled}")
            session.run_all()
        assert (ldl_sweeps.calls > calls) is compiled
        found = {name: dict(session.namespace[name].fields) for name in ("VISC", "HYST")}
        return {**found, "tests": [record.value for record in session.tests]}

    compiled = outcome(True)
    numba = reference(request, lambda: exact(outcome(False)))
    assert_same(exact(compiled), numba, "the deck's results")
    assert "DEPL" in compiled["VISC"] and "DEPL" in compiled["HYST"] and compiled["tests"]
