"""LIRE_FONCTION: a function read from columns of a text file (FORMAT='LIBRE').

The file on logical unit UNITE is cut into blocks of consecutive numeric
lines (any other line, or a blank one, ends a block); INDIC_PARA and
INDIC_RESU give (block, column), both 1-based. Fortran exponents
(``1.0D+03``) are accepted. TYPE='FONCTION_C' reads REEL_IMAG or
MODULE_PHASE (degrees) columns. A NaN or an infinity in a column read is
refused, naming the file, its unit, the block and the line.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
from asterlite.commands.defi_fonction import check_abscissas

from asterlite.concepts.function import ComplexFunction, Function


class Row(list):
    """The numbers of one line of the file, with its 1-based line number."""

    def __init__(self, values, line: int = 0):
        super().__init__(values)
        self.line = line


class NonFiniteValue(ValueError):
    """A column read holds a NaN or an infinity (``nan``, ``inf``, ``1.E+999``)."""


def numeric_blocks(text: str, separator: str | None = None) -> list[list[Row]]:
    """Blocks of rows of floats; a line that is not all numbers closes a block."""
    text = re.sub(r"(\d\.?)[dD]([+-]?\d)", r"\1E\2", text)
    blocks, current = [], []
    for number, line in enumerate(text.splitlines(), start=1):
        items = line.split(separator) if separator else line.split()
        try:
            row = Row([float(item) for item in items if item.strip()], number)
        except ValueError:
            row = []
        if row:
            current.append(row)
        elif current:
            blocks.append(current)
            current = []
    if current:
        blocks.append(current)
    return blocks


def column(blocks, indices, what: str) -> np.ndarray:
    block_no, column_no = (int(i) for i in indices)
    if not 1 <= block_no <= len(blocks):
        raise ValueError(f"{what}: block {block_no} does not exist (the file has {len(blocks)})")
    rows = blocks[block_no - 1]
    if any(len(r) < column_no for r in rows):
        width = min(len(r) for r in rows)
        raise ValueError(
            f"{what}: column {column_no} does not exist (block {block_no} has {width})"
        )
    values = np.array([r[column_no - 1] for r in rows])
    bad = np.flatnonzero(~np.isfinite(values))
    if bad.size:
        row = rows[int(bad[0])]
        line = getattr(row, "line", 0)
        where = f"block {block_no}, line {line}" if line else f"block {block_no}"
        raise NonFiniteValue(
            f"{what}: {where}, column {column_no} holds {values[bad[0]]!r}: "
            "a finite number is expected"
        )
    return values


def run(ctx, kw):
    if kw.get("FORMAT", "LIBRE") != "LIBRE":
        ctx.unsupported(f"LIRE_FONCTION FORMAT={kw['FORMAT']}", "FORMAT", kw)
    if kw.get("TYPE", "FONCTION") == "NAPPE":
        ctx.unsupported("LIRE_FONCTION TYPE='NAPPE'", "TYPE", kw)
    path = Path(ctx.session.input_path(int(kw["UNITE"])))
    if not path.exists():
        ctx.error(f"file {path} (unit {kw['UNITE']}) does not exist", "UNITE", kw)
    separator = kw.get("SEPARATEUR")
    separator = None if separator in (None, "None", " ", "") else separator
    from asterlite.io.input_files import InputFileError, read_bounded_text

    try:  # rows of Python floats: about 30 bytes of memory per byte of text
        text = read_bounded_text(path, "function file", 30)
    except InputFileError as error:
        ctx.error(str(error), "UNITE", kw)
    blocks = numeric_blocks(text, separator)
    try:
        x = column(blocks, kw.get("INDIC_PARA", (1, 1)), "INDIC_PARA")
        if kw.get("TYPE", "FONCTION") == "FONCTION_C":
            y = complex_column(blocks, kw)
        else:
            y = column(blocks, kw.get("INDIC_RESU", (1, 2)), "INDIC_RESU")
    except NonFiniteValue as exc:
        ctx.error(f"file {path.name} (unit {kw['UNITE']}): {exc}", "UNITE", kw)
    except ValueError as exc:
        ctx.error(f"{path.name}: {exc}", "INDIC_PARA", kw)
    if x.size != y.size:
        ctx.error(f"{x.size} abscissas but {y.size} ordinates in {path.name}", "INDIC_RESU", kw)
    check_abscissas(ctx, kw, x)
    cls = ComplexFunction if np.iscomplexobj(y) else Function
    return cls(
        x,
        y,
        NOM_PARA=kw["NOM_PARA"],
        NOM_RESU=kw.get("NOM_RESU", "TOUTRESU"),
        INTERPOL=kw.get("INTERPOL", ("LIN", "LIN")),
        PROL_GAUCHE=kw.get("PROL_GAUCHE", "EXCLU"),
        PROL_DROITE=kw.get("PROL_DROITE", "EXCLU"),
        title=kw.get("TITRE") or "",
    )


def complex_column(blocks, kw) -> np.ndarray:
    if kw.get("FORMAT_C", "REEL_IMAG") == "MODULE_PHASE":
        modulus = column(blocks, kw.get("INDIC_MODU", (1, 2)), "INDIC_MODU")
        phase = np.radians(column(blocks, kw.get("INDIC_PHAS", (1, 3)), "INDIC_PHAS"))
        return modulus * np.exp(1j * phase)
    real = column(blocks, kw.get("INDIC_REEL", (1, 2)), "INDIC_REEL")
    imag = column(blocks, kw.get("INDIC_IMAG", (1, 3)), "INDIC_IMAG")
    return real + 1j * imag
