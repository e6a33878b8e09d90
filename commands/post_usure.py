"""POST_USURE: wear volumes and depths of a tube and its obstacle.

The wear power comes from PUIS_USURE or from the shock history of NOEUD in
RESU_GENE (Archard power, NB_BLOC blocks); the law (ARCHARD, KWU_EPRI,
EDF_MZ) gives volumes at INST·COEF_INST; the CONTACT geometry gives the tube
depth. With SECTEUR, the power is split by angular sector of the contact
point and the table holds one row per (instant, sector). TUBE_NEUF resets
the tube wear of a reused table from INST on. Numerics: asterlite.post.wear.
"""

from __future__ import annotations

import re

import numpy as np

from asterlite.concepts.table import Table
from asterlite.errors import CommandError
from asterlite.post import wear
from asterlite.post.restitution import as_tuple, values_of

GLOBAL_COLUMNS = ("PUIS_USUR_GLOBAL", "INST", "V_USUR_TUBE", "V_USUR_OBST", "P_USUR_TUBE")
SECTOR_COLUMNS = (
    "PUIS_USUR_GLOBAL", "INST", "DUREE", "ORIG_INST", "V_USUR_TUBE", "V_USUR_OBST",
    "P_USUR_TUBE", "SECTEUR", "ANGLE_DEBUT", "ANGLE_FIN", "V_USUR_TUBE_SECT",
    "V_USUR_OBST_SECT", "P_USUR_TUBE_SECT", "P_USUR_OBST_SECT", "V_USUR_TUBE_CUMU",
    "V_USUR_OBST_CUMU",
)  # fmt: skip


def run(ctx, kw):
    try:
        if kw.get("TUBE_NEUF") == "OUI":
            return new_tube(ctx, kw)
        return wear_table(ctx, kw)
    except CommandError as exc:
        if exc.location is None:
            ctx.error(exc.message, None, kw)
        raise


# ------------------------------------------------------------------ inputs


def shock_of(ctx, kw):
    """The shock history of NOEUD / GROUP_NO in RESU_GENE."""
    result = kw["RESU_GENE"]
    shocks = [s for s in result.shocks if s.relation in ("DIS_CHOC", "FLAMBAGE")]
    if not shocks:
        ctx.error(f"{result.name or 'RESU_GENE'} has no shock nonlinearity", "RESU_GENE", kw)
    wanted = kw.get("NOEUD") or kw.get("GROUP_NO")
    for shock in shocks:
        if wanted in (shock.node_1, shock.name):
            return shock
    # code_aster also accepts a node by its number ("6", "N6" for the 6th node)
    number = re.sub(r"^\D*", "", str(wanted))
    for shock in shocks:
        if number and re.sub(r"^\D*", "", str(shock.node_1)) == number:
            return shock
    known = ", ".join(str(s.node_1) for s in shocks)
    ctx.error(f"no shock at node {wanted!r} in RESU_GENE (shocks at {known})", "NOEUD", kw)


def shock_window(shock, times, kw):
    """Samples between INST_INIT and INST_FIN (first archived instant at or after each)."""
    t = np.asarray(times, dtype=float)
    start = kw.get("INST_INIT")
    stop = kw.get("INST_FIN")
    first = 0 if start is None or start < 0 else int(np.argmax(t >= min(start, t[-1])))
    last = t.size - 1 if stop is None else int(np.argmax(t >= min(stop, t[-1])))
    if first >= last:
        raise CommandError("POST_USURE: INST_INIT must be before INST_FIN")
    window = slice(first, last + 1)
    fields = shock.fields
    zeros = np.zeros(t.size)
    adherence = fields.get("ADHERENCE", fields.get("IADH"))
    return {
        "t": t[window],
        "fn": np.asarray(fields.get("FN", zeros))[window],
        "vt1": np.asarray(fields.get("VT1", zeros))[window],
        "vt2": np.asarray(fields.get("VT2", zeros))[window],
        "dy": np.asarray(fields.get("DYLOC", zeros))[window],
        "dz": np.asarray(fields.get("DZLOC", zeros))[window],
        "adherence": None if adherence is None else np.asarray(adherence)[window],
    }


def instants(kw) -> np.ndarray:
    if kw.get("INST") is not None:
        return values_of(kw["INST"])
    return values_of(kw["LIST_INST"])


def geometry_of(kw) -> wear.ContactGeometry:
    return wear.ContactGeometry(
        kind=kw.get("CONTACT") or "",
        r_mobile=kw.get("RAYON_MOBILE"),
        r_obstacle=kw.get("RAYON_OBST"),
        width=kw.get("LARGEUR_OBST"),
        incline=kw.get("ANGL_INCLI"),
        isthmus=kw.get("ANGL_ISTHME"),
        impact=kw.get("ANGL_IMPACT"),
    )


def _occurrence(kw, name):
    occurrences = kw.factor(name)
    return occurrences[0] if occurrences else None


# ------------------------------------------------------------ wear volumes


def law_volumes(ctx, kw, power, seconds, history) -> tuple[np.ndarray, np.ndarray]:
    """Worn volumes of the mobile and of the obstacle (zero when the deck
    gives no coefficient for the obstacle)."""
    law = kw["LOI_USURE"]
    contact = kw.get("CONTACT") or ""
    material = kw.get("MATER_USURE")
    obstacle_from_bank = kw.get("USURE_OBST") == "OUI"
    mobile, obstacle = _occurrence(kw, "MOBILE"), _occurrence(kw, "OBSTACLE")
    zeros = np.zeros_like(seconds)

    if law == "ARCHARD":
        if mobile is not None:
            k_mobile = mobile["COEF_USURE"]
        else:
            k_mobile = wear.bank_entry(wear.ARCHARD_BANK, contact, material, law)[0]
        if obstacle is not None:
            k_obst = obstacle["COEF_USURE"]
        elif obstacle_from_bank and material:
            k_obst = wear.bank_entry(wear.ARCHARD_BANK, contact, material, law)[1]
        else:
            k_obst = None
        if k_mobile is None:
            ctx.error(f"MATER_USURE={material!r}: no mobile coefficient", "MATER_USURE", kw)
        v_obst = zeros if k_obst is None else wear.archard_volume(k_obst, power, seconds)
        return wear.archard_volume(k_mobile, power, seconds), v_obst

    if law == "KWU_EPRI":
        if history is None:
            ctx.error("KWU_EPRI needs the shock history of RESU_GENE", "LOI_USURE", kw)

        def volume(occ, from_bank):
            coefs = dict(occ or {})
            if from_bank:
                bank = wear.bank_entry(wear.KWU_BANK, contact, material, law)
                coefs.update(
                    zip(
                        ("COEF_USURE", "COEF_FNOR", "COEF_VTAN", "COEF_K", "COEF_C"),
                        bank,
                        strict=True,
                    )
                )
            if coefs.get("COEF_USURE") is None:
                return None
            w = wear.kwu_weight(
                history["fn"],
                np.hypot(history["vt1"], history["vt2"]),
                coefs.get("COEF_FNOR"),
                coefs.get("COEF_VTAN"),
                coefs.get("COEF_K", 5.0),
                coefs.get("COEF_C", 10.0),
                kw.get("FNOR_MAXI"),
                kw.get("VTAN_MAXI"),
            )
            return coefs["COEF_USURE"] * w * power * seconds

        v_mobile = volume(mobile, material is not None)
        if v_mobile is None:
            ctx.error("KWU_EPRI needs MOBILE/COEF_USURE or MATER_USURE", "MOBILE", kw)
        v_obst = volume(obstacle, material is not None and obstacle_from_bank)
        if material is not None and not obstacle_from_bank:
            v_obst = None
        return v_mobile, zeros if v_obst is None else v_obst

    # EDF_MZ
    def mz_volume(occ, from_bank):
        coefs = dict(occ or {})
        if from_bank:
            bank = wear.bank_entry(wear.EDF_MZ_BANK, contact, material, law)
            coefs.update(zip(("COEF_USURE", "COEF_S", "COEF_B", "COEF_N"), bank, strict=True))
        return wear.edf_mz_volume(
            power,
            seconds,
            a=coefs.get("COEF_USURE", 1.0e-13),
            b=coefs.get("COEF_B", 1.2),
            n=coefs.get("COEF_N", 2.44e-8),
            s=coefs.get("COEF_S", 1.14e-16),
        )

    v_mobile = mz_volume(mobile, material is not None)
    if material is not None:
        v_obst = mz_volume(None, True) if obstacle_from_bank else zeros
    else:
        v_obst = zeros if obstacle is None else mz_volume(obstacle, False)
    return v_mobile, v_obst


# ------------------------------------------------------------------ tables


def wear_table(ctx, kw):
    times = instants(kw)
    coef_inst = float(kw.get("COEF_INST", 1.0))
    seconds = times * coef_inst
    history = None
    if kw.get("RESU_GENE") is not None:
        result = kw["RESU_GENE"]
        shock = shock_of(ctx, kw)
        history = shock_window(shock, result.times, kw)
        power = wear.wear_power(
            history["t"], history["fn"], history["vt1"], history["vt2"],
            history["adherence"], kw.get("NB_BLOC", 1),
        )  # fmt: skip
    else:
        power = float(kw["PUIS_USURE"])
    ctx.log(f"wear power: {power:.6e} W")
    if kw.factor("SECTEUR"):
        return sector_table(ctx, kw, power, times, seconds, history)

    table = Table(title=kw.get("TITRE") or "")
    for name in GLOBAL_COLUMNS:
        table.add_column(name, "R")
    table.add_row({"PUIS_USUR_GLOBAL": power})
    if power <= np.finfo(float).eps:
        v_tube = v_obst = depth = np.zeros_like(seconds)
    else:
        v_tube, v_obst = law_volumes(ctx, kw, power, seconds, history)
        depth = wear.tube_depth(geometry_of(kw), v_tube, v_obst)
    for t, vt, vo, p in zip(times, v_tube, v_obst, depth, strict=True):
        table.add_row({"INST": t, "V_USUR_TUBE": vt, "V_USUR_OBST": vo, "P_USUR_TUBE": p})
    return table


def sector_bounds(ctx, kw) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Sector angles (n+1, from -180 to 180) and the mobile/obstacle coefficients."""
    sectors = kw.factor("SECTEUR")
    start = sectors[0].get("ANGL_INIT")
    if start is None or abs(start + 180.0) > 1e-4:
        ctx.error("the first SECTEUR must start at ANGL_INIT=-180", "SECTEUR", kw)
    bounds = [start] + [occ.get("ANGL_FIN") for occ in sectors]
    if any(b is None for b in bounds) or np.any(np.diff(bounds) < 0):
        ctx.error("SECTEUR angles (ANGL_FIN) must increase", "SECTEUR", kw)
    if abs(bounds[-1] - 180.0) > 1e-4:
        ctx.error("the last SECTEUR must end at ANGL_FIN=180", "SECTEUR", kw)

    def coefficients(key):
        return np.array([occ.get(key) or 0.0 for occ in sectors])

    return np.array(bounds), coefficients("COEF_USUR_MOBILE"), coefficients("COEF_USUR_OBST")


def sector_table(ctx, kw, power, times, seconds, history):
    bounds, k_mobile, k_obst = sector_bounds(ctx, kw)
    n_sect = bounds.size - 1
    v_tube_sect = np.zeros((times.size, n_sect))
    v_obst_sect = np.zeros((times.size, n_sect))
    v_tube = np.zeros(times.size)
    v_obst = np.zeros(times.size)
    if power > np.finfo(float).eps:
        if history is None:
            ctx.error("SECTEUR needs the shock history of RESU_GENE", "SECTEUR", kw)
        if kw["LOI_USURE"] != "ARCHARD":
            ctx.unsupported(f"SECTEUR with LOI_USURE={kw['LOI_USURE']}", "LOI_USURE", kw)
        angle = wear.contact_angle(history["dy"], history["dz"])
        split = wear.sector_power(
            history["t"], history["fn"], history["vt1"], history["vt2"], angle, bounds,
            kw.get("NB_BLOC", 1),
        )  # fmt: skip
        share = split.power * split.presence
        v_tube_sect = np.outer(seconds, k_mobile * share)
        v_obst_sect = np.outer(seconds, k_obst * share)
        v_tube = split.weighted(k_mobile) * seconds
        v_obst = split.weighted(k_obst) * seconds
    width = kw.get("LARGEUR_OBST") or 0.011
    spans = np.diff(bounds)
    if kw.get("RAYON_MOBILE") is None:
        ctx.error("SECTEUR needs RAYON_MOBILE", "RAYON_MOBILE", kw)
    if kw.get("RAYON_OBST") is None:
        ctx.error("SECTEUR needs RAYON_OBST", "RAYON_OBST", kw)
    p_tube_sect = wear.sector_depth(kw["RAYON_MOBILE"], v_tube_sect, width, spans[None, :])
    p_obst_sect = wear.sector_depth(kw["RAYON_OBST"], v_obst_sect, width, spans[None, :])

    reused = _occurrence(kw, "ETAT_INIT")
    table, origin, cumul_tube, cumul_obst = restart_from(ctx, kw, reused, n_sect)
    table.add_row({"PUIS_USUR_GLOBAL": power})
    for k, t in enumerate(times):
        common = {"INST": t + origin, "DUREE": t, "ORIG_INST": origin}
        table.add_row(
            {**common, "V_USUR_TUBE": v_tube[k], "V_USUR_OBST": v_obst[k], "P_USUR_TUBE": 0.0}
        )
        for i in range(n_sect):
            table.add_row(
                {
                    **common,
                    "SECTEUR": i + 1,
                    "ANGLE_DEBUT": bounds[i],
                    "ANGLE_FIN": bounds[i + 1],
                    "V_USUR_TUBE_SECT": v_tube_sect[k, i],
                    "V_USUR_OBST_SECT": v_obst_sect[k, i],
                    "P_USUR_TUBE_SECT": p_tube_sect[k, i],
                    "P_USUR_OBST_SECT": p_obst_sect[k, i],
                    "V_USUR_TUBE_CUMU": v_tube_sect[k, i] + cumul_tube[i],
                    "V_USUR_OBST_CUMU": v_obst_sect[k, i] + cumul_obst[i],
                }
            )
    return table


def _empty_sector_table(title: str) -> Table:
    table = Table(title=title)
    for name in SECTOR_COLUMNS:
        table.add_column(name, "I" if name == "SECTEUR" else "R")
    return table


def restart_from(ctx, kw, occ, n_sect):
    """ETAT_INIT: continue a wear table (reused) from its last instant (or
    INST_INIT, the later rows dropped), adding its cumulated volumes."""
    zeros = np.zeros(n_sect)
    if occ is None or occ.get("TABL_USURE") is None:
        return _empty_sector_table(kw.get("TITRE") or ""), 0.0, zeros, zeros
    table = occ["TABL_USURE"]
    if ctx.reuse is not table:
        ctx.error("ETAT_INIT/TABL_USURE must be the reused table (reuse=)", "ETAT_INIT", kw)
    for name in ("INST", "SECTEUR", "V_USUR_TUBE_CUMU", "V_USUR_OBST_CUMU"):
        table.require(name)
    insts = [v for v in table.column("INST") if v is not None]
    sectors = [v for v in table.column("SECTEUR") if v is not None]
    if not insts or sectors[-1] != n_sect:
        ctx.error("the reused wear table has another number of sectors", "ETAT_INIT", kw)
    origin = insts[-1]
    start = occ.get("INST_INIT")
    if start is not None and start < origin:
        instants = table.column("INST")
        kept = [i for i, t in enumerate(instants) if t is None or t <= start * (1 + 1e-3)]
        table.keep_rows(kept)
        origin = [instants[i] for i in kept if instants[i] is not None][-1]

    def cumul(name):
        out = np.zeros(n_sect)
        for row in table.rows:
            inst, sector = row.get("INST"), row.get("SECTEUR")
            if sector is not None and inst is not None and abs(inst - origin) <= 1e-3 * abs(origin):
                out[int(sector) - 1] = row.get(name, 0.0)
        return out

    return table, origin, cumul("V_USUR_TUBE_CUMU"), cumul("V_USUR_OBST_CUMU")


def new_tube(ctx, kw):
    """TUBE_NEUF: the tube is replaced at INST: its wear (volumes, depths,
    cumulated volumes) is reset at that instant and after."""
    table = kw["TABL_USURE"]
    if ctx.reuse is not table:
        ctx.error("TUBE_NEUF needs reuse= of the TABL_USURE table", "TABL_USURE", kw)
    for name in ("INST", "SECTEUR", "V_USUR_TUBE", "P_USUR_TUBE", "V_USUR_TUBE_SECT",
                 "P_USUR_TUBE_SECT", "V_USUR_TUBE_CUMU"):  # fmt: skip
        table.require(name)
    insts = [v for v in table.column("INST") if v is not None]
    start = kw.get("INST")
    if start is None:
        start = insts[-1]
    reset = 0
    for i, row in enumerate(table.iter_rows()):
        inst = row.get("INST")
        if inst is None or inst < start * (1 - 1e-6):
            continue
        if row.get("SECTEUR") is not None:
            for name in ("V_USUR_TUBE_SECT", "P_USUR_TUBE_SECT", "V_USUR_TUBE_CUMU"):
                table.set_cell(name, i, 0.0)
            reset += 1
        elif "V_USUR_TUBE" in row:
            row["V_USUR_TUBE"] = row["P_USUR_TUBE"] = 0.0
    ctx.log(f"new tube from INST={start:g}: {reset} sector rows reset")
    return table


__all__ = ["run", "as_tuple"]
