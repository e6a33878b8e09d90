"""ASSE_MATR_GENE: the block-diagonal generalized matrix of a coupled model.

The interface relations are not written into the matrix (code_aster's
Lagrange rows): they stay on the NUME_DDL_GENE and the solvers apply them."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.modes import ComplexGeneralizedMatrix, GeneralizedMatrix
from asterlite.concepts.substructure import SubstructuredNumbering

_BLOCKS = {
    "RIGI_GENE": ("stiffness", "RIGI"),
    "RIGI_GENE_C": ("stiffness", "RIGI"),  # complex: the macro-elements' K (1 + iη)
    "MASS_GENE": ("mass", "MASS"),
    "AMOR_GENE": ("damping", "AMOR"),
}


def run(ctx, kw):
    numbering = kw["NUME_DDL_GENE"]
    if kw.get("METHODE", "CLASSIQUE") != "CLASSIQUE":
        ctx.unsupported("ASSE_MATR_GENE METHODE='INITIAL'", "METHODE", kw)
    if not isinstance(numbering, SubstructuredNumbering):
        ctx.error("NUME_DDL_GENE must be built on a MODELE_GENE", "NUME_DDL_GENE", kw)
    return assemble(ctx, kw, numbering, kw["OPTION"])


def assemble(ctx, kw, numbering, option):
    """The block-diagonal matrix of OPTION (also ASSE_ELEM_SSD's)."""
    if option not in _BLOCKS:
        ctx.unsupported(f"ASSE_MATR_GENE OPTION={option!r}", "OPTION", kw)
    attribute, kind = _BLOCKS[option]
    n = numbering.n_modes
    complex_option = option == "RIGI_GENE_C"
    matrix = np.zeros((n, n), dtype=complex if complex_option else float)
    for k, sub in enumerate(numbering.model.substructures):
        block = getattr(sub.macro, attribute)
        if block is None:
            if option == "AMOR_GENE":
                continue  # a macro-element without damping adds nothing
            ctx.error(f"macro-element of {sub.name} has no {option} matrix", "OPTION", kw)
        if np.iscomplexobj(block) and not complex_option:
            ctx.unsupported(
                f"ASSE_MATR_GENE OPTION={option!r} of the complex stiffness of {sub.name}'s "
                "macro-element (RIGI_GENE_C assembles it)",
                "OPTION",
                kw,
            )
        lo, hi = numbering.offsets[k], numbering.offsets[k + 1]
        matrix[lo:hi, lo:hi] = block
    cls = ComplexGeneralizedMatrix if complex_option else GeneralizedMatrix
    return cls(numbering=numbering, matrix=matrix, kind=kind)
