"""IMPR_MACR_ELEM: a dynamic macro-element written as an I-DEAS universal
file (asterlite.io.ideas_macro); MISS_3D is refused."""

from __future__ import annotations

from asterlite.io.ideas_macro import macro_element_lines
from asterlite.io.tables import write_lines


def run(ctx, kw):
    if kw.get("FORMAT", "IDEAS") != "IDEAS":
        ctx.unsupported("IMPR_MACR_ELEM FORMAT='MISS_3D'", "FORMAT", kw)
    kw.mark_used("VERSION")  # 5, the only one
    macro = kw["MACR_ELEM_DYNA"]
    path = ctx.session.output_path(int(kw.get("UNITE", 30)))
    lines = macro_element_lines(macro, macro.name or "")
    write_lines(path, lines)
    ctx.log(f"IMPR_MACR_ELEM: {len(lines)} lines written to {path.name}")
