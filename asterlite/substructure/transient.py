"""DYNA_VIBRA on the assembled matrices of a generalized model.

code_aster integrates the double-Lagrange system after giving the Lagrange
rows a mass proportional to their stiffness (dtmprep / ajlagr): the sum of
each pair of Lagrange rows then reads c (B q)'' + B q = 0, which any linear
scheme started from rest keeps at B q = 0 step after step, and the
remaining equations are the scheme applied to the pencil restricted to
{B q = 0}. asterlite integrates that restricted system directly: q = T r
with T an orthonormal basis of the null space of B (so Euclidean norms of
r, which adaptive schemes measure, are those of q)."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.modes import (
    GeneralizedMatrix,
    GeneralizedModes,
    GeneralizedNumbering,
    GeneralizedVector,
)
from asterlite.concepts.substructure import SubstructuredNumbering
from asterlite.substructure.coupling import null_space_basis

MATRICES = ("MATR_MASS", "MATR_RIGI", "MATR_AMOR")


def is_substructured(matrix) -> bool:
    return isinstance(getattr(matrix, "numbering", None), SubstructuredNumbering)


def reduced_numbering(numbering: SubstructuredNumbering, mass, stiffness) -> GeneralizedNumbering:
    """A numbering whose "modes" are the columns of T (vectors on ``numbering``)."""
    t = null_space_basis(numbering.constraints, numbering.n_modes)
    gm = np.einsum("ij,ij->j", t, mass @ t)
    gk = np.einsum("ij,ij->j", t, stiffness @ t)
    basis = GeneralizedModes(
        numbering=numbering,
        vectors=t,
        frequencies=np.zeros(t.shape[1]),
        generalized_mass=gm,
        generalized_stiffness=gk,
        parameters={"NUME_MODE": np.arange(1, t.shape[1] + 1)},
    )
    return GeneralizedNumbering(basis=basis, storage="PLEIN")


def reduce_keywords(kw) -> str | None:
    """Replace the generalized matrices and vectors of a DYNA_VIBRA call by
    their restriction q = T r; returns the keyword of an operand that cannot
    be restricted (a vector on another numbering), or None."""
    numbering = kw["MATR_MASS"].numbering
    mass = np.asarray(kw["MATR_MASS"].matrix, dtype=float)
    stiffness = np.asarray(kw["MATR_RIGI"].matrix, dtype=float)
    reduced = reduced_numbering(numbering, mass, stiffness)
    t = reduced.basis.vectors
    for keyword in MATRICES:
        matrix = kw.get(keyword)
        if matrix is None:
            continue
        if matrix.numbering is not numbering:
            return keyword
        values = t.T @ np.asarray(matrix.matrix, dtype=float) @ t
        dict.__setitem__(kw, keyword, GeneralizedMatrix(reduced, values, matrix.kind))
    for occ in kw.factor("EXCIT"):
        vector = occ.get("VECT_ASSE_GENE")
        if vector is None:
            continue
        if vector.numbering is not numbering:
            return "VECT_ASSE_GENE"
        values = _restricted(t, vector)
        dict.__setitem__(occ, "VECT_ASSE_GENE", GeneralizedVector(reduced, values, vector.kind))
    for occ in kw.factor("ETAT_INIT"):
        for keyword in ("DEPL", "VITE"):
            vector = occ.get(keyword)
            if vector is not None and getattr(vector, "numbering", None) is numbering:
                values = _restricted(t, vector)
                dict.__setitem__(occ, keyword, GeneralizedVector(reduced, values, vector.kind))
    return None


def _restricted(t, vector) -> np.ndarray:
    """Tᵀ f for a force; the coordinates r of q = T r for a state."""
    values = np.asarray(vector.values, dtype=float)
    return t.T @ values  # T orthonormal: also the least-squares r of a state
