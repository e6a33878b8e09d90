"""Tables read from text files, as code_aster 17's LIRE_TABLE reads them.

Three layouts (FORMAT):

- ``LIBRE``: the non-blank lines are cut into blocks; a line with fewer
  fields than the line before it (when that one had more than one) starts a
  new block. In a block, the lines with the most fields are the table: the
  first of them names the columns, the others are rows; any other line of
  the block is its title.
- ``TABLEAU`` (the default): as LIBRE, with ``#`` lines as comments (a block
  may open with comments, which join its title) and ``-`` for an empty cell.
- ``ASTER``: tables between ``#DEBUT_TABLE`` and ``#FIN_TABLE`` lines; in
  one, ``#TITRE`` lines give the title, then a line of names, a line of
  types (``I``, ``R``, ``K8``...) and rows whose cells must match the types
  (a ``Kn`` cell is exactly n characters wide); ``-`` is an empty cell.

Fields are separated by one or more SEPARATEUR (a space by default; only
that character, a tab is not a space). A cell is an integer when ``int``
reads it, else a real when ``float`` reads it (also with a decimal comma),
else text. Without declared types, a column's type follows its cells: ``I``,
``R`` when integers and reals mix, ``K24`` for text; text among numbers is
an error. NUME_TABLE picks the block (1-based); RENOMME_PARA='UNIQUE'
renames a repeated column name ``A`` to ``A_1``, ``A_2``...
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

TEXT_TYPE = "K24"  # the type of a column of text without declared type
TEXT_TYPES = ("K8", "K16", "K24")  # the text types a table column may have
EMPTY_CELL = "-"
# ASTER layout: the regular expression of a cell of each declared type
_CELL_PATTERNS = {"I": r"([0-9\-\+]+)", "R": r"([0-9\.,\-\+eEdD]+)"}


class TableFileError(ValueError):
    """The text does not hold the table asked for; the message says where."""


TITLE_WIDTH = 80  # a table's title line


@dataclass
class ReadTable:
    """A table as read: column names, their type codes, sparse rows, title
    (its lines as the file gives them) and whether the title's lines are
    joined (LIBRE and TABLEAU) or kept apart (ASTER)."""

    columns: list[str]
    types: list[str | None]
    rows: list[dict[str, int | float | str]] = field(default_factory=list)
    title: str = ""
    joined_title: bool = False

    def title_line(self) -> str:
        """The one title line the table keeps, at most 80 characters: long
        lines are cut between words; in LIBRE and TABLEAU the first line gathers
        as many of the title's lines (joined by a space) as fit."""
        pieces = [piece for line in self.title.splitlines() for piece in _wrapped(line)]
        if not self.joined_title:
            return pieces[0] if pieces else ""
        first = ""
        for piece in pieces:
            candidate = f"{first} {piece}" if first else piece
            if len(candidate) > TITLE_WIDTH:
                break
            first = candidate
        return first


def _wrapped(line: str) -> list[str]:
    """``line`` cut between words into pieces of at most 80 characters (a
    longer word cut every 80 characters)."""
    if len(line) <= TITLE_WIDTH:
        return [line]
    words = [
        word[i : i + TITLE_WIDTH]
        for word in line.split(" ")
        for i in range(0, max(len(word), 1), TITLE_WIDTH)
    ]
    pieces, current = [], None
    for word in words:
        if current is not None and len(current) + 1 + len(word) <= TITLE_WIDTH:
            current = f"{current} {word}"
        else:
            if current is not None:
                pieces.append(current)
            current = word
    pieces.append(current)
    return [piece for piece in pieces if piece]


def split_fields(line: str, separator: str) -> list[str]:
    """The fields of ``line`` between runs of ``separator`` (none at its ends)."""
    return re.split(f"{re.escape(separator)}+", line.strip(separator))


def cell_value(text: str) -> int | float | str:
    """An integer, else a real (a decimal comma accepted), else the text."""
    for reader in (int, float, lambda t: float(t.replace(",", "."))):
        try:
            return reader(text)
        except ValueError:
            continue
    return text


def unique_names(names: list[str]) -> list[str]:
    """RENOMME_PARA='UNIQUE': a repeated name gets ``_1``, ``_2``... appended."""
    result: list[str] = []
    for name in names:
        candidate, count = name, 0
        while candidate in result:
            count += 1
            candidate = f"{name}_{count}"
        result.append(candidate)
    return result


def read_table(
    text: str, layout: str, separator: str = " ", number: int = 1, unique: bool = False
) -> ReadTable:
    """Table ``number`` (1-based) of ``text`` in ``layout`` (``ASTER``,
    ``LIBRE`` or ``TABLEAU``). TableFileError when the text has fewer tables,
    a row does not match its declared types, a name repeats without
    ``unique``, or a column mixes text and numbers."""
    if not separator:
        raise TableFileError("SEPARATEUR is empty")
    if layout == "ASTER":
        table = _read_aster(text, separator, number, unique)
    elif layout in ("LIBRE", "TABLEAU"):
        table = _read_free(text, separator, number, unique, comments=layout == "TABLEAU")
    else:
        raise TableFileError(f"unknown table layout {layout!r}")
    _check_columns(table)
    return table


# --------------------------------------------------------- LIBRE and TABLEAU


def _free_blocks(lines: list[str], separator: str, comments: bool) -> list[list[tuple[int, str]]]:
    """The blocks of (field count, line); a comment line opening a block counts 0."""
    blocks: list[list[tuple[int, str]]] = [[]]
    previous = 0
    has_values = False
    for line in lines:
        count = len(split_fields(line, separator))
        is_comment = comments and line.startswith("#")
        if is_comment and not has_values:
            count = 0
        elif previous > 1 and count < previous:
            blocks.append([])
            has_values = False
        previous = count
        blocks[-1].append((count, line))
        if not is_comment:
            has_values = True
    return blocks


def _read_free(text: str, separator: str, number: int, unique: bool, comments: bool) -> ReadTable:
    lines = [line for line in text.splitlines() if line.strip()]
    blocks = _free_blocks(lines, separator, comments)
    held = len(blocks) if blocks[0] else 0
    if number > held:
        raise TableFileError(f"table {number} asked for, the file holds {held}")
    block = blocks[number - 1]
    width = max(count for count, _ in block)
    body, title = [], []
    for count, line in block:
        if count == width and not (comments and line.startswith("#")):
            body.append(line)
        else:
            title.append(line)
    if not body:
        raise TableFileError(f"table {number} has no line of column names")
    # with a separator other than a space a name may hold spaces: not in a table
    names = [name.replace(" ", "_") for name in split_fields(body[0], separator)]
    table = ReadTable(
        _named(names, unique, number), [None] * width, title="\n".join(title), joined_title=True
    )
    empty = EMPTY_CELL if comments else ""
    for line in body[1:]:
        cells = split_fields(line, separator)
        table.rows.append(
            {
                name: cell_value(cell.strip())
                for name, cell in zip(table.columns, cells, strict=True)
                if cell.strip() != empty
            }
        )
    _infer_types(table)
    return table


def _infer_types(table: ReadTable) -> None:
    """Each column's type from its cells: I, R (integers and reals), K24 (text)."""
    for index, name in enumerate(table.columns):
        kinds = set()
        for line, row in enumerate(table.rows, start=1):
            if name not in row:
                continue
            value = row[name]
            kind = "K" if isinstance(value, str) else ("I" if isinstance(value, int) else "R")
            if kinds and ("K" in kinds) != (kind == "K"):
                raise TableFileError(
                    f"column {name!r} mixes text and numbers (row {line}: {value!r})"
                )
            kinds.add(kind)
        if kinds == {"K"}:
            table.types[index] = TEXT_TYPE
        elif kinds:
            table.types[index] = "R" if "R" in kinds else "I"
    for index, code in enumerate(table.types):
        if code == "R":
            name = table.columns[index]
            for row in table.rows:
                if name in row:
                    row[name] = float(row[name])


# --------------------------------------------------------------------- ASTER


_ASTER_TABLE = re.compile(r"#DEBUT_TABLE\n(.*?)#FIN_TABLE\n", re.MULTILINE | re.DOTALL)


def _read_aster(text: str, separator: str, number: int, unique: bool) -> ReadTable:
    tables = _ASTER_TABLE.findall(text.replace("\r\n", "\n"))
    if number > len(tables):
        raise TableFileError(
            f"table {number} asked for, the file holds {len(tables)} (#DEBUT_TABLE ... #FIN_TABLE)"
        )
    body = tables[number - 1]
    title = "\n".join(
        line[len("#TITRE") :].strip(separator)
        for line in body.splitlines()
        if line.startswith("#TITRE")
    )
    lines = [
        line
        for line in body.splitlines()
        if line.strip(separator) and not line.startswith("#TITRE")
    ]
    if len(lines) < 2:
        raise TableFileError(f"table {number} lacks its line of names or of types")
    names = split_fields(lines[0], separator)
    types = split_fields(lines[1], separator)
    if len(types) != len(names):
        raise TableFileError(f"table {number}: {len(names)} column names but {len(types)} types")
    patterns = []
    for name, code in zip(names, types, strict=True):
        if code in _CELL_PATTERNS:
            patterns.append(_CELL_PATTERNS[code])
        elif code[:1] == "K" and code[1:].isdigit():
            patterns.append(f"(.{{{code[1:]}}})")
        else:
            raise TableFileError(f"table {number}: column {name!r} has the unknown type {code!r}")
    # code_aster searches the pattern anywhere in the line, so that "1.5 2"
    # under types I R reads A=5: the whole line must match here
    gap = re.escape(separator)
    line_pattern = re.compile(f"{gap}*" + f"{gap}+".join(patterns) + rf"{gap}*\s*")
    # code_aster keeps a text column of another width as K24
    codes = [code if code[0] != "K" or code in TEXT_TYPES else TEXT_TYPE for code in types]
    table = ReadTable(_named(names, unique, number), codes, title=title)
    for index, line in enumerate(lines[2:], start=1):
        match = line_pattern.fullmatch(line)
        if match is None:
            raise TableFileError(
                f"table {number}, row {index}: {line.strip()!r} does not match the "
                f"{len(names)} columns of types {' '.join(types)}"
            )
        row = {}
        for name, code, cell in zip(table.columns, types, match.groups(), strict=True):
            cell = cell.strip()
            if cell == EMPTY_CELL:
                continue
            row[name] = cell if code[0] == "K" else _typed_number(cell, code, name, index)
        table.rows.append(row)
    return table


def _typed_number(cell: str, code: str, name: str, row: int) -> int | float:
    value = cell_value(cell)
    if isinstance(value, str) or (code == "I" and isinstance(value, float)):
        raise TableFileError(f"row {row}, column {name!r} of type {code}: {cell!r} is not read")
    return float(value) if code == "R" else value


# ------------------------------------------------------------------ common


def _named(names: list[str], unique: bool, number: int) -> list[str]:
    if unique:
        return unique_names(names)
    repeated = next((name for name in names if names.count(name) > 1), None)
    if repeated is not None:
        raise TableFileError(
            f"table {number}: the column name {repeated!r} repeats (RENOMME_PARA='UNIQUE' "
            "renames repeats)"
        )
    return names


def _check_columns(table: ReadTable) -> None:
    """A real column holds finite numbers only. A column of declared type
    without any cell is left out (as code_aster's CREA_TABLE leaves it); one
    whose type no cell tells is an error, and so is a table left empty."""
    kept = [
        (name, code)
        for name, code in zip(table.columns, table.types, strict=True)
        if any(name in row for row in table.rows)
    ]
    untyped = [name for name in table.columns if name not in dict(kept)]
    if untyped and table.types[table.columns.index(untyped[0])] is None:
        raise TableFileError(f"column {untyped[0]!r} has no value: its type is unknown")
    if not kept:
        raise TableFileError("the table has no value")
    table.columns = [name for name, _ in kept]
    table.types = [code for _, code in kept]
    for name, code in kept:
        if code == "R":
            for line, row in enumerate(table.rows, start=1):
                if name in row and not math.isfinite(row[name]):
                    raise TableFileError(f"column {name!r}, row {line}: {row[name]} is not finite")
