"""IMPR_TABLE: print a table (FORMAT TABLEAU or CSV) to a logical unit, after
FILTRE, with the chosen NOM_PARA columns and TRI order."""

from __future__ import annotations

from asterlite.io.tables import table_csv_lines, table_lines, write_lines
from asterlite.post.restitution import as_tuple

from .recu_fonction import filter_table


def run(ctx, kw):
    table = kw["TABLE"]
    for occ in kw.factor("FILTRE"):
        table = filter_table(ctx, table, occ)
    for occ in kw.factor("TRI"):
        names = as_tuple(occ["NOM_PARA"])
        for name in names:
            if name not in table.types:
                ctx.error(f"table has no parameter {name!r}", "NOM_PARA", occ)
        table = table.sorted_by(names, descending=occ.get("ORDRE") == "DECROISSANT")
    columns = as_tuple(kw.get("NOM_PARA")) or None
    if columns:
        missing = [c for c in columns if c not in table.types]
        if missing:
            ctx.error(f"table has no parameter {missing[0]!r}", "NOM_PARA", kw)
        table = table.select(columns)
    fmt = kw.get("FORMAT", "TABLEAU")
    if fmt == "TABLEAU":
        title = kw.get("TITRE") or f"ASTERLITE TABLE {kw['TABLE'].name or ''}".rstrip()
        real = kw.get("FORMAT_R", "E12.5")
        lines = table_lines(
            table, columns, title if isinstance(title, str) else " ".join(title), real
        )
    elif fmt == "CSV":
        lines = table_csv_lines(table, columns, kw.get("SEPARATEUR", ","))
    else:
        ctx.unsupported(f"FORMAT={fmt!r}", "FORMAT", kw)
    unit = kw.get("UNITE", 8)
    path = ctx.session.output_path(int(unit))
    write_lines(path, lines)
    ctx.log(f"table {kw['TABLE'].name or ''}: {len(table)} rows written to {path.name}")
    return None
