"""CALC_SPECTRE_IPM: oscillator spectra of floor accelerations corrected for
the floor-equipment interaction (numerics in asterlite.post.floor_spectra).

For each EQUIPEMENT and each of its nodes: the vertical (DZ) acceleration is
read from RESU/TABLE (columns INST NOEUD NOM_CHAM NOM_CMP VALE, or INST
NOEUD NOM_CHAM DZ) or taken as RESU/FONCTION; RELATIF adds the drive
acceleration ACCE_Z (re-tabulated on LIST_INST when given). A first value
above TOLE_INIT times the peak is an error, or is set to zero with an alarm
under CORR_INIT='OUI'. The corrected acceleration's spectra (pseudo-
acceleration, AMOR_SPEC, NORME, on FREQ or LIST_FREQ) fill a table with a
column 'FREQ <equipment>' and one 'IPM <equipment> [<node> ]<damping %>%'
per damping (the node only when the equipment has several), columns
sorted by name as code_aster does.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.function import Function
from asterlite.concepts.table import Table
from asterlite.post import functions as fops
from asterlite.post.floor_spectra import Equipment, corrected_acceleration
from asterlite.post.restitution import as_tuple, values_of

LONG_FORMAT = ("INST", "NOEUD", "NOM_CHAM", "NOM_CMP", "VALE")
WIDE_FORMAT = ("INST", "NOEUD", "NOM_CHAM", "DZ")


def run(ctx, kw):
    freqs = _frequencies(ctx, kw)
    if kw["CALCUL"] == "ABSOLU":
        # code_aster re-tabulates only the RELATIF sum on LIST_INST; ABSOLU ignores it
        kw.mark_used("LIST_INST")
    dampings = [float(a) for a in as_tuple(kw["AMOR_SPEC"])]
    resu = kw.factor("RESU")[0]
    columns: dict[str, list[float]] = {}
    for occ in kw.factor("EQUIPEMENT"):
        equipment = _equipment(ctx, occ)
        nodes = _node_labels(ctx, kw, occ)
        for node in nodes:
            accel = _floor_acceleration(ctx, kw, resu, node)
            accel = _checked_start(ctx, kw, accel)
            corrected = corrected_acceleration(accel, equipment)
            columns[f"FREQ {occ['NOM']}"] = freqs.tolist()
            for damping in dampings:
                spectrum = fops.response_spectrum(corrected, freqs, damping, "ACCE", kw["NORME"])
                where = f"{occ['NOM']} {node}" if len(nodes) > 1 else occ["NOM"]
                # code_aster truncates the percentage (0.05 -> 5%)
                columns[f"IPM {where} {int(damping * 100)}%"] = spectrum.tolist()
    return Table.from_columns({name: columns[name] for name in sorted(columns)})


def _frequencies(ctx, kw) -> np.ndarray:
    if kw.get("FREQ") is not None and kw.get("LIST_FREQ") is not None:
        ctx.error("give FREQ or LIST_FREQ, not both", "FREQ", kw)
    if kw.get("LIST_FREQ") is not None:
        return values_of(kw["LIST_FREQ"])
    if kw.get("FREQ") is not None:
        return values_of(kw["FREQ"])
    ctx.unsupported(
        "CALC_SPECTRE_IPM without FREQ / LIST_FREQ (SPEC_OSCI's default frequency list)",
        "LIST_FREQ",
        kw,
    )


def _equipment(ctx, occ) -> Equipment:
    fractions = tuple(float(v) for v in as_tuple(occ["COEF_MASS_EQUIP"]))
    freqs = tuple(float(v) for v in as_tuple(occ["FREQ_EQUIP"]))
    dampings = tuple(float(v) for v in as_tuple(occ["AMOR_EQUIP"]))
    if not len(fractions) == len(freqs) == len(dampings):
        ctx.error(
            f"COEF_MASS_EQUIP, FREQ_EQUIP and AMOR_EQUIP have {len(fractions)}, {len(freqs)} "
            f"and {len(dampings)} values: they must have as many",
            "COEF_MASS_EQUIP",
            occ,
        )
    if abs(sum(fractions) - 1) > 1e-4:
        ctx.error(f"COEF_MASS_EQUIP sums to {sum(fractions):.6g}, not 1", "COEF_MASS_EQUIP", occ)
    return Equipment(
        mass_ratio=float(occ["RAPPORT_MASSE_TOTALE"]),
        support_frequency=float(occ["FREQ_SUPPORT"]),
        support_damping=float(occ["AMOR_SUPPORT"]),
        mass_fractions=fractions,
        frequencies=freqs,
        dampings=dampings,
    )


def _node_labels(ctx, kw, occ) -> list[str]:
    """The nodes as the table names them: code_aster 17 names a mesh's nodes
    by their 1-based number (see asterlite.post.table_ops)."""
    if occ.get("NOEUD") is not None:
        return [str(n).strip() for n in as_tuple(occ["NOEUD"])]
    mesh = kw["MAILLAGE"]
    labels = []
    for group in as_tuple(occ["GROUP_NO"]):
        if group not in mesh.node_groups:
            ctx.error(f"the mesh has no node group {group!r}", "GROUP_NO", occ)
        labels += [str(int(n) + 1) for n in mesh.node_group(group)]
    return labels


def _floor_acceleration(ctx, kw, resu, node: str) -> Function:
    if resu.get("TABLE") is not None:
        accel = _from_table(ctx, resu, node)
    else:
        accel = resu["FONCTION"]
    if kw["CALCUL"] == "RELATIF":
        accel = fops.combine([accel, resu["ACCE_Z"]], [1.0, 1.0])
        if kw.get("LIST_INST") is not None:
            times = values_of(kw["LIST_INST"])
            accel = accel.with_values(times, accel.evaluate(times))
    return accel


def _from_table(ctx, resu, node: str) -> Function:
    table: Table = resu["TABLE"]
    long_format = all(name in table.types for name in LONG_FORMAT)
    wide_format = all(name in table.types for name in WIDE_FORMAT)
    if long_format == wide_format:
        ctx.error(
            f"the table needs the columns {', '.join(LONG_FORMAT)} or else "
            f"{', '.join(WIDE_FORMAT)} (it has {', '.join(table.columns)})",
            "TABLE",
            resu,
        )
    if "ACCE" not in _stripped(table.column("NOM_CHAM")):
        ctx.error("the table has no row with NOM_CHAM='ACCE'", "TABLE", resu)
    if long_format and "DZ" not in _stripped(table.column("NOM_CMP")):
        ctx.error("the table has no row with NOM_CMP='DZ'", "TABLE", resu)

    def wanted(row) -> bool:
        return (
            _text(row.get("NOEUD")) == node
            and _text(row.get("NOM_CHAM")) == "ACCE"
            and (not long_format or _text(row.get("NOM_CMP")) == "DZ")
            and row.get("INST") is not None
        )

    rows = [row for row in table.rows if wanted(row)]
    if not rows:
        ctx.error(f"the table has no acceleration DZ of node {node!r}", "TABLE", resu)
    value = "VALE" if long_format else "DZ"
    return Function(
        [row["INST"] for row in rows],
        [row[value] for row in rows],
        NOM_PARA="INST",
        NOM_RESU="ACCE",
    )


def _text(value) -> str | None:
    return value.strip() if isinstance(value, str) else value


def _stripped(values) -> set:
    return {_text(v) for v in values}


def _checked_start(ctx, kw, accel: Function) -> Function:
    """code_aster's check that the signal starts from rest (TOLE_INIT, CORR_INIT)."""
    values = np.asarray(accel.ordinates, dtype=float)
    ratio = abs(values[0]) / np.abs(values).max()
    if not ratio > kw["TOLE_INIT"]:
        return accel
    if kw["CORR_INIT"] != "OUI":
        ctx.error(
            f"the acceleration starts at {ratio:.4g} times its peak, above TOLE_INIT="
            f"{kw['TOLE_INIT']:g}: CORR_INIT='OUI' sets its first value to zero",
            "CORR_INIT",
            kw,
        )
    ctx.log(
        f"alarm: SPECTRAL0_16: the acceleration starts at {ratio:.4g} times its peak, above "
        f"TOLE_INIT={kw['TOLE_INIT']:g}: its first value is set to zero (CORR_INIT='OUI')"
    )
    values[0] = 0.0
    # code_aster rebuilds the function with DEFI_FONCTION's defaults
    return Function(accel.abscissas, values, NOM_PARA="INST")
