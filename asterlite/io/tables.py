"""Text writers for tables and functions: code_aster's TABLEAU layout, CSV,
and XMGRACE (.agr) curves."""

from __future__ import annotations

import math
from collections.abc import Iterable
from itertools import groupby
from operator import itemgetter

import numpy as np


def format_value(value, type_code: str, real_format: str = "E12.5") -> str:
    """One cell as code_aster prints it (Fortran-like E format for reals)."""
    if value is None:
        return "-"
    if type_code == "R":
        return fortran_real(float(value), real_format)
    if type_code == "C":
        return f"{fortran_real(value.real, real_format)} {fortran_real(value.imag, real_format)}"
    return str(value)


def fortran_real(value: float, spec: str = "E12.5") -> str:
    """``E12.5`` → ``1.55000E-02`` (width, digits after the point)."""
    kind = spec[0].upper()
    width, _, digits = spec[1:].partition(".")
    digits = int(digits or 5)
    if not math.isfinite(value):
        return str(value).rjust(int(width or 12))
    text = f"{value:.{digits}E}" if kind in "ED" else f"{value:.{digits}f}"
    return text.rjust(int(width or 12))


def column_cells(values: list, type_code: str, real_format: str = "E12.5") -> list[str]:
    """The cells of one column: ``format_value`` of each value, in one
    comprehension per column with the format parsed once (a table of
    impacts has thousands of rows)."""
    if type_code not in ("R", "C"):
        return ["-" if value is None else str(value) for value in values]
    if type_code == "C":
        return [format_value(value, type_code, real_format) for value in values]
    kind = real_format[0].upper()
    width_text, _, digits = real_format[1:].partition(".")
    width = int(width_text or 12)
    pattern = f"{{:>{width}.{int(digits or 5)}{'E' if kind in 'ED' else 'f'}}}".format
    isfinite = math.isfinite
    return [
        "-"
        if value is None
        else (pattern(x) if isfinite(x := float(value)) else str(x).rjust(width))
        for value in values
    ]


def table_lines(table, columns: Iterable[str] | None = None, title: str = "", real_format="E12.5"):
    """Lines of a table in code_aster's TABLEAU layout: a commented title,
    a header of parameter names, one line per row, '-' where a row has no
    value."""
    columns = list(columns or table.columns)
    rows = table.rows
    fast = uniform_lines(rows, columns, table.types, real_format)
    if fast is not None:
        widths, body = fast
        lines = ["#-" * 40]
        if title:
            lines.extend(f"#{t}" for t in title.splitlines())
        lines.append(" ".join(c.ljust(w) for c, w in zip(columns, widths, strict=True)).rstrip())
        return lines + body
    by_column = [
        column_cells([row.get(c) for row in rows], table.types[c], real_format) for c in columns
    ]
    widths = [
        max([len(c)] + [len(v) for v in values])
        for c, values in zip(columns, by_column, strict=True)
    ]
    lines = ["#-" * 40]
    if title:
        lines.extend(f"#{t}" for t in title.splitlines())
    lines.append(" ".join(c.ljust(w) for c, w in zip(columns, widths, strict=True)).rstrip())
    if not columns:  # no column: an empty line per row
        lines.extend("" for _ in rows)
        return lines
    # one format per line: each cell left-justified to its column's width
    line = " ".join(f"{{:<{w}}}" for w in widths).format
    lines.extend(line(*cells).rstrip() for cells in zip(*by_column, strict=True))
    return lines


#: exponents of two digits: |x| in [1e-98, 9e99] or 0 (a margin for the rounding)
TWO_DIGIT_EXPONENT = (1.0e-98, 9.0e99)


def uniform_lines(rows, columns, types, real_format="E12.5"):
    """(widths, lines) of the rows of a table as :func:`table_lines` writes
    them, one ``%`` format per run of rows holding the same parameters
    (POST_DYNA_MODA_T's thousands of IMPACT rows are one run); None when a
    cell is outside what such a format writes identically (complex cells, a
    reals format other than E/D, a real of three exponent digits or not
    finite, a value not of its column's type, a row holding None, no
    column): the caller then formats cell by cell."""
    kind = real_format[0].upper()
    width_text, _, digits_text = real_format[1:].partition(".")
    real_width, digits = int(width_text or 12), int(digits_text or 5)
    if kind not in "ED" or digits + 7 > real_width or not columns:
        return None  # a real's text is then not always real_width long
    position = {c: i for i, c in enumerate(columns)}
    widths = [len(c) for c in columns]
    runs = []  # (indices of the columns a run holds, its rows' values)
    for keys, members in groupby(rows, key=tuple):
        shown = sorted(position[k] for k in keys if k in position)
        names = [columns[i] for i in shown]
        if list(keys) == names:
            values = [tuple(row.values()) for row in members]
        elif len(names) == 1:
            values = [(row[names[0]],) for row in members]
        else:
            pick = itemgetter(*names)
            values = [pick(row) for row in members] if names else [() for _ in members]
        for i, cells in zip(shown, zip(*values, strict=True), strict=True):
            width = cell_width(cells, types[columns[i]], real_width)
            if width is None:
                return None
            widths[i] = max(widths[i], width)
        if len(shown) < len(columns):  # a '-' somewhere
            for i in set(range(len(columns))) - set(shown):
                widths[i] = max(widths[i], 1)
        runs.append((shown, values))
    body = []
    for shown, values in runs:
        held = set(shown)
        parts = []
        for i, (name, width) in enumerate(zip(columns, widths, strict=True)):
            code = types[name]
            if i not in held:
                parts.append("-".ljust(width))
            elif code == "R":
                parts.append(f"%{real_width}.{digits}E" + " " * (width - real_width))
            else:
                parts.append(f"%-{width}{'d' if code == 'I' else 's'}")
        line = " ".join(parts)
        body.extend((line % cells).rstrip() for cells in values)
    return widths, body


def cell_width(cells, type_code, real_width):
    """The widest text of a column's cells under a ``%`` format of its type,
    None when a cell needs the cell-by-cell path."""
    kinds = set(map(type, cells))
    if type_code == "R":
        if kinds != {float}:
            return None
        size = np.abs(np.array(cells))
        low, high = TWO_DIGIT_EXPONENT
        if not np.all((size == 0.0) | ((size >= low) & (size <= high))):
            return None  # not finite, or three exponent digits
        return real_width
    if type_code == "I":
        if kinds != {int}:
            return None
        return max(len(str(min(cells))), len(str(max(cells))))
    if type_code == "C" or kinds != {str}:
        return None
    return max(map(len, cells))


def table_csv_lines(table, columns: Iterable[str] | None = None, separator: str = ","):
    columns = list(columns or table.columns)
    lines = [separator.join(columns)]
    for row in table.rows:
        lines.append(
            separator.join(
                "" if row.get(c) is None else format_value(row[c], table.types[c], "E.12").strip()
                for c in columns
            )
        )
    return lines


def function_lines(abscissas, ordinates, nom_para: str, nom_resu: str, title: str = ""):
    """A function as a two-column (three for complex) TABLEAU block."""
    ordinates = np.asarray(ordinates)
    lines = ["#-" * 40]
    if title:
        lines.append(f"#{title}")
    if ordinates.dtype.kind == "c":
        lines.append(f"{nom_para:<12} {nom_resu + '_R':<12} {nom_resu + '_I':<12}")
        for x, y in zip(abscissas, ordinates, strict=True):
            lines.append(f"{fortran_real(x)} {fortran_real(y.real)} {fortran_real(y.imag)}")
    else:
        lines.append(f"{nom_para:<12} {nom_resu:<12}")
        for x, y in zip(abscissas, ordinates, strict=True):
            lines.append(f"{fortran_real(x)} {fortran_real(float(y))}")
    return lines


# IMPR_FONCTION's curve styles (Grace's own numbers) and the set attribute each sets
GRACE_STYLE_ATTRIBUTES = {
    "STYLE": "line linestyle",
    "COULEUR": "line color",
    "MARQUEUR": "symbol",
    "FREQ_MARQUEUR": "symbol skip",
}


# IMPR_FONCTION's ECHELLE_X/Y and Grace's axis scales
GRACE_SCALES = {"LIN": "Normal", "LOG": "Logarithmic"}
#: the major tick step code_aster gives a logarithmic axis (decades)
GRACE_LOG_TICK = 10


def xmgrace_lines(curves, title: str = "", x_label: str = "", y_label: str = "", layout=None):
    """A minimal Grace project: one xy set per curve (abscissas, ordinates,
    legend, and the styles the deck gave: ``{"STYLE": 1, ...}``); ``layout``:
    the graph's subtitle, axis scales, major tick steps and bounds
    (:func:`grace_layout_lines`)."""
    lines = ["# Grace project file", "@version 50122"]
    if title:
        lines.append(f'@title "{title}"')
    lines += [f'@xaxis label "{x_label}"', f'@yaxis label "{y_label}"']
    lines += grace_layout_lines(layout or {})
    for k, (x, y, legend, *style) in enumerate(curves):
        lines.append(f'@s{k} legend "{legend}"')
        for key, value in (style[0] if style else {}).items():
            lines.append(f"@s{k} {GRACE_STYLE_ATTRIBUTES[key]} {int(value)}")
        lines += [f"@target G0.S{k}", "@type xy"]
        lines += [f"{xi:.10E} {float(np.real(yi)):.10E}" for xi, yi in zip(x, y, strict=True)]
        lines.append("&")
    return lines


def grace_layout_lines(layout: dict) -> list[str]:
    """Grace directives of a graph layout, as code_aster writes them:
    ``subtitle``; per axis ``x``/``y``: ``_scale`` ('LIN' or 'LOG'), ``_grid``
    (the major tick step; a decade on a logarithmic axis), ``_range`` (the
    world's bounds). What the layout leaves out (a linear scale among them),
    Grace decides."""
    lines = []
    if layout.get("subtitle"):
        lines.append(f'@subtitle "{layout["subtitle"]}"')
    for axis in ("x", "y"):
        scale = layout.get(f"{axis}_scale") or "LIN"
        if scale != "LIN":
            lines.append(f"@{axis}axes scale {GRACE_SCALES[scale]}")
        step = GRACE_LOG_TICK if scale == "LOG" else layout.get(f"{axis}_grid")
        if step:
            lines.append(f"@{axis}axis tick major {float(step):g}")
        bounds = layout.get(f"{axis}_range")
        if bounds is not None:
            low, high = (float(bound) for bound in bounds)
            lines += [f"@world {axis}min {low:g}", f"@world {axis}max {high:g}"]
    return lines


def write_lines(path, lines, append: bool = True) -> None:
    with open(path, "a" if append else "w", encoding="utf-8") as stream:
        stream.write("\n".join(lines) + "\n")
