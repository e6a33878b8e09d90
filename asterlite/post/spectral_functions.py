"""RECU_FONCTION(INTE_SPEC=...): one term of a spectral matrix as a function.

As code_aster's rfinte: the abscissa is the matrix's (FREQ, or INST for
generated signals), the ordinate NOM_CHAM or 'DSP'; a diagonal term gives a
real function, an off-diagonal one a complex function; interpolation
'LIN LIN' and linear extension on both sides unless INTERPOL / PROL_* say
otherwise. NUME_ORDRE_J defaults to NUME_ORDRE_I (NOEUD_J, NOM_CMP_J alike).
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.function import ComplexFunction, Function


def term_key(kw):
    if kw.get("NUME_ORDRE") is not None:
        return int(kw["NUME_ORDRE"])
    if kw.get("NUME_ORDRE_I") is not None:
        i = int(kw["NUME_ORDRE_I"])
        j = kw.get("NUME_ORDRE_J")
        return (i, i if j is None else int(j))
    node_i, cmp_i = str(kw["NOEUD_I"]), kw["NOM_CMP_I"]
    node_j = kw.get("NOEUD_J")
    cmp_j = kw.get("NOM_CMP_J")
    return (
        node_i,
        cmp_i,
        node_i if node_j is None else str(node_j),
        cmp_i if cmp_j is None else cmp_j,
    )


def function_of_interspectrum(ctx, kw):
    inter = kw["INTE_SPEC"]
    key = term_key(kw)
    try:
        values = inter.lookup(key)
    except KeyError:
        where = next(k for k in ("NUME_ORDRE", "NUME_ORDRE_I", "NOEUD_I") if kw.get(k) is not None)
        ctx.error(f"the matrix has no term {key}", where, kw)
    name = kw.get("NOM_CHAM")
    if name is not None and name != "DSP":
        ctx.error(f"the matrix holds DSP, not {name}", "NOM_CHAM", kw)
    cls = ComplexFunction if np.iscomplexobj(values) else Function
    return cls(
        inter.disc.copy(),
        np.array(values, copy=True),
        NOM_PARA=inter.abscissa,
        NOM_RESU=name or "DSP",
        INTERPOL=kw.get("INTERPOL", ("LIN", "LIN")),
        PROL_GAUCHE=kw.get("PROL_GAUCHE", "LINEAIRE"),
        PROL_DROITE=kw.get("PROL_DROITE", "LINEAIRE"),
    )
