"""RECU_TABLE: parameters of a result (NOM_PARA / TOUT_PARA), or a table
stored inside a concept (NOM_TABLE, looked up in the concept's ``tables``).

For a modal basis the parameters are per mode (``ModeResult.parameters``,
plus FREQ, MASS_GENE, RIGI_GENE, NUME_MODE derived from the basis); for a
transient result, the instants (INST) and their NUME_ORDRE.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.modes import ModeResult
from asterlite.concepts.table import Table, TableNotComputed
from asterlite.errors import UnsupportedError
from asterlite.post.restitution import as_tuple


def run(ctx, kw):
    source = kw["CO"]
    if kw.get("NOM_TABLE") is not None:
        tables = getattr(source, "tables", None) or {}
        name = kw["NOM_TABLE"]
        if name not in tables:
            known = ", ".join(sorted(tables)) or "none"
            ctx.error(
                f"{source.name or 'CO'} holds no table {name!r} (tables: {known})", "NOM_TABLE", kw
            )
        table = tables[name]
        if isinstance(table, TableNotComputed):
            raise UnsupportedError(
                f"table {name!r} of {source.name or 'CO'}: {table.reason}",
                table.location or ctx.location,
                table.path,
            )
        return table
    available = result_parameters(source)
    if not available:
        ctx.unsupported(f"RECU_TABLE parameters of a {source.aster_type}", "CO", kw)
    wanted = list(available) if kw.get("TOUT_PARA") == "OUI" else list(as_tuple(kw["NOM_PARA"]))
    missing = [p for p in wanted if p not in available]
    if missing:
        ctx.error(
            f"{source.name or 'CO'} has no parameter {', '.join(missing)} "
            f"(it has {', '.join(available)})",
            "NOM_PARA",
            kw,
        )
    table = Table(title=kw.get("TITRE") or "")
    table.add_column("NUME_ORDRE", "I")
    for name in wanted:
        if name != "NUME_ORDRE":
            table.add_column(name, "I" if np.asarray(available[name]).dtype.kind in "iu" else "R")
    order = available["NUME_ORDRE"]
    for i in range(len(order)):
        table.add_row({"NUME_ORDRE": int(order[i]), **{n: available[n][i] for n in wanted}})
    return table


def result_parameters(source) -> dict[str, np.ndarray]:
    """Per-order parameters of a result, by code_aster name."""
    if isinstance(source, ModeResult):
        params = {
            "NUME_ORDRE": np.arange(1, source.n_modes + 1),
            "NUME_MODE": source.mode_numbers,
            "FREQ": np.asarray(source.frequencies, dtype=float),
            "MASS_GENE": np.asarray(source.generalized_mass, dtype=float),
            "RIGI_GENE": np.asarray(source.generalized_stiffness, dtype=float),
            "OMEGA2": source.omega2,
        }
        for key, value in source.parameters.items():
            value = np.asarray(value)
            if value.shape[:1] == (source.n_modes,):
                params[key] = value
        return params
    times = getattr(source, "times", None)
    if times is not None:
        return {"NUME_ORDRE": np.asarray(source.order), "INST": np.asarray(times, dtype=float)}
    return {}
