"""AFFE_CHAR_MECA_C: DDL_IMPO, LIAISON_DDL and FORCE_POUTRE with complex values.

The load is built twice by AFFE_CHAR_MECA's own code, once from the real parts
of the values and once from the imaginary parts (loads are linear in their
values); the result keeps both (asterlite.concepts.complex_load). Imposed
values (DDL_IMPO, LIAISON_DDL's COEF_IMPO) with an imaginary part are refused.
"""

from __future__ import annotations

from asterlite.commands import affe_char_meca

from asterlite.concepts.complex_load import ComplexMechanicalLoad


def _part(keywords, part: str):
    """A copy of the keyword tree with each complex value replaced by its real
    or imaginary part (reads of the copy count as reads of the deck's tree)."""
    twin = keywords.copy()
    for key in dict.keys(keywords):
        value = dict.__getitem__(keywords, key)
        if isinstance(value, complex):
            dict.__setitem__(twin, key, value.real if part == "real" else value.imag)
        elif isinstance(value, (list, tuple)) and value and hasattr(value[0], "copy"):
            dict.__setitem__(twin, key, [_part(occ, part) for occ in value])
    return twin


def run(ctx, kw):
    real = affe_char_meca.run(ctx, _part(kw, "real"))
    imaginary = affe_char_meca.run(ctx, _part(kw, "imag"))
    if any(twin.rhs != 0.0 for twin in imaginary.relations):
        ctx.unsupported(
            "AFFE_CHAR_MECA_C imposing values with an imaginary part (DDL_IMPO, "
            "LIAISON_DDL COEF_IMPO)",
            None,
            kw,
        )
    return ComplexMechanicalLoad(
        model=real.model,
        relations=real.relations,
        nodal_forces=real.nodal_forces,
        extra=real.extra,
        imaginary=imaginary,
    )
