"""CALC_VECT_ELEM OPTION='CHAR_MECA': nodal load terms of mechanical loads."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import ElementaryVectors
from asterlite.fem.elements import element_blocks
from asterlite.fem.selection import as_tuple

_TRANSLATIONS = ("DX", "DY", "DZ")


def gravity_terms(model, characteristics, gravity: float, direction) -> list:
    """Nodal forces M·a of a uniform acceleration g·d on the discrete masses."""
    d = np.asarray(direction, dtype=float)
    d = gravity * d / np.linalg.norm(d)
    terms = []
    for block in element_blocks(model, characteristics, "M"):
        accel = np.array(
            [d[_TRANSLATIONS.index(c)] if c in _TRANSLATIONS else 0.0 for c in block.components]
        )
        n_el, per_el = block.nodes.shape
        a = np.tile(accel, per_el)
        forces = block.matrices @ a  # (n_el, d)
        comps = list(block.components) * per_el
        for e in range(n_el):
            nodes = np.repeat(block.nodes[e], len(block.components))
            terms.extend(zip(nodes.tolist(), comps, forces[e].tolist(), strict=True))
    return terms


def run(ctx, kw):
    option = kw.get("OPTION", "CHAR_MECA")
    if option != "CHAR_MECA":
        ctx.unsupported(f"CALC_VECT_ELEM OPTION={option!r}", "OPTION", kw)
    loads = list(as_tuple(kw.get("CHARGE")))
    model = kw.get("MODELE") or (loads[0].model if loads else None)
    terms = []
    for load in loads:
        terms.extend(load.nodal_forces)
        gravity = load.extra.get("PESANTEUR")
        if gravity is not None:
            if kw.get("CARA_ELEM") is None:
                ctx.error("PESANTEUR needs CARA_ELEM to know the masses", "CARA_ELEM", kw)
            terms.extend(
                gravity_terms(load.model, kw["CARA_ELEM"], gravity["GRAVITE"], gravity["DIRECTION"])
            )
    return ElementaryVectors(model=model, option=option, loads=loads, terms=terms)
