"""Large modal solves: MUMPS and CHOLMOD factors (asterlite.fem.sparse_direct)
and the block shift-invert Lanczos method (asterlite.modal.block_lanczos),
checked against dense LAPACK and against the SuperLU + ARPACK path on a
CALC_MODES deck. CHOLMOD (cholespy) is a core dependency; MUMPS comes with the
``large`` extra (python-mumps, built on Debian's libmumps-seq-dev): without it
the tests that need it skip, except in CI (``CI=true``), where .ci/run
installs it."""

from __future__ import annotations

import os
import re

import numpy as np
import pytest
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg  # noqa: F401  (sp.linalg)

from asterlite.fem import sparse_direct
from asterlite.modal import block_lanczos
from asterlite.runtime.runner import run_deck
from tests.solid_meshes import aster_mesh_text, box_mesh, with_side_faces


def _grid_pencil(nx: int, ny: int):
    """Stiffness and mass of a square membrane grid, fixed edges: a 2D
    Laplacian, whose eigenvalues on a square grid come in equal pairs."""
    lap_x = sp.diags([-1.0, 2.0, -1.0], [-1, 0, 1], shape=(nx, nx))
    lap_y = sp.diags([-1.0, 2.0, -1.0], [-1, 0, 1], shape=(ny, ny))
    k = sp.kron(lap_x, sp.eye(ny)) + sp.kron(sp.eye(nx), lap_y)
    rng = np.random.default_rng(3)
    m = sp.diags(1.0 + 0.0 * rng.random(nx * ny))
    return sp.csc_matrix(k), sp.csc_matrix(m)


def test_mumps_solves_blocks_and_counts_negative_pivots(needs_mumps):
    k, m = _grid_pencil(12, 12)
    dense = k.toarray()
    eigenvalues = np.linalg.eigvalsh(dense)
    assert eigenvalues[10] - eigenvalues[9] > 1e-3  # σ between two distinct values
    sigma = 0.5 * (eigenvalues[9] + eigenvalues[10])
    shifted = sp.csc_matrix(k - sigma * m)
    factor = sparse_direct.factorize_symmetric(shifted, backend="mumps")
    rhs = np.random.default_rng(0).standard_normal((k.shape[0], 5))
    x = factor.solve(rhs)
    np.testing.assert_allclose(shifted @ x, rhs, atol=1e-10)
    np.testing.assert_allclose(factor.solve(rhs[:, 0]), x[:, 0], atol=1e-12)
    # the inertia of K - σM: as many negative pivots as eigenvalues below σ
    assert factor.negative_pivots == int(np.sum(eigenvalues < sigma)) == 10


def test_closing_a_mumps_factor_leaves_the_last_solution_alone(needs_mumps):
    # python-mumps 0.0.4's Context.__exit__ repeats the last job (a solve into
    # the last right-hand side, which is the returned solution): close() must
    # not call it (it corrupted freed memory: forma12c crashed)
    k, _ = _grid_pencil(8, 8)
    factor = sparse_direct.factorize_symmetric(k, backend="mumps")
    x = factor.solve(np.ones((k.shape[0], 3)))
    kept = x.copy()
    factor.close()
    np.testing.assert_array_equal(x, kept)
    for _ in range(20):  # factors made and dropped in a loop stay sound
        other = sparse_direct.factorize_symmetric(k, backend="mumps")
        np.testing.assert_allclose(k @ other.solve(np.ones(k.shape[0])), 1.0, atol=1e-10)
        del other


@pytest.mark.parametrize("layout", ["csr", "csc", "coo"])
def test_mumps_takes_any_layout_and_releases_its_input(layout, needs_mumps):
    # the upper triangle is made once from CSR or CSC; after the factorisation
    # MUMPS keeps only its factor (the solves read no input triplet)
    k, m = _grid_pencil(10, 10)
    shifted = (k - 0.3 * m).asformat(layout)
    factor = sparse_direct.factorize_symmetric(shifted, backend="mumps")
    assert factor._context.row is None and factor._context.data.size == 1
    rhs = np.random.default_rng(1).standard_normal((k.shape[0], 3))
    np.testing.assert_allclose(shifted @ factor.solve(rhs), rhs, atol=1e-10)
    assert not factor.out_of_core


def test_a_factor_past_the_memory_headroom_goes_out_of_core(needs_mumps, monkeypatch):
    # code_aster's GESTION_MEMOIRE='AUTO': the factor goes to disk when its
    # in-core estimate passes the share of what the run may still add; its
    # folder is removed with it
    k, _ = _grid_pencil(30, 30)
    in_core = sparse_direct.factorize_symmetric(k, backend="mumps")
    monkeypatch.setattr(sparse_direct.watchdog, "memory_headroom", lambda: 1024)
    factor = sparse_direct.factorize_symmetric(k, backend="mumps")
    assert factor.out_of_core
    folder = factor._folder
    assert os.path.isdir(folder) and os.listdir(folder)
    rhs = np.random.default_rng(2).standard_normal((k.shape[0], 4))
    np.testing.assert_allclose(factor.solve(rhs), in_core.solve(rhs), rtol=1e-9, atol=1e-12)
    factor.close()
    assert not os.path.exists(folder)


def test_a_singular_matrix_is_refused_by_name(needs_mumps):
    k, _ = _grid_pencil(5, 5)
    singular = sp.csc_matrix(sp.block_diag([k, sp.csc_matrix((2, 2))]))
    with pytest.raises(sparse_direct.SingularFactorError, match="MUMPS"):
        sparse_direct.factorize_symmetric(singular, backend="mumps")


@pytest.mark.parametrize("sigma_index", [None, 30])
def test_block_lanczos_matches_lapack_with_double_eigenvalues(sigma_index, needs_mumps):
    k, m = _grid_pencil(20, 20)
    reference = sla.eigh(k.toarray(), m.toarray(), eigvals_only=True)
    sigma = 0.0
    if sigma_index is not None:  # inside the spectrum, midway in a gap (not at a double value)
        gap = sigma_index + int(np.argmax(np.diff(reference[sigma_index:]) > 1e-3))
        sigma = 0.5 * (reference[gap] + reference[gap + 1])
    factor = sparse_direct.factorize_symmetric(sp.csc_matrix(k - sigma * m), backend="mumps")
    count = 24
    values, vectors, stats = block_lanczos.shift_invert_lanczos(m, factor.solve, sigma, count)
    # the count nearest σ: eigenvalues of the pencil whose distances to σ are
    # the count smallest (which of values tied at the last distance is taken
    # depends on round-off: on this grid three lie at 0.3131069 from σ = 1.045)
    distances = np.sort(np.abs(reference - sigma))[:count]
    np.testing.assert_allclose(np.sort(np.abs(values - sigma)), distances, rtol=1e-10)
    nearest_reference = reference[np.abs(reference[:, None] - values).argmin(axis=0)]
    np.testing.assert_allclose(values, nearest_reference, rtol=1e-11)
    # M-orthonormal eigenvectors with small residuals
    np.testing.assert_allclose(vectors.T @ (m @ vectors), np.eye(count), atol=1e-9)
    residual = k @ vectors - (m @ vectors) * values
    assert np.linalg.norm(residual, axis=0).max() < 1e-8 * np.abs(values).max()
    assert stats["block"] >= 2 and stats["solves"] >= count


def _clustered_pencil(n: int, rng):
    """Dense K and M (SPD) whose eigenvalues come in tight clusters (1e-9
    apart) and one multiple value, with the exact eigenvalues."""
    clusters = [1.0 + 1e-9 * k for k in range(6)] + [3.0] * 4 + [5.0 + 1e-7 * k for k in range(8)]
    spread = np.sort(rng.uniform(6.0, 400.0, n - len(clusters)))
    values = np.concatenate([clusters, spread])
    b = rng.standard_normal((n, n))
    m = b @ b.T / n + np.eye(n)
    q, _ = np.linalg.qr(rng.standard_normal((n, n)))
    modes = np.linalg.solve(np.linalg.cholesky(m).T, q)  # Φᵀ M Φ = I
    mphi = m @ modes
    return (mphi * values) @ mphi.T, m, values


class _CountingMass:
    """A mass matrix that counts its products with blocks of vectors."""

    def __init__(self, m):
        self.m, self.shape, self.products = m, m.shape, 0

    def __matmul__(self, x):
        self.products += 1
        return self.m @ x


def test_block_lanczos_keeps_its_basis_orthogonal_on_clustered_eigenvalues():
    """Many small blocks (over 30 steps of 4) on clusters 1e-9 apart: with the
    first pass against the last two blocks only and one classical
    Gram-Schmidt pass against the whole basis (M w recomputed in between),
    the modes stay M-orthonormal to round-off, with exact eigenvalues; M is
    applied twice per block (and twice for the start)."""
    rng = np.random.default_rng(5)
    k, m, exact = _clustered_pencil(300, rng)
    lu = sla.lu_factor(k)
    mass = _CountingMass(m)
    count = 40
    values, vectors, stats = block_lanczos.shift_invert_lanczos(
        mass, lambda b: sla.lu_solve(lu, b), 0.0, count, block=4
    )
    assert stats["steps"] >= 30
    assert mass.products == 2 + 2 * stats["steps"]
    np.testing.assert_allclose(np.sort(values), np.sort(exact)[:count], rtol=1e-12)
    assert np.abs(vectors.T @ m @ vectors - np.eye(count)).max() < 1e-12
    residual = k @ vectors - (m @ vectors) * values
    assert (np.linalg.norm(residual, axis=0) / np.linalg.norm(k @ vectors, axis=0)).max() < 1e-10


def test_block_lanczos_fills_an_exhausted_krylov_space():
    """Three distinct eigenvalues: a block of 4 spans a Krylov space of 12
    vectors at most, then loses rank; random directions M-orthogonal to the
    basis replace the lost ones, and the pairs found stay exact and
    orthonormal. (Beyond the block size, a multiplicity is found only as far
    as those directions reach: CALC_MODES's Sturm count tells the rest.)"""
    n = 39
    k = sp.diags(np.repeat([1.0, 2.0, 4.0], 13))
    m = sp.identity(n, format="csr")
    count = 14
    values, vectors, stats = block_lanczos.shift_invert_lanczos(
        m, lambda b: sp.linalg.spsolve(sp.csc_matrix(k), b), 0.0, count, block=4
    )
    assert stats["dimension"] > 12
    assert np.abs(values - np.round(values)).max() < 1e-12 and set(np.round(values)) <= {1, 2, 4}
    assert np.abs(vectors.T @ vectors - np.eye(count)).max() < 1e-12
    assert np.abs(k @ vectors - vectors * values).max() < 1e-12


BAR_DECK = """DEBUT()
mesh = LIRE_MAILLAGE(FORMAT="ASTER", UNITE=20)
model = AFFE_MODELE(MAILLAGE=mesh, AFFE=_F(TOUT="OUI", PHENOMENE="MECANIQUE", MODELISATION="3D"))
steel = DEFI_MATERIAU(ELAS=_F(E=2.1e11, NU=0.3, RHO=7800.0))
chmat = AFFE_MATERIAU(MAILLAGE=mesh, AFFE=_F(TOUT="OUI", MATER=steel))
clamp = AFFE_CHAR_MECA(MODELE=model, DDL_IMPO=_F(GROUP_MA="CLAMP", DX=0.0, DY=0.0, DZ=0.0))
ASSEMBLAGE(MODELE=model, CHAM_MATER=chmat, CHARGE=clamp, NUME_DDL=CO("nume"),
           MATR_ASSE=(_F(MATRICE=CO("rigi"), OPTION="RIGI_MECA"),
                      _F(MATRICE=CO("mass"), OPTION="MASS_MECA")))
low = CALC_MODES(MATR_RIGI=rigi, MATR_MASS=mass, OPTION="PLUS_PETITE",
                 CALC_FREQ=_F(NMAX_FREQ=20))
centre = CALC_MODES(MATR_RIGI=rigi, MATR_MASS=mass, OPTION="CENTRE",
                    CALC_FREQ=_F(FREQ=900.0, NMAX_FREQ=6))
band = CALC_MODES(MATR_RIGI=rigi, MATR_MASS=mass, OPTION="BANDE",
                  CALC_FREQ=_F(FREQ=(300.0, 1500.0)))
FIN()
"""


def _bar_frequencies(folder, solver, monkeypatch):
    folder.mkdir()
    mesh = with_side_faces(box_mesh("HEXA8", (12, 3, 3), (10.0, 1.0, 1.0)), {"CLAMP": (0, 0.0)})
    (folder / "bar.mail").write_text(aster_mesh_text(mesh))
    (folder / "bar.comm").write_text(BAR_DECK)
    (folder / "bar.export").write_text("F comm bar.comm D 1\nF mail bar.mail D 20\n")
    monkeypatch.setenv("ASTERLITE_SPARSE_SOLVER", solver)
    report = run_deck(folder / "bar.export", folder / "out")
    assert report.status == "DONE", report.message
    log = (folder / "out" / "message.log").read_text()
    blocks = re.split(r"\nCALC_MODES", log)[1:]
    modes = [
        np.array([float(f) for f in re.findall(r"mode +\d+ +(\S+) Hz", block)]) for block in blocks
    ]
    return modes, log


def test_calc_modes_on_mumps_equals_superlu_and_arpack(tmp_path, monkeypatch, needs_mumps):
    large, log = _bar_frequencies(tmp_path / "mumps", "mumps", monkeypatch)
    small, old_log = _bar_frequencies(tmp_path / "superlu", "superlu", monkeypatch)
    assert log.count("block Lanczos on a MUMPS factorisation") == 3
    assert "MUMPS" not in old_log
    assert [len(f) for f in large] == [20, 6, len(small[2])] and len(small[2]) > 6
    for new, old in zip(large, small, strict=True):
        np.testing.assert_allclose(new, old, rtol=1e-9)


def test_arpack_takes_over_when_the_lanczos_basis_reaches_its_bound(monkeypatch, needs_mumps):
    from asterlite.modal import eigen

    k, m = _grid_pencil(20, 20)
    reference = sla.eigh(k.toarray(), m.toarray(), eigvals_only=True)[:12]
    real_lanczos = block_lanczos.shift_invert_lanczos

    def bounded(*args, **kwargs):
        return real_lanczos(*args, **{**kwargs, "max_dim": 16})

    monkeypatch.setattr(block_lanczos, "shift_invert_lanczos", bounded)
    values, vectors, how = eigen._large_shift_invert(k, m, 0.0, 12)
    assert how["method"] == "ARPACK" and how["backend"] == "mumps"
    np.testing.assert_allclose(np.sort(values), reference, rtol=1e-11)


# --- CHOLMOD (cholespy): the path without the large extra -------------------


def test_cholmod_solves_blocks_and_refuses_an_indefinite_matrix_quietly(capfd):
    k, m = _grid_pencil(12, 12)
    factor = sparse_direct.factorize_symmetric(k, backend="cholmod")
    assert factor.backend == "cholmod" and factor.negative_pivots == 0
    rhs = np.random.default_rng(1).standard_normal((k.shape[0], 5))
    x = factor.solve(np.asfortranarray(rhs))  # the Lanczos blocks are Fortran-ordered
    np.testing.assert_allclose(k @ x, rhs, atol=1e-10)
    np.testing.assert_allclose(factor.solve(rhs[:, 2]), x[:, 2], atol=1e-12)
    assert not factor.nearly_singular(k)
    sigma = 0.5 * sum(np.linalg.eigvalsh(k.toarray())[9:11])
    with pytest.raises(sparse_direct.NotPositiveDefiniteError, match="CHOLMOD"):
        sparse_direct.factorize_symmetric(sp.csc_matrix(k - sigma * m), backend="cholmod")
    shown = capfd.readouterr()
    assert "CHOLMOD" not in shown.out + shown.err  # its C warning is not shown


def _free_chain(n: int, seed: int | None = None):
    """A free-free chain of springs and unit masses: K is singular (the rigid
    translation). Unit springs (seed None) make CHOLMOD meet an exactly zero
    pivot; random ones leave a round-off pivot that it accepts."""
    springs = np.ones(n - 1) if seed is None else np.random.default_rng(seed).uniform(0.5, 2, n - 1)
    diagonal = np.zeros(n)
    diagonal[:-1] += springs
    diagonal[1:] += springs
    k = sp.diags([-springs, diagonal, -springs], [-1, 0, 1], format="csc")
    return k, sp.identity(n, format="csc")


@pytest.mark.parametrize("seed", [None, 5])
def test_cholmod_steps_below_the_rigid_body_mode_of_a_free_structure(seed):
    from asterlite.modal import eigen

    k, m = _free_chain(600, seed)
    if seed is None:
        with pytest.raises(sparse_direct.NotPositiveDefiniteError):
            sparse_direct.factorize_symmetric(k, backend="cholmod")
    else:  # factorised, but a solve shows the null space
        assert sparse_direct.factorize_symmetric(k, backend="cholmod").nearly_singular(k)
    exact = sla.eigh(k.toarray(), eigvals_only=True)[:12]
    sigma, factor = eigen._large_smallest_shift(k, m, "cholmod")
    assert sigma < 0.0 and factor.backend == "cholmod"  # K (singular) was not kept
    values, _, how = eigen._large_shift_invert(k, m, sigma, 12, factor)
    assert how["backend"] == "cholmod" and how["method"] == "block Lanczos"
    values = np.sort(values)
    np.testing.assert_allclose(values[1:], exact[1:], rtol=1e-9)
    assert abs(values[0]) < 1e-9
    # clamped at one end, K itself is factorised (σ = 0)
    sigma, factor = eigen._large_smallest_shift(
        sp.csc_matrix(k[1:, 1:]), sp.csc_matrix(m[1:, 1:]), "cholmod"
    )
    assert sigma == 0.0
    factor.close()


@pytest.mark.parametrize(
    ("requested", "mumps", "n", "definite", "expected"),
    [
        ("auto", True, 3999, True, "superlu"),  # below LARGE_LIMIT: the code of before
        ("auto", False, 3999, True, "superlu"),
        ("auto", True, 4000, False, "mumps"),
        ("auto", False, 4000, True, "cholmod"),
        ("auto", False, 4000, False, "superlu"),  # indefinite without MUMPS
        ("cholmod", True, 500, True, "cholmod"),
        ("cholmod", True, 500, False, "superlu"),
        ("mumps", False, 500, True, "cholmod"),
        ("superlu", True, 10**5, True, "superlu"),
    ],
)
def test_backend_choice(monkeypatch, requested, mumps, n, definite, expected):
    monkeypatch.setenv("ASTERLITE_SPARSE_SOLVER", requested)
    monkeypatch.setattr(sparse_direct, "mumps_available", lambda: mumps)
    assert sparse_direct.choose_backend(n, definite=definite) == expected


def test_calc_modes_on_cholmod_equals_superlu_and_arpack(tmp_path, monkeypatch):
    monkeypatch.setattr(sparse_direct, "mumps_available", lambda: False)
    large, log = _bar_frequencies(tmp_path / "cholmod", "cholmod", monkeypatch)
    small, old_log = _bar_frequencies(tmp_path / "superlu", "superlu", monkeypatch)
    # PLUS_PETITE on CHOLMOD; CENTRE and BANDE shift inside the spectrum,
    # where K - σM is indefinite: their modes come from the lowest up on
    # CHOLMOD's factor of K
    assert log.count("block Lanczos on a CHOLMOD factorisation") == 1
    assert log.count("lowest modes) on a CHOLMOD factorisation") == 2
    assert "CHOLMOD" not in old_log
    assert [len(f) for f in large] == [len(f) for f in small] == [20, 6, len(small[2])]
    for new, old in zip(large, small, strict=True):
        np.testing.assert_allclose(new, old, rtol=1e-9)


def test_sturm_count_of_a_large_model_reads_the_inertia_of_its_factor(needs_mumps, monkeypatch):
    from asterlite.fem.constraints import eliminate
    from asterlite.modal.eigen import ReducedPencil

    nx = ny = 64  # 4 096 unknowns: from LARGE_LIMIT on, no SuperLU factor
    k, m = _grid_pencil(nx, ny)
    one_d = 2.0 - 2.0 * np.cos(np.arange(1, nx + 1) * np.pi / (nx + 1))
    exact = np.sort(np.add.outer(one_d, one_d).ravel())
    n = k.shape[0]
    pencil = ReducedPencil(k, m, eliminate(sp.csr_matrix((0, n)), np.zeros(0), n))
    assert pencil.n >= sparse_direct.LARGE_LIMIT

    def no_superlu(*args, **kwargs):
        raise AssertionError("SuperLU factorised a large model")

    monkeypatch.setattr("scipy.sparse.linalg.splu", no_superlu)
    gaps = np.flatnonzero(np.diff(exact[:300]) > 1e-6)  # between distinct values
    for index in (gaps[0], gaps[len(gaps) // 2], gaps[-1]):
        sigma = 0.5 * (exact[index] + exact[index + 1])
        assert pencil.count_below(sigma) == index + 1
    assert pencil.count_below(-1.0) == 0
    monkeypatch.setattr(sparse_direct, "mumps_available", lambda: False)
    assert pencil.count_below(-1.0) == 0  # CHOLMOD: positive definite below the spectrum


def test_modes_nearest_a_positive_shift_without_mumps_come_from_the_lowest_up(monkeypatch):
    from asterlite.fem.constraints import eliminate
    from asterlite.modal import eigen

    nx = ny = 24  # 576 unknowns, taken as large (above the dense solver's limit)
    k, m = _grid_pencil(nx, ny)
    one_d = 2.0 - 2.0 * np.cos(np.arange(1, nx + 1) * np.pi / (nx + 1))
    exact = np.sort(np.add.outer(one_d, one_d).ravel())
    n = k.shape[0]
    monkeypatch.setattr(sparse_direct, "LARGE_LIMIT", 500)
    monkeypatch.setattr(sparse_direct, "mumps_available", lambda: False)
    calls = []
    real_splu = eigen.spla.splu
    monkeypatch.setattr(eigen.spla, "splu", lambda *a, **kw: calls.append(1) or real_splu(*a, **kw))

    def pencil():
        return eigen.ReducedPencil(k, m, eliminate(sp.csr_matrix((0, n)), np.zeros(0), n))

    sigma = 0.5 * (exact[30] + exact[31])
    nearest = exact[np.argsort(np.abs(exact - sigma), kind="stable")[:6]]
    solved = pencil()
    values, vectors = solved.nearest(sigma, 6)
    np.testing.assert_allclose(np.sort(values), np.sort(nearest), rtol=1e-10)
    residual = k @ vectors - (m @ vectors) * values
    assert np.linalg.norm(residual, axis=0).max() < 1e-8
    assert solved.last_solve["backend"] == "cholmod" and not calls
    assert "lowest modes" in solved.last_solve["method"]
    # a band: every mode inside, K factorised once for all its growing counts
    gaps = np.flatnonzero(np.diff(exact[:100]) > 1e-6)  # between distinct values
    first, last = gaps[gaps >= 20][0] + 1, gaps[gaps >= 40][0]
    low, high = 0.5 * (exact[first - 1] + exact[first]), 0.5 * (exact[last] + exact[last + 1])
    values, _ = solved.band(low, high)
    np.testing.assert_allclose(np.sort(values), exact[first : last + 1], rtol=1e-10)
    assert not calls
    # more modes below the shift than BOTTOM_UP_LIMIT: SuperLU and ARPACK, as before
    monkeypatch.setattr(eigen, "BOTTOM_UP_LIMIT", 16)
    values, _ = pencil().nearest(sigma, 6)
    np.testing.assert_allclose(np.sort(values), np.sort(nearest), rtol=1e-10)
    assert calls


def test_mumps_factors_of_one_matrix_solve_to_the_same_bits(needs_mumps):
    """MUMPS's ordering draws no random numbers (PORD; Debian's SCOTCH, its
    "auto" choice, does): a deck's modes are the same from run to run."""
    from tests.test_harmonic_ordering import _grid_laplacian

    stiffness = _grid_laplacian(18)
    rhs = np.random.default_rng(0).standard_normal(stiffness.shape[0])
    first, *others = [sparse_direct.MumpsFactor(stiffness).solve(rhs) for _ in range(3)]
    for other in others:
        np.testing.assert_array_equal(other, first)
