"""The basis code_aster's METHODE='JACOBI' returns inside a multiple eigenvalue.

Inside a group of equal eigenvalues any M-orthonormal basis of the eigenspace
is an answer; which one a solver returns is an accident of its algorithm. A
transient on those modes does not care, unless it mixes them non-linearly
(a fluid film's diagonal added mass, a fixed point stopped at a tolerance):
then the basis shows in the results, and decks expect code_aster's.

code_aster's JACOBI is Bathe and Wilson's subspace iteration (sspace, from
code_aster 10 to today). Its start vectors are right-hand sides of the first
solve with the shifted stiffness K - σM: first the diagonal of M, then unit
vectors at the active DOFs ordered by increasing (K_ii - σM_ii) / M_ii
(sstriv), blocked DOFs left out. Iterating (K - σM)⁻¹M multiplies every
component of an eigenspace by the same factor, so inside an eigenspace E the
iterates keep the part of each start vector s there, Φ_E Φ_Eᵀ s (Φ_E an
M-orthonormal basis of E). Taken in order and M-orthogonalised, those parts
are the basis returned here; the Jacobi rotations of the projected pencil,
which cannot tell equal Ritz values apart, are taken to leave it alone.

The last start vector of sspace is pseudo-random (ggubs); it only matters
for an eigenspace the others do not span, where the solver's own vectors
complete the basis instead.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from asterlite.modal.eigen import omega2_from_freq

# Eigenvalues (ω²) closer than this, relatively, form one eigenspace: far
# above the round-off that separates an exact multiplicity in the solvers
# (about 1e-13 relatively, more for the highest modes of stiff models), far
# below the gap of distinct physical modes (5e-9 in frequency). Between this
# and code_aster's own resolution (its subspace iteration stops once the
# eigenvalues settle to PREC_BATHE, 1e-10) the two bases may differ.
EQUAL_RTOL = 1e-8
# a start vector whose part in the eigenspace is below this fraction of what
# it could be adds no direction (it is orthogonal to the eigenspace)
INDEPENDENT_RTOL = 1e-8


def code_aster_shift(option: str, freq=()) -> float:
    """The shift σ (ω² units) code_aster factorises K - σM at (vpfopr): the
    centre frequency for CENTRE, the middle of the band in ω² for BANDE, 0
    for PLUS_PETITE, TOUT and PLUS_GRANDE."""
    freq = np.atleast_1d(np.asarray(freq if freq is not None else (), dtype=float))
    if option == "CENTRE" and freq.size:
        return float(omega2_from_freq(freq[0]))
    if option == "BANDE" and freq.size >= 2:
        return float(np.mean(omega2_from_freq([freq.min(), freq.max()])))
    return 0.0


def unit_load_order(k_diag: np.ndarray, m_diag: np.ndarray, shift: float) -> np.ndarray:
    """DOFs in sstriv's order: positive mass and shifted stiffness first, by
    increasing (K_ii - σM_ii)/M_ii; then the other DOFs with a mass; massless
    DOFs last. Ties keep the numbering's order (sstriv is a bubble sort)."""
    shifted = k_diag - shift * m_diag
    regular = (m_diag > 0) & (shifted > 0)
    ratio = np.where(regular, shifted / np.where(regular, m_diag, 1.0), 0.0)
    rank = np.where(regular, 0, np.where(m_diag != 0, 1, 2))
    return np.lexsort((np.arange(len(ratio)), ratio, rank))


def equal_groups(omega2: np.ndarray, floor: float) -> list[np.ndarray]:
    """Index arrays (two or more, by increasing ω²) of the eigenvalues equal
    within EQUAL_RTOL, ``floor`` the absolute tolerance near ω² = 0."""
    order = np.argsort(omega2, kind="stable")
    values = np.asarray(omega2, dtype=float)[order]
    gaps = np.abs(np.diff(values))
    scale = np.maximum(np.abs(values[1:]), np.abs(values[:-1]))
    same = gaps <= EQUAL_RTOL * scale + floor
    groups, start = [], 0
    for i in range(1, len(values) + 1):
        if i == len(values) or not same[i - 1]:
            if i - start > 1:
                groups.append(order[start:i])
            start = i
    return groups


def _start_coefficients(full_shapes: np.ndarray, first_load: np.ndarray, order: np.ndarray):
    """Rows: Φ_Eᵀ s for each start vector s, in sspace's order (a unit load's
    row is the shapes' row at its DOF), with the largest size each could have."""
    first = full_shapes.T @ first_load
    bound = np.linalg.norm(full_shapes)
    coefficients = np.vstack([first[None, :], full_shapes[order]])
    scales = np.concatenate([[bound * np.linalg.norm(first_load)], np.full(len(order), bound)])
    return coefficients, scales


def _orthonormal_in_order(rows: np.ndarray, scales: np.ndarray, size: int) -> np.ndarray:
    """Gram-Schmidt over the rows, in order, skipping dependent ones, completed
    by the unit axes (the solver's own vectors) if they do not span: (size, size)."""
    basis: list[np.ndarray] = []
    candidates = [(r, s) for r, s in zip(rows, scales, strict=True)]
    candidates += [(axis, 1.0) for axis in np.eye(size)]
    for row, scale in candidates:
        residual = row.copy()
        for _ in range(2):  # twice is enough against cancellation
            for q in basis:
                residual -= (q @ residual) * q
        norm = np.linalg.norm(residual)
        if norm > INDEPENDENT_RTOL * scale:
            basis.append(residual / norm)
            if len(basis) == size:
                break
    return np.array(basis)


def rebase_group(shapes: np.ndarray, mass: np.ndarray, expand, first_load, order) -> np.ndarray:
    """The group's shapes (reduced, n × d) replaced by the parts of the start
    vectors in their span, M-orthonormal, in start order."""
    gram = shapes.T @ (mass @ shapes)
    chol = np.linalg.cholesky(0.5 * (gram + gram.T))
    orthonormal = np.linalg.solve(chol, shapes.T).T  # Φ_E with Φ_Eᵀ M Φ_E = I
    full = np.asarray(expand(orthonormal))
    rows, scales = _start_coefficients(full, first_load, order)
    rotation = _orthonormal_in_order(rows, scales, shapes.shape[1])
    return orthonormal @ rotation.T


def jacobi_basis_rule(
    pencil, option: str, freq=()
) -> Callable[[np.ndarray, np.ndarray], np.ndarray]:
    """A rule (ω², reduced shapes) -> shapes giving every group of equal
    eigenvalues of ``pencil`` (a ReducedPencil) code_aster's JACOBI basis.
    Start loads live on the full numbering: the pencil's ``expand`` gives
    blocked DOFs 0, so their loads drop out as sspace leaves them out.
    PLUS_GRANDE solves M φ = (1/ω²) K φ: the two matrices swap roles."""
    k_diag, m_diag = (np.asarray(d, dtype=float) for d in pencil.full_diagonals)
    floor = EQUAL_RTOL * _rigid_scale(k_diag, m_diag)
    if option == "PLUS_GRANDE":
        k_diag, m_diag = m_diag, k_diag
    order = unit_load_order(k_diag, m_diag, code_aster_shift(option, freq))

    def rule(omega2: np.ndarray, shapes: np.ndarray) -> np.ndarray:
        shapes = np.array(shapes, dtype=float, copy=True)
        for group in equal_groups(omega2, floor):
            shapes[:, group] = rebase_group(
                shapes[:, group], pencil.m, pencil.expand, m_diag, order
            )
        return shapes

    return rule


def _rigid_scale(k_diag: np.ndarray, m_diag: np.ndarray) -> float:
    """The size of the solvers' shift below rigid-body modes (1e-4 times the
    median K_ii/M_ii): round-off leaves a zero ω² about ε times this from 0."""
    ok = (k_diag > 0) & (m_diag > 0)
    return 1e-4 * float(np.median(k_diag[ok] / m_diag[ok])) if np.any(ok) else 0.0
