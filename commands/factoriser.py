"""FACTORISER: factorise an assembled matrix (real or complex) under its
kinematic relations.

The direct methods (MUMPS, MULT_FRONT, LDLT) give the same factors up to
rounding: whichever is named, asterlite factorises the reduced matrix with
MUMPS when it is real, symmetric and of 4 000 unknowns or more (where
python-mumps is installed; out of core past its share of the memory limit),
with SuperLU otherwise, in a symmetric ordering (the RENUM orderings of
code_aster's solvers change the cost, not the solution). The factors are
kept on the matrix (``reuse``, as code_aster keeps them) for RESOUDRE. A
singular matrix stops (STOP_SINGULIER='OUI') or is reported (``'NON'``):
on SuperLU a pivot losing more than NPREC digits against its diagonal term,
on MUMPS a pivot below 10^-NPREC of the largest row sum (MUMPS's null pivot
detection, which code_aster sets from NPREC).
"""

from __future__ import annotations

from asterlite.concepts.assembly import AssembledMatrix
from asterlite.fem.factorization import FactorizationError, factorize

DIRECT_METHODS = ("MUMPS", "MULT_FRONT", "LDLT")
# keywords of the direct methods that tune their speed or memory, not the factors
_TUNING = (
    "RENUM",
    "TYPE_RESOL",
    "PRETRAITEMENTS",
    "PCENT_PIVOT",
    "ELIM_LAGR",
    "GESTION_MEMOIRE",
    "ACCELERATION",
    "LOW_RANK_SEUIL",
)


def run(ctx, kw):
    matrix = kw["MATR_ASSE"]
    method = kw.get("METHODE", "MUMPS")
    if method not in DIRECT_METHODS:
        ctx.unsupported(f"FACTORISER METHODE={method!r} (preconditioners)", "METHODE", kw)
    if not isinstance(matrix, AssembledMatrix):
        ctx.unsupported(f"FACTORISER of a {matrix.aster_type}", "MATR_ASSE", kw)
    for name in ("BLOC_DEBUT", "DDL_DEBUT", "BLOC_FIN", "DDL_FIN"):
        if kw.get(name) is not None:
            ctx.unsupported(f"FACTORISER {name} (partial factorisation)", name, kw)
    if kw.get("LOW_RANK_SEUIL"):
        # a non-zero threshold makes MUMPS's factors approximate
        ctx.unsupported("FACTORISER LOW_RANK_SEUIL (approximate factors)", "LOW_RANK_SEUIL", kw)
    kw.mark_used(*_TUNING)
    digits = int(kw.get("NPREC", 8))
    try:
        factors = factorize(matrix.matrix, matrix.numbering, digits)
    except FactorizationError as exc:
        ctx.error(str(exc), "MATR_ASSE", kw)
    n = factors.reduced.shape[0]
    if factors.null_pivots is not None:  # MUMPS: its null pivots, as code_aster's
        singular = factors.null_pivots > 0
        message = (
            f"the matrix is singular: {factors.null_pivots} pivot(s) below 1e-{digits} "
            f"of the largest row sum (NPREC={digits})"
        )
        summary = (
            f"factorised by MUMPS: {n} unknowns after the relations, "
            f"{factors.null_pivots} null pivot(s)"
        )
    else:
        singular = factors.lost_digits > digits
        message = (
            f"the matrix is singular: a pivot loses {factors.lost_digits:.1f} digits "
            f"(NPREC={digits})"
        )
        summary = (
            f"factorised: {n} unknowns after the relations, "
            f"largest loss of digits {factors.lost_digits:.1f}"
        )
    if singular:
        if kw.get("STOP_SINGULIER", "OUI") == "OUI":
            ctx.error(message, "STOP_SINGULIER", kw)
        ctx.log(f"warning: {message}")
    ctx.log(summary)
    target = matrix if ctx.reuse is matrix else _copy(matrix)
    target.factorization = factors
    return target


def _copy(matrix: AssembledMatrix) -> AssembledMatrix:
    # ComplexAssembledMatrix stays complex
    return type(matrix)(
        numbering=matrix.numbering,
        matrix=matrix.matrix,
        kind=matrix.kind,
        model=matrix.model,
        characteristics=matrix.characteristics,
        materials=matrix.materials,
    )
