"""IMPR_FONCTION: print curves (FONCTION, LIST_PARA + LIST_RESU, or ABSCISSE
+ ORDONNEE) as TABLEAU text or as a Grace project (XMGRACE). With an image
PILOTE (PNG, SVG, PDF, EPS, POSTSCRIPT, JPEG) the unit receives the picture,
drawn with matplotlib instead of the xmgrace program; 'INTERACTIF' (a window)
keeps the project file."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.function import Formula
from asterlite.extras import MissingExtraError, require
from asterlite.io.tables import function_lines, write_lines, xmgrace_lines
from asterlite.post.restitution import values_of

# code_aster's PILOTE image drivers and the matplotlib format drawing each
IMAGE_FORMATS = {
    "PNG": "png",
    "SVG": "svg",
    "PDF": "pdf",
    "EPS": "eps",
    "POSTSCRIPT": "ps",
    "JPEG": "jpeg",
}


def run(ctx, kw):
    curves = [curve(ctx, occ) for occ in kw.factor("COURBE")]
    if not curves:
        ctx.error("COURBE is required", "COURBE", kw)
    fmt = kw.get("FORMAT", "TABLEAU")
    unit = int(kw.get("UNITE", 8))
    path = ctx.session.output_path(unit)
    styles = [curve_style(occ) for occ in kw.factor("COURBE")]  # a table draws none
    if fmt == "TABLEAU":
        lines = []
        for x, y, legend, para, resu in curves:
            lines += function_lines(x, y, para, resu, legend)
        write_lines(path, lines)
    elif fmt == "XMGRACE":
        title = kw.get("TITRE") or ""
        title = title if isinstance(title, str) else " ".join(title)
        xlabel = kw.get("LEGENDE_X") or curves[0][3]
        ylabel = kw.get("LEGENDE_Y") or curves[0][4]
        drawn = [
            (x, y, legend, style)
            for (x, y, legend, _, _), style in zip(curves, styles, strict=True)
        ]
        image_format = IMAGE_FORMATS.get(kw.get("PILOTE") or "")
        if image_format is not None:
            from asterlite.post.plots import curves_figure

            require_matplotlib(ctx, kw)

            curves_figure(drawn, title, xlabel, ylabel).savefig(path, format=image_format)
        else:
            write_lines(path, xmgrace_lines(drawn, title, xlabel, ylabel), append=False)
            if kw.get("PILOTE"):
                ctx.log(f"PILOTE={kw['PILOTE']!r}: no window here, Grace project written")
    else:
        ctx.unsupported(f"FORMAT={fmt!r}", "FORMAT", kw)
    ctx.log(f"{len(curves)} curve(s) written to {path.name}")
    return None


def curve_style(occ) -> dict:
    """The drawing styles a COURBE occurrence gives (Grace's numbers)."""
    names = ("STYLE", "COULEUR", "MARQUEUR", "FREQ_MARQUEUR")
    return {name: occ[name] for name in names if occ.get(name) is not None}


def curve(ctx, occ):
    legend = occ.get("LEGENDE") or ""
    if occ.get("FONCTION") is not None:
        func = occ["FONCTION"]
        if isinstance(func, Formula):
            if occ.get("LIST_PARA") is None:
                ctx.error("a FORMULE needs LIST_PARA to be printed", "LIST_PARA", occ)
            x = values_of(occ["LIST_PARA"])
            return x, func.evaluate(x), legend or func.name or "", func.NOM_PARA[0], "TOUTRESU"
        x = func.abscissas
        if occ.get("LIST_PARA") is not None:
            x = values_of(occ["LIST_PARA"])
        return x, func.evaluate(x), legend or func.name or "", func.NOM_PARA, func.NOM_RESU
    if occ.get("LIST_PARA") is not None and occ.get("LIST_RESU") is not None:
        return values_of(occ["LIST_PARA"]), values_of(occ["LIST_RESU"]), legend, "PARA", "RESU"
    if occ.get("ABSCISSE") is not None:
        x, y = values_of(occ["ABSCISSE"]), values_of(occ["ORDONNEE"])
        if x.size != y.size:
            ctx.error(f"{x.size} abscissas but {y.size} ordinates", "ORDONNEE", occ)
        return x, y, legend, "ABSCISSE", "ORDONNEE"
    which = next((k for k in ("FONC_X", "NAPPE", "TABLE") if occ.get(k) is not None), "COURBE")
    ctx.unsupported(f"IMPR_FONCTION/COURBE with {which}", which, occ)
    return np.zeros(0), np.zeros(0), "", "", ""


def require_matplotlib(ctx, kw) -> None:
    """Images need matplotlib (the plot extra): say so at the PILOTE keyword."""

    try:
        require("matplotlib.figure", f"PILOTE={kw['PILOTE']!r} (an image)")
    except MissingExtraError as error:
        error.path, location = kw.where("PILOTE")
        error.location = location or ctx.location
        raise
