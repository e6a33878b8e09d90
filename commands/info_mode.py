"""INFO_MODE: how many eigenfrequencies of (K, M) lie in each band of FREQ.

TYPE_MODE='DYNAMIQUE': one table row per band [FREQ[k], FREQ[k+1]] with
FREQ_MIN, FREQ_MAX, the bounds actually used once moved off an eigenvalue
(BORNE_MIN_EFFECT, BORNE_MAX_EFFECT) and NB_MODE, from Sturm counts of
K - (2π f)² M under the model's kinematic relations (asterlite.modal.sturm,
code_aster's op0032). Physical matrices and generalized ones (with the
interface relations of a substructured model) are counted alike."""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from asterlite.concepts.assembly import AssembledMatrix, ComplexAssembledMatrix
from asterlite.concepts.modes import GeneralizedMatrix
from asterlite.concepts.table import Table
from asterlite.fem.constraints import ConstraintError, Elimination
from asterlite.fem.selection import as_tuple
from asterlite.modal.calc import constrained_pencil
from asterlite.modal.eigen import EigenError, ReducedPencil, freq_from_omega2, omega2_from_freq
from asterlite.modal.sturm import ShiftRule, band_counts


def run(ctx, kw):
    kind = kw.get("TYPE_MODE", "DYNAMIQUE")
    if kind != "DYNAMIQUE":
        ctx.unsupported(f"INFO_MODE TYPE_MODE={kind!r} (only DYNAMIQUE)", "TYPE_MODE", kw)
    freq = np.asarray(as_tuple(kw["FREQ"]), dtype=float)
    if np.any(np.diff(freq) <= 0.0):
        ctx.error("FREQ must be strictly increasing", "FREQ", kw)
    counting = kw.factor("COMPTAGE")[0] if kw.factor("COMPTAGE") else {}
    rule = ShiftRule(
        threshold=float(omega2_from_freq(float(counting.get("SEUIL_FREQ", 1e-2)))),
        precision=float(counting.get("PREC_SHIFT", 5e-2)),
        max_tries=int(counting.get("NMAX_ITER_SHIFT", 3)),
    )
    if counting:
        # METHODE AUTO is STURM for a real pencil, the only count made here
        counting.mark_used("METHODE")
    pencil = _pencil(ctx, kw, kw["MATR_RIGI"], kw["MATR_MASS"])
    try:
        bands = band_counts(pencil, omega2_from_freq(freq), rule, ctx.log)
    except EigenError as exc:
        ctx.error(str(exc), "COMPTAGE", kw)
    table = Table()
    for name, code in (
        ("FREQ_MIN", "R"),
        ("FREQ_MAX", "R"),
        ("BORNE_MIN_EFFECT", "R"),
        ("BORNE_MAX_EFFECT", "R"),
        ("NB_MODE", "I"),
    ):
        table.add_column(name, code)
    lower, upper = freq_from_omega2(bands.lower), freq_from_omega2(bands.upper)
    for k, count in enumerate(bands.counts):
        table.add_row(
            {
                "FREQ_MIN": float(freq[k]),
                "FREQ_MAX": float(freq[k + 1]),
                "BORNE_MIN_EFFECT": float(lower[k]),
                "BORNE_MAX_EFFECT": float(upper[k]),
                "NB_MODE": int(count),
            }
        )
        ctx.log(f"[{freq[k]:.6g}, {freq[k + 1]:.6g}] Hz: {int(count)} eigenfrequencies")
    return table


def _pencil(ctx, kw, stiffness, mass) -> ReducedPencil:
    if isinstance(stiffness, GeneralizedMatrix) and isinstance(mass, GeneralizedMatrix):
        if stiffness.matrix.shape != mass.matrix.shape:
            ctx.error("MATR_RIGI and MATR_MASS differ in size", "MATR_MASS", kw)
        if np.iscomplexobj(stiffness.matrix):
            ctx.unsupported("INFO_MODE of a complex generalized stiffness", "MATR_RIGI", kw)
        return _generalized_pencil(stiffness, mass)
    if isinstance(stiffness, ComplexAssembledMatrix):
        ctx.unsupported("INFO_MODE of a complex stiffness", "MATR_RIGI", kw)
    if not isinstance(stiffness, AssembledMatrix) or not isinstance(mass, AssembledMatrix):
        ctx.unsupported("INFO_MODE on these matrix types", "MATR_RIGI", kw)
    if mass.numbering is not stiffness.numbering:
        ctx.error("MATR_RIGI and MATR_MASS use different numberings", "MATR_MASS", kw)
    try:
        return constrained_pencil(stiffness, mass)
    except ConstraintError as exc:
        ctx.error(str(exc), "MATR_RIGI", kw)


def _generalized_pencil(stiffness, mass) -> ReducedPencil:
    """The projected pencil; a substructured model's on the null space of
    its interface relations (what code_aster's Lagrange multipliers impose)."""
    n = stiffness.matrix.shape[0]
    constraints = getattr(stiffness.numbering, "constraints", None)
    if constraints is None:
        basis = sp.identity(n, format="csr")
    else:
        from asterlite.substructure.coupling import null_space_basis

        basis = sp.csr_matrix(null_space_basis(np.asarray(constraints, dtype=float), n))
    elimination = Elimination(
        basis, np.zeros(n), np.arange(basis.shape[1]), np.array([], dtype=int)
    )
    return ReducedPencil(
        np.asarray(stiffness.matrix, dtype=float), np.asarray(mass.matrix, dtype=float), elimination
    )
