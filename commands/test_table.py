"""TEST_TABLE: check one value (or a TYPE_TEST reduction) of a table column,
after the FILTRE conditions. Verdicts: ``asterlite.post.checks``."""

from __future__ import annotations

import numpy as np

from asterlite.post.checks import record_check, reduce_values

from .recu_fonction import filter_table

EXTREMES = ("MAXI", "MAXI_ABS", "MINI", "MINI_ABS")


def run(ctx, kw):
    table = kw["TABLE"]
    para = kw["NOM_PARA"]
    filters = kw.factor("FILTRE")
    for occ in filters:
        table = filter_table(ctx, table, occ)
        if occ.get("CRIT_COMP") in EXTREMES and len(table) > 1:
            # code_aster's TEST_TABLE keeps the first row reaching the extreme
            # (its Python tables, CALC_TABLE's, keep every tie)
            table = table.first_rows(1)
    if para not in table.types:
        ctx.error(
            f"table has no parameter {para!r} (it has {', '.join(table.columns)})", "NOM_PARA", kw
        )
    values = [v for v in table.column(para) if v is not None]
    conditions = " ".join(describe_filter(o) for o in filters)
    label = f"{kw['TABLE'].name or '?'} {para}" + (f" [{conditions}]" if conditions else "")
    type_test = kw.get("TYPE_TEST")
    if type_test is not None:
        if not values:
            ctx.error("no row left after FILTRE", "FILTRE", kw)
        value = reduce_values(np.asarray(values), type_test)
        label += f" {type_test}"
    else:
        if not values:
            ctx.error(f"no value of {para} left after FILTRE", "FILTRE", kw)
        if len(values) > 1:
            ctx.error(
                f"{len(values)} rows remain after FILTRE: add filters or TYPE_TEST", "FILTRE", kw
            )
        value = values[0]
    record_check(ctx, label, value, kw)
    return None


def describe_filter(occ) -> str:
    for key in ("VALE_K", "VALE_I", "VALE", "VALE_C"):
        if occ.get(key) is not None:
            return f"{occ['NOM_PARA']}={occ[key]}"
    return f"{occ['NOM_PARA']} {occ.get('CRIT_COMP', 'EQ')}"
