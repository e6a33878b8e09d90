"""AGRAF curve files, as code_aster's IMPR_FONCTION / IMPR_TABLE FORMAT='AGRAF'
write them: a data file (one block per curve: a '#NOM DE LA FONCTION:' line,
then one line of columns per point, a blank line) and a directives file (a
fixed page layout, the graph's title, grid, scales, legends and ranges, and
one COURBE entry per ordinate column). Both are appended to, one graph per
call. Unset ranges are the curves' bounding box widened by 5 % of its
extent on each side (2.5 % of the extent at each end), code_aster's margin.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

_PAGE = """
ASPECT_GRAPHIQUE:
  En-tete :Departement Analyses Mecaniques et Acoustique
  Aspect :0
  Nombre de vues :1
  Cesure commentaire :40
  MinMax :0
  Fonte Titre :%helvetica-14
  Fonte Axes :%courier-12
  Fonte Autre :%times-12
"""
# the default colour of curves 0..11 (16-bit RGB), in code_aster's order
_COLOURS = (
    (0, 0, 0),
    (65535, 0, 0),
    (11822, 35723, 22359),
    (0, 0, 65535),
    (65535, 0, 65535),
    (0, 65535, 65535),
    (0, 65535, 0),
    (41120, 21074, 11565),
    (65535, 42405, 0),
    (41120, 8224, 61680),
    (65535, 65535, 0),
    (53970, 46260, 35980),
)
_SCALES = {"LIN": "0", "LOG": "1"}


@dataclass
class AgrafCurve:
    """One curve: abscissas and one or two ordinate columns (real and
    imaginary parts of a complex function), with its drawing choices (None:
    code_aster's default for the curve's rank)."""

    columns: list[np.ndarray]
    legend: str = ""
    style: int | None = None
    colour: int | None = None
    marker: int | None = None
    marker_frequency: int | None = None
    sort: str = "N"


@dataclass
class AgrafGraph:
    curves: list[AgrafCurve] = field(default_factory=list)
    title: str = ""
    subtitle: str = ""
    x_range: tuple[float, float] | None = None
    y_range: tuple[float, float] | None = None
    x_scale: str = "LIN"
    y_scale: str = "LIN"
    x_grid: float | None = None
    y_grid: float | None = None
    x_label: str = ""
    y_label: str = ""


def _cycled(value, low: int, high: int, default: int) -> int:
    """code_aster's ValCycl: the default below ``low``, cycled above ``high``
    (no bound when high < low)."""
    value = low - 1 if value is None else int(value)
    if value < low:
        value = default
    if high < low:
        return value
    return (value - low) % (high + 1 - low) + low


def _bounds(values: np.ndarray) -> tuple[float, float]:
    """A range around the values: code_aster's SetExtrema with a 0.05 margin."""
    low, high = float(np.min(values)), float(np.max(values))
    extent = max(high - low, 0.01 * high)
    if extent == 0.0:
        extent = 1.0e-6
    return low - 0.05 * extent / 2.0, high + 0.05 * extent / 2.0


def _positive_minimum(values: np.ndarray) -> float:
    positive = values[values > 0.0]
    return float(positive.min()) if positive.size else 1.0e99


def directives(graph: AgrafGraph) -> str:
    """The directives file's part of one graph."""
    xs = np.concatenate([c.columns[0] for c in graph.curves])
    ys = np.concatenate([col for c in graph.curves for col in c.columns[1:]])
    x_range = graph.x_range if graph.x_range is not None else _bounds(xs)
    y_range = graph.y_range if graph.y_range is not None else _bounds(ys)
    x_grid, y_grid = graph.x_grid, graph.y_grid
    if graph.x_scale == "LOG":
        x_grid = 10
        if x_range[0] < 0.0:
            x_range = (_positive_minimum(xs), x_range[1])
    if graph.y_scale == "LOG":
        y_grid = 10
        if y_range[0] < 0.0:
            y_range = (_positive_minimum(ys), y_range[1])
    if x_grid is None or y_grid is None:
        x_grid = y_grid = 0
    text = _PAGE + "\n"
    for rgb in _COLOURS:
        text += "  DEFAUT_COURBE:\n    Couleur (rvb) :" + "".join(f"{c:6d}" for c in rgb) + "\n\n"
    text += "GRAPHIQUE:\n"
    text += f"Titre :{graph.title}\n"
    if graph.subtitle:
        text += f"Commentaire :{graph.subtitle}\n"
    text += f"Frequence Grille X :{int(x_grid)}\nFrequence Grille Y :{int(y_grid)}\n"
    text += f"Echelle X :{_SCALES[graph.x_scale]}\nEchelle Y :{_SCALES[graph.y_scale]}\n"
    if graph.x_label:
        text += f"Legende X :{graph.x_label}\n"
    if graph.y_label:
        text += f"Legende Y :{graph.y_label}\n"
    text += f"Min X : {x_range[0]!r}\nMax X : {x_range[1]!r}\n"
    text += f"Min Y : {y_range[0]!r}\nMax Y : {y_range[1]!r}\n"
    for rank, curve in enumerate(graph.curves):
        for column in range(2, len(curve.columns) + 1):
            text += "  COURBE:\n"
            text += f"     Trait :{_cycled(curve.style, 0, 2, 0)}\n"
            text += f"     Couleur :{_cycled(curve.colour, 0, 12, rank)}\n"
            text += f"     Marqueur :{_cycled(curve.marker, 0, 12, rank)}\n"
            text += f"     Frequence Marqueur :{_cycled(curve.marker_frequency, 0, -1, 0)}\n"
            if curve.legend:
                text += f"     Legende :{curve.legend}\n"
            text += f"     Tri :{curve.sort}\n"
            text += f"     Abscisses : [ {rank + 1}, 1]\n"
            text += f"     Ordonnees : [ {rank + 1}, {column}]\n"
    return text


def data(graph: AgrafGraph) -> str:
    """The data file's part of one graph (values as %12.5E)."""
    text = ""
    for rank, curve in enumerate(graph.curves):
        text += f"#NOM DE LA FONCTION: {curve.legend or f'COURBE_{rank}'}\n"
        table = np.column_stack([np.asarray(c, dtype=float) for c in curve.columns])
        for row in table:
            text += "".join(f" {v:12.5E}" for v in row) + "\n"
        text += "\n"
    return text


def append_graph(data_path, directives_path, graph: AgrafGraph) -> None:
    """Append one graph's data and directives to their files."""
    if not graph.curves:
        return
    with open(data_path, "a", encoding="utf-8") as stream:
        stream.write(data(graph))
    with open(directives_path, "a", encoding="utf-8") as stream:
        stream.write(directives(graph))
