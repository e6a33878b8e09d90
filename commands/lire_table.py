"""LIRE_TABLE: a table read from the file on logical unit UNITE, in layout
FORMAT (TABLEAU, LIBRE or ASTER: :mod:`asterlite.io.table_reader`)."""

from __future__ import annotations

from pathlib import Path

from asterlite.concepts.table import Table
from asterlite.io.input_files import InputFileError, read_bounded_text
from asterlite.io.table_reader import TableFileError, read_table


def run(ctx, kw):
    kw.mark_used("INFO")  # the listing only
    unit = int(kw["UNITE"])
    path = Path(ctx.session.input_path(unit))
    if not path.exists():
        ctx.error(f"file {path} (unit {unit}) does not exist", "UNITE", kw)
    number = int(kw.get("NUME_TABLE", 1))
    if number < 1:
        ctx.error(f"NUME_TABLE={number}: tables are numbered from 1", "NUME_TABLE", kw)
    try:  # rows of Python values: about 30 bytes of memory per byte of text
        text = read_bounded_text(path, "table file", 30)
    except InputFileError as error:
        ctx.error(str(error), "UNITE", kw)
    try:
        read = read_table(
            text,
            kw.get("FORMAT", "TABLEAU"),
            kw.get("SEPARATEUR", " "),
            number,
            unique=kw.get("RENOMME_PARA") == "UNIQUE",
        )
    except TableFileError as error:
        ctx.error(f"file {path.name} (unit {unit}): {error}", "FORMAT", kw)
    # code_aster's table keeps the first line of the title read, unless TITRE
    title = kw.get("TITRE") or read.title_line()
    table = Table(title=title)
    for name, code in zip(read.columns, read.types, strict=True):
        table.add_column(name, code)
    # code_aster's CREA_TABLE places cells by row number: rows after the last
    # cell of any column are not made
    while read.rows and not read.rows[-1]:
        read.rows.pop()
    for row in read.rows:
        table.add_row({name: row.get(name) for name in read.columns})
    ctx.log(f"{len(table)} rows, {len(table.columns)} parameters read from unit {unit}")
    return table
