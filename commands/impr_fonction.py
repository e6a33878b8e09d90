"""IMPR_FONCTION: print curves (FONCTION, LIST_PARA + LIST_RESU, or ABSCISSE
+ ORDONNEE) as TABLEAU text, as AGRAF data and directives files
(asterlite.io.agraf) or as a Grace project (XMGRACE). With an image
PILOTE (PNG, SVG, PDF, EPS, POSTSCRIPT, JPEG) the unit receives the picture,
drawn with matplotlib instead of the xmgrace program; 'INTERACTIF' (a window)
keeps the project file."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.function import Formula
from asterlite.extras import MissingExtraError, require
from asterlite.io import agraf
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
        layout = graph_layout(kw)
        image_format = IMAGE_FORMATS.get(kw.get("PILOTE") or "")
        if image_format is not None:
            from asterlite.post.plots import curves_figure

            require_matplotlib(ctx, kw)

            figure = curves_figure(drawn, title, xlabel, ylabel, layout)
            figure.savefig(path, format=image_format)
        else:
            write_lines(path, xmgrace_lines(drawn, title, xlabel, ylabel, layout), append=False)
            if kw.get("PILOTE"):
                ctx.log(f"PILOTE={kw['PILOTE']!r}: no window here, Grace project written")
    elif fmt == "AGRAF":
        write_agraf(ctx, kw, curves, path)
    else:
        ctx.unsupported(f"FORMAT={fmt!r}", "FORMAT", kw)
    ctx.log(f"{len(curves)} curve(s) written to {path.name}")
    return None


def graph_layout(kw) -> dict:
    """The graph's SOUS_TITRE, ECHELLE_X/Y, GRILLE_X/Y and BORNE_X/Y
    (asterlite.io.tables.grace_layout_lines); a grid step of zero is no step,
    as in code_aster."""
    layout = {"subtitle": _text(kw.get("SOUS_TITRE"))}
    for axis in ("X", "Y"):
        layout[f"{axis.lower()}_scale"] = kw.get(f"ECHELLE_{axis}", "LIN")
        layout[f"{axis.lower()}_grid"] = kw.get(f"GRILLE_{axis}") or None
        given = kw.get(f"BORNE_{axis}")
        layout[f"{axis.lower()}_range"] = None if given is None else tuple(map(float, given))
    return layout


def write_agraf(ctx, kw, curves, path) -> None:
    """FORMAT='AGRAF': the data to UNITE, the directives to UNITE_DIGR (the
    message file when it is 6); a complex function gives its real and
    imaginary parts as two columns, or the PARTIE asked."""
    graph = agraf.AgrafGraph(
        title=_text(kw.get("TITRE")),
        subtitle=_text(kw.get("SOUS_TITRE")),
        x_scale=kw.get("ECHELLE_X", "LIN"),
        y_scale=kw.get("ECHELLE_Y", "LIN"),
        x_label=kw.get("LEGENDE_X") or "",
        y_label=kw.get("LEGENDE_Y") or "",
    )
    for axis in ("X", "Y"):
        given = kw.get(f"BORNE_{axis}")
        if given is not None:
            setattr(graph, f"{axis.lower()}_range", tuple(float(v) for v in given))
        # code_aster takes a grid step only when it is not zero
        if kw.get(f"GRILLE_{axis}"):
            setattr(graph, f"{axis.lower()}_grid", float(kw[f"GRILLE_{axis}"]))
    for occ, (x, y, legend, _, _) in zip(kw.factor("COURBE"), curves, strict=True):
        y = np.asarray(y)
        if np.iscomplexobj(y):
            part = occ.get("PARTIE")
            columns = {"REEL": [y.real], "IMAG": [y.imag]}.get(part, [y.real, y.imag])
        else:
            columns = [y]
        graph.curves.append(
            agraf.AgrafCurve(
                columns=[np.asarray(x, dtype=float), *columns],
                legend=legend,
                style=occ.get("STYLE"),
                colour=occ.get("COULEUR"),
                marker=occ.get("MARQUEUR"),
                marker_frequency=occ.get("FREQ_MARQUEUR"),
                sort=occ.get("TRI", "N"),
            )
        )
    unit = int(kw.get("UNITE_DIGR", 26))
    if unit == 6:
        with open(path, "a", encoding="utf-8") as stream:
            stream.write(agraf.data(graph))
        ctx.log(agraf.directives(graph))
    else:
        agraf.append_graph(path, ctx.session.output_path(unit), graph)


def _text(value) -> str:
    if value is None:
        return ""
    return value if isinstance(value, str) else " ".join(str(v) for v in value)


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
