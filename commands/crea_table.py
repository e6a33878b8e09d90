"""CREA_TABLE: a table from lists (LISTE: PARA + LISTE_R / LISTE_I / LISTE_K
/ LISTE_CO) or from a function (FONCTION: its abscissas and ordinates)."""

from __future__ import annotations

from asterlite.concepts.table import Table
from asterlite.post.restitution import as_tuple


def run(ctx, kw):
    table = Table(title=kw.get("TITRE") or "")
    if kw.factor("LISTE"):
        columns = {}
        for occ in kw.factor("LISTE"):
            given = [
                (key, code)
                for key, code in (("LISTE_R", "R"), ("LISTE_I", "I"), ("LISTE_K", "K24"))
                if occ.get(key) is not None
            ]
            if not given:
                ctx.unsupported("LISTE without LISTE_R, LISTE_I or LISTE_K", None, occ)
            key, code = given[0]
            values = list(as_tuple(occ[key]))
            if occ.get("NUME_LIGN") is not None:
                lines = [int(n) - 1 for n in as_tuple(occ["NUME_LIGN"])]
                if len(lines) != len(values):
                    ctx.error("NUME_LIGN and the values differ in length", "NUME_LIGN", occ)
                spread = [None] * (max(lines) + 1)
                for line, value in zip(lines, values, strict=True):
                    spread[line] = value
                values = spread
            columns[occ["PARA"]] = (values, code)
        for name, (_, code) in columns.items():
            table.add_column(name, code)
        n_rows = max(len(v) for v, _ in columns.values())
        for i in range(n_rows):
            table.add_row({n: (v[i] if i < len(v) else None) for n, (v, _) in columns.items()})
        return table
    if kw.factor("FONCTION"):
        occ = kw.factor("FONCTION")[0]
        func = occ["FONCTION"]
        para = as_tuple(occ.get("PARA")) or (func.NOM_PARA, func.NOM_RESU)
        table.add_column(para[0], "R")
        table.add_column(para[1], "R")
        for x, y in zip(func.abscissas, func.ordinates, strict=True):
            table.add_row({para[0]: float(x), para[1]: y})
        return table
    which = next((k for k in ("RESU", "TITRE") if kw.get(k)), "source")
    ctx.unsupported(f"CREA_TABLE from {which}", which, kw)
