"""The result of a DYNA_VIBRA transient on a modal basis: the shock
histories named as code_aster's NOEUD_CHOC parameters, the continuation of
a reused result, the IMPRESSION listings."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.transient import ShockHistory, TranGene
from asterlite.dynamics import contact as C
from asterlite.dynamics.basis_check import node_checks
from asterlite.dynamics.shock_fields import ArchivedFields, column_difference
from asterlite.dynamics.shock_fields import column as archived_column
from asterlite.io import relation_history, shock_listing


def shock_parameters(shocks, s: int) -> dict:
    """What the result keeps of shock ``s``, named as DYNA_VIBRA's keywords
    (IMPR_RESU, the report and the plots read them)."""
    p = shocks.params[s]
    spec = shocks.specs[s]
    return {
        "OBSTACLE": spec.obstacle_type,
        "JEU": p[C.P_GAP],
        "DIST_1": p[C.P_DIST1],
        "DIST_2": p[C.P_DIST2],
        "RIGI_NOR": p[C.P_KN],
        "AMOR_NOR": p[C.P_CN],
        "RIGI_TAN": p[C.P_KT],
        "AMOR_TAN": p[C.P_CT],
        "COULOMB_DYNA": p[C.P_MU_DYN],
        "COULOMB_STAT": p[C.P_MU_STAT],
        "ORIG_OBST": p[C.P_ORIGIN : C.P_ORIGIN + 3].copy(),
        "NORM_OBST": spec.norm_obst.copy(),
        "LOCAL_FRAME": shocks.rots[s].copy(),
        "UNIDIRECTIONNEL": bool(shocks.flags[s, C.F_UNIDIR]),
    }


def shock_histories(shocks, vint) -> list[ShockHistory]:
    """Archived local quantities, named as code_aster's NOEUD_CHOC parameters."""
    histories = []
    for s, spec in enumerate(shocks.specs):
        v = vint[:, s, :]
        if spec.relation != "DIS_CHOC":  # a relation of asterlite.dynamics.laws
            from asterlite.dynamics.laws.connections import law_fields

            fields = law_fields(spec.relation, v)
            histories.append(
                ShockHistory(
                    name=spec.name,
                    relation=spec.relation,
                    node_1=spec.node_1,
                    node_2=spec.node_2,
                    fields={k: np.ascontiguousarray(a) for k, a in fields.items()},
                    parameters=shock_parameters(shocks, s),
                )
            )
            continue
        # each named column is copied from the archive when first read
        named = {
            "FN": C.V_FN,
            "FT1": C.V_FT1,
            "FT2": C.V_FT2,
            "DXLOC": C.V_LOC1,
            "DYLOC": C.V_LOC1 + 1,
            "DZLOC": C.V_LOC1 + 2,
            "DXLOC_2": C.V_LOC2,
            "DYLOC_2": C.V_LOC2 + 1,
            "DZLOC_2": C.V_LOC2 + 2,
            "VN": C.V_VN,
            "VT1": C.V_VT1,
            "VT2": C.V_VT2,
            "ADHERENCE": C.V_STICK,
        }
        recipes = {name: archived_column(v, j) for name, j in named.items()}
        two = spec.node_2 is not None and spec.obstacle_type.startswith("BI_")
        for axis, i in (("X", 0), ("Y", 1), ("Z", 2)):
            recipes[f"D{axis}REL"] = column_difference(
                v, C.V_LOC1 + i, C.V_LOC2 + i if two else None
            )
        for i in range(C.N_VINT):
            recipes[f"VINT{i + 1}"] = archived_column(v, i)
        histories.append(
            ShockHistory(
                name=spec.name,
                relation="DIS_CHOC",
                node_1=spec.node_1,
                node_2=spec.node_2,
                fields=ArchivedFields(recipes),
                parameters=shock_parameters(shocks, s),
            )
        )
    return histories


def appended(previous: TranGene, new: TranGene) -> TranGene:
    """reuse= continuation: the reused states before the new start, then the
    new run, its NUME_ORDRE continuing the reused ones."""
    t0 = new.times[0]
    keep = previous.times < t0 - 1.0e-12 * max(1.0, abs(t0))
    start = int(previous.order[np.flatnonzero(~keep)[0]]) if np.any(~keep) else 0
    shocks = []
    for old, fresh in zip(previous.shocks, new.shocks, strict=False):
        fields = {
            k: np.concatenate([old.fields[k][keep], v])
            for k, v in fresh.fields.items()
            if k in old.fields
        }
        shocks.append(
            ShockHistory(
                fresh.name, fresh.relation, fresh.node_1, fresh.node_2, fields, fresh.parameters
            )
        )
    info = dict(new.info)
    for key in ("mult_appui", "corr_stat"):
        if key in previous.info and key not in info:
            info[key] = previous.info[key]
    return TranGene(
        basis=new.basis,
        times=np.concatenate([previous.times[keep], new.times]),
        order=np.concatenate([previous.order[keep], start + new.order]),
        depl=np.concatenate([previous.depl[keep], new.depl]),
        vite=np.concatenate([previous.vite[keep], new.vite]),
        acce=np.concatenate([previous.acce[keep], new.acce]),
        shocks=shocks if previous.shocks else new.shocks,
        scheme=new.scheme,
        step=new.step,
        info=info,
        step_sizes=_joined(previous.step_sizes, new.step_sizes, keep),
        rejections=_joined(previous.rejections, new.rejections, keep),
    )


def _joined(previous, new, keep):
    """An archived-instant history of a continuation (None if either part lacks it)."""
    if previous is None or new is None:
        return None
    return np.concatenate([previous[keep], new])


def impression(ctx, kw, result, name, specs, system) -> None:
    """IMPRESSION: the DIS_VISC / DIS_ECRO_TRAC histories on their logical
    units (asterlite.io.relation_history), the shocks' local quantities in
    the message log (asterlite.io.shock_listing)."""

    occs = kw.factor("IMPRESSION")
    if not occs:
        return
    occ = occs[0]
    units = {k: occ.get(k) for k in relation_history.UNIT_KEYWORDS if occ.get(k) is not None}
    for note in relation_history.write_histories(ctx.session, result, name, units):
        ctx.log(note)
    levels = shock_listing.requested_levels(occ.get("NIVEAU"), occ.get("TOUT"))
    first, last = occ.get("INST_INIT"), occ.get("INST_FIN")
    if not levels:
        if first is not None or last is not None:  # code_aster lists nothing either
            ctx.log("IMPRESSION/INST_INIT, INST_FIN: nothing listed without NIVEAU or TOUT='OUI'")
        return
    rates = restitution_rates(ctx, kw, occ, specs, system) if "TAUX_CHOC" in levels else None
    for line in shock_listing.listing_lines(result, levels, first, last, rates):
        ctx.log(line)


def restitution_rates(ctx, kw, occ, specs, system) -> dict:
    """{(shock, node): static restitution rate of the basis} (VERI_CHOC's)."""

    basis = kw["MATR_MASS"].basis
    if getattr(basis, "stiffness", None) is None:  # also a mode_gene
        keyword = "NIVEAU" if occ.get("NIVEAU") else "TOUT"
        ctx.unsupported(
            "IMPRESSION TAUX_CHOC (restitution rate) on a basis without its assembled stiffness",
            keyword,
            occ,
        )
    checks = node_checks(specs, basis, np.diag(system.stiffness))
    return {(check.shock, check.node): check.restitution for check in checks}
