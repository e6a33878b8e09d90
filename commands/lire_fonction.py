"""LIRE_FONCTION: a function read from columns of a text file (FORMAT='LIBRE').

The file on logical unit UNITE is cut into blocks of consecutive numeric
lines (any other line, or a blank one, ends a block); INDIC_PARA and
INDIC_RESU give (block, column), both 1-based. Fortran exponents
(``1.0D+03``) are accepted. TYPE='FONCTION_C' reads REEL_IMAG or
MODULE_PHASE (degrees) columns. A NaN or an infinity anywhere in a line of
numbers, however spelt (``nan``, ``1.#QNAN``, ``-1.#IND``, ``1.E+999``...),
is refused, naming the file, its unit, the block, the line and the column.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from asterlite.commands.defi_fonction import check_abscissas

from asterlite.concepts.function import ComplexFunction, Function
from asterlite.io.input_files import InputFileError, read_bounded_text
from asterlite.io.non_finite import NonFiniteNumber, finite_float, is_number_token


class Row(list):
    """The numbers of one line of the file, with its 1-based line number."""

    def __init__(self, values, line: int = 0):
        super().__init__(values)
        self.line = line


class NonFiniteValue(ValueError):
    """A NaN or an infinity in the file (``nan``, ``1.#QNAN``, ``1.E+999``...)."""


def file_lines(text: str) -> list[str]:
    """The lines as code_aster's ``for line in open(...)`` cuts them: at
    ``\\n``, ``\\r\\n`` and ``\\r`` only (``str.splitlines`` also cuts at
    form feeds and other separators, which ``split()`` reads as blanks)."""
    return text.replace("\r\n", "\n").replace("\r", "\n").split("\n")


def numeric_blocks(text: str, separator: str | None = None) -> list[list[Row]]:
    """Blocks of rows of floats; a line that is not all numbers closes a block,
    as in code_aster's lire_blocs. A line of numbers holding a NaN or an
    infinity, however spelt, is refused (NonFiniteValue): code_aster would
    keep a NaN, or end the block at ``1.#QNAN`` and drop what follows."""
    blocks, current = [], []
    for number, line in enumerate(file_lines(text), start=1):
        fields = line.split(separator) if separator else line.split()
        items = [item for item in fields if item.strip()]
        row = _numbers(items, number, len(blocks) + 1)
        if row:
            current.append(row)
        elif current:
            blocks.append(current)
            current = []
    if current:
        blocks.append(current)
    return blocks


def _numbers(items: list[str], line: int, block: int) -> Row | None:
    """The row of numbers ``items`` spell, or None when one is not a number
    (the line ends a block). NonFiniteValue for a line of numbers with a NaN
    or an infinity."""
    try:
        return Row([finite_float(item, fortran_exponent=True) for item in items], line)
    except NonFiniteNumber:
        if not all(is_number_token(item) for item in items):
            return None  # text mentioning "inf", say: a block separator
        column, error = next(_non_finite_items(items))
        raise NonFiniteValue(f"block {block}, line {line}, column {column}: {error}") from None
    except ValueError:
        return None


def _non_finite_items(items: list[str]):
    for column, item in enumerate(items, start=1):
        try:
            finite_float(item, fortran_exponent=True)
        except NonFiniteNumber as error:
            yield column, error


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
    return np.array([r[column_no - 1] for r in rows])


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

    try:  # rows of Python floats: about 30 bytes of memory per byte of text
        text = read_bounded_text(path, "function file", 30)
    except InputFileError as error:
        ctx.error(str(error), "UNITE", kw)
    try:
        blocks = numeric_blocks(text, separator)
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
