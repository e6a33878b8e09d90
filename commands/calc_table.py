"""CALC_TABLE: ACTION occurrences applied in order to a copy of TABLE
(numerics in asterlite.post.table_ops)."""

from __future__ import annotations

from asterlite.errors import CommandError
from asterlite.post import table_ops as ops
from asterlite.post.restitution import as_tuple


def run(ctx, kw):
    table = ops.copy_table(kw["TABLE"])
    for occ in kw.factor("ACTION"):
        try:
            table = apply(ctx, table, occ)
        except CommandError as exc:
            ctx.error(exc.message, "OPERATION", occ)
    if kw.get("TITRE"):
        table.title = kw["TITRE"]
    if ctx.reuse is not None and ctx.reuse is kw["TABLE"]:
        # reuse=: the deck keeps the same concept, updated in place
        target = ctx.reuse
        target.assign(table)
        return target
    return table


def filter_value(occ):
    for key in ("VALE", "VALE_I", "VALE_K", "VALE_C"):
        if occ.get(key) is not None:
            return as_tuple(occ[key])
    return None


def apply(ctx, table, occ):
    operation = occ["OPERATION"]
    names = as_tuple(occ.get("NOM_PARA"))
    match operation:
        case "FILTRE":
            return table.filtered(
                occ["NOM_PARA"],
                occ.get("CRIT_COMP", "EQ"),
                filter_value(occ),
                float(occ.get("PRECISION", 1e-3)),
                occ.get("CRITERE", "RELATIF"),
            )
        case "EXTR":
            return table.select(names)
        case "SUPPRIME":
            return ops.drop_columns(table, names)
        case "RENOMME":
            return ops.rename(table, names[0], names[1])
        case "TRI":
            return table.sorted_by(names, descending=occ.get("ORDRE") == "DECROISSANT")
        case "UNIQUE":
            return ops.unique_rows(table, names)
        case "COMB":
            return ops.merge(table, occ["TABLE"], names, occ.get("RESTREINT") == "OUI")
        case "AJOUT_LIGNE":
            return ops.add_row(table, names, as_tuple(occ["VALE"]))
        case "AJOUT_COLONNE":
            column = occ.get("VALE_COLONNE")
            return ops.add_column(
                table,
                names,
                as_tuple(occ.get("VALE")),
                None if column is None else as_tuple(column),
            )
        case "OPER":
            return ops.formula_column(
                table, occ["FORMULE"], occ["NOM_PARA"], as_tuple(occ.get("NOM_COLONNE"))
            )
        case "CALCUL":
            return ops.statistics(table, names, as_tuple(occ["TYPE_CALCUL"]))
    ctx.unsupported(f"CALC_TABLE OPERATION={operation}", "OPERATION", occ)
