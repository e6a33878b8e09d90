"""MACRO_PROJ_BASE (code_aster 10-11): one generalized numbering on the basis,
then PROJ_MATR_BASE / PROJ_VECT_BASE for each occurrence, each result bound
to its CO("NAME") (as code_aster 11's macro did)."""

from __future__ import annotations

import numpy as np
from asterlite.commands import proj_matr_base, proj_vect_base

from asterlite.concepts.modes import GeneralizedNumbering
from asterlite.lang.values import CO

TYPE_VECT = ("FORC", "DEPL", "VITE", "ACCE")  # what PROJ_VECT_BASE accepted


def _output(ctx, occ, keyword: str) -> CO:
    """The CO("NAME") an occurrence names; an existing concept would have been
    overwritten by code_aster, which asterlite does not do."""
    output = occ[keyword]
    if not isinstance(output, CO):
        ctx.unsupported(
            f"{keyword} given an existing concept (code_aster overwrote it): "
            'name a new result with CO("NAME")',
            keyword,
            occ,
        )
    return output


def run(ctx, kw):
    basis = kw["BASE"]
    count = int(kw["NB_VECT"])
    if count < basis.n_modes:
        basis = basis.select(np.arange(count))
    numbering = GeneralizedNumbering(basis=basis, storage=kw["PROFIL"])
    for occ in kw.factor("MATR_ASSE_GENE"):
        output = _output(ctx, occ, "MATRICE")
        if occ.get("MATR_ASSE") is None:
            ctx.unsupported("projection of a generalized matrix", "MATR_ASSE_GENE", occ)
        ctx.bind(output, proj_matr_base.project(ctx, occ, basis, numbering, occ["MATR_ASSE"]))
    for occ in kw.factor("VECT_ASSE_GENE"):
        output = _output(ctx, occ, "VECTEUR")
        if occ.get("VECT_ASSE") is None:
            ctx.unsupported("projection of a generalized vector", "VECT_ASSE_GENE", occ)
        kind = occ["TYPE_VECT"]
        if kind not in TYPE_VECT:
            expected = ", ".join(TYPE_VECT)
            ctx.error(f"TYPE_VECT={kind!r}: expected one of {expected}", "TYPE_VECT", occ)
        vector = proj_vect_base.project(ctx, occ, basis, numbering, occ["VECT_ASSE"], kind)
        ctx.bind(output, vector)
    return None
