"""POST_DYNA_MODA_T: shock statistics of a tran_gene (CHOC).

OPTION='IMPACT' writes, per localized nonlinearity, CALCUL='IMPACT' rows
(one per global impact), one CALCUL='GLOBAL' row and NB_CLASSE
CALCUL='PROBA' rows (and a CALCUL='FLAMBAGE' row for a buckled FLAMBAGE
connection); OPTION='USURE' writes the displacement, force, shock-count and
wear-power rows. Definitions: ``asterlite.post.shocks``. The NOEUD column
holds the node number (code_aster 17 names nodes by number), INTITULE the
connection's name.

RELA_EFFO_DEPL (NOEUD/GROUP_NO, NOM_CMP) writes one row per phase the
RELA_EFFO_DEPL relation of that node and component spends in its nonlinear
zone (archived non-zero-force flag): RELATION (the function's name), NOEUD,
CMP, PHASE, INST_INIT, INST_FIN, MAXI and INST_MAXI (the displacement of
largest magnitude in the phase and its instant); see
``asterlite.post.shocks.nonlinear_phases``.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.table import Table
from asterlite.concepts.transient import TranGene
from asterlite.dynamics.shock_fields import ArchivedFields
from asterlite.legacy.v15 import computes
from asterlite.legacy.version import tables_name_nodes
from asterlite.post import shocks as stats
from asterlite.post.restitution import single_node
from asterlite.post.wear import history_wear_power

from .recu_fonction import shock_quantity

IMPACT_COLUMNS = {
    "INTITULE": "K24", "NOEUD": "K8", "CALCUL": "K16", "CHOC": "I", "INSTANT": "R",
    "F_MAX": "R", "IMPULSION": "R", "T_CHOC": "R", "V_IMPACT": "R", "NB_IMPACT": "I",
    "F_MAX_ABS": "R", "F_MAX_MOY": "R", "F_MAX_ETYPE": "R", "CLASSE": "I", "DEBUT": "R",
    "FIN": "R", "PROBA": "R", "FLAMBAGE": "K8", "ECRAS_RESI": "R", "INST_FLAMB": "R",
}  # fmt: skip
USURE_COLUMNS = {
    "INTITULE": "K24", "NOEUD": "K8", "CALCUL": "K16", "MOYEN": "R", "ECART_TYPE": "R",
    "RMS": "R", "MAXI": "R", "MINI": "R", "MOYEN_T_TOTAL": "R", "MOYEN_T_CHOC": "R",
    "RMS_T_TOTAL": "R", "RMS_T_CHOC": "R", "NB_CHOC_S": "I", "NB_REBON_CHOC": "I",
    "T_CHOC_MOYEN": "R", "T_CHOC_MAXI": "R", "T_CHOC_MINI": "R", "T_REBON_MOYEN": "R",
    "%_T_CHOC": "I", "PUIS_USURE": "R",
}  # fmt: skip
RELATION_COLUMNS = {
    "RELATION": "K8", "NOEUD": "K8", "CMP": "K8", "PHASE": "I", "INST_INIT": "R",
    "INST_FIN": "R", "MAXI": "R", "INST_MAXI": "R",
}  # fmt: skip
COMPONENTS = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")  # RELA_EFFO_DEPL's LAW[0] indexes these


def run(ctx, kw):
    result = kw["RESU_GENE"]
    if not isinstance(result, TranGene):
        ctx.unsupported(f"POST_DYNA_MODA_T of a {result.aster_type}", "RESU_GENE", kw)
    if kw.get("RELA_EFFO_VITE"):
        ctx.unsupported("POST_DYNA_MODA_T/RELA_EFFO_VITE", "RELA_EFFO_VITE", kw)
    if kw.get("RELA_EFFO_DEPL") and not kw.get("CHOC"):
        return relation_table(ctx, kw, result)
    occurrences = kw.factor("CHOC")
    if not occurrences:
        ctx.error("CHOC is required", "CHOC", kw)
    occ = occurrences[0]
    if not result.shocks:
        ctx.error("the result has no localized nonlinearity to analyse", "RESU_GENE", kw)
    option = occ.get("OPTION", "USURE")
    window = time_window(ctx, occ, result.times)
    if option != "IMPACT" and computes(ctx.session, "POST_DYNA_MODA_T_WINDOW_BY_TRUNCATION"):
        window = truncated_window(ctx, occ, result.times, result.order)
    occ.mark_used("NB_CLASSE")  # op0130 reads it for both options; only IMPACT uses it
    table = Table()
    columns = IMPACT_COLUMNS if option == "IMPACT" else USURE_COLUMNS
    for name, type_code in columns.items():
        table.add_column(name, type_code)
    by_name = tables_name_nodes(ctx.session)  # code_aster 15 decks: nodes by name
    t = result.times[window]
    weights = stats.trapezoid_weights(t) if option == "IMPACT" else None  # shared
    for number, shock in enumerate(result.shocks, start=1):
        mesh = shock_mesh(result, shock)
        labels = {"INTITULE": shock.name, "NOEUD": node_number(mesh, shock.node_1, by_name)}
        fields = windowed(shock.fields, window)
        if "FN" not in fields:
            ctx.error(f"shock {shock.name} has no archived normal force FN", "RESU_GENE", kw)
        if option == "IMPACT":
            impact_rows(table, labels, t, fields, occ, weights)
            buckling_rows(table, labels, shock, number, result.times, mesh, by_name)
        else:
            wear_rows(table, labels, t, fields, occ)
    return table


def relation_table(ctx, kw, result: TranGene) -> Table:
    """RELA_EFFO_DEPL: the nonlinear phases of the relation at one node
    component (code_aster fails when no RELA_EFFO_DEPL matches)."""

    by_name = tables_name_nodes(ctx.session)  # code_aster 15 decks: nodes by name

    table = Table()
    for name, type_code in RELATION_COLUMNS.items():
        table.add_column(name, type_code)
    mesh = result.basis.numbering.mesh
    for occ in kw.factor("RELA_EFFO_DEPL"):
        node = mesh.node_names[single_node(ctx, occ, mesh, with_cells=False)]
        component = str(occ["NOM_CMP"]).strip()
        shock = next(
            (
                s
                for s in result.shocks
                if s.relation == "RELA_EFFO_DEPL"
                and s.node_1 == node
                and relation_component(s) == component
            ),
            None,
        )
        if shock is None:
            known = [
                f"{s.node_1}/{relation_component(s)}"
                for s in result.shocks
                if s.relation == "RELA_EFFO_DEPL"
            ]
            ctx.error(
                f"no RELA_EFFO_DEPL relation at node {node} component {component}"
                f" (known: {', '.join(known) or 'none'})",
                "RELA_EFFO_DEPL",
                occ,
            )
        value = shock_quantity(shock, "VINT1")
        if value is None:  # not archived: Φ q of the node component
            value = np.asarray(result.depl) @ result.basis.shape_at(node, component)
        active = shock_quantity(shock, "VINT3")
        if active is None:
            ctx.error(f"RELA_EFFO_DEPL {shock.name}: no archived flag VINT3", "RESU_GENE", kw)
        labels = {
            "RELATION": relation_function(shock, node_number(mesh, node, by_name), component),
            "NOEUD": node_number(mesh, node, by_name),
            "CMP": component,
        }
        for phase in stats.nonlinear_phases(result.times, value, active):
            table.add_row(
                {
                    **labels,
                    "PHASE": phase.number,
                    "INST_INIT": phase.start,
                    "INST_FIN": phase.end,
                    "MAXI": phase.extreme,
                    "INST_MAXI": phase.instant,
                }
            )
    return table


def relation_component(shock) -> str:
    """NOM_CMP of a RELA_EFFO_DEPL history: from its parameters (LAW[0]),
    else from its generated name (node, component, function; 8 chars each)."""
    law = (shock.parameters or {}).get("LAW")
    if law is not None and len(law) and 0 <= int(law[0]) < len(COMPONENTS):
        return COMPONENTS[int(law[0])]
    return shock.name[8:16].strip()


def relation_function(shock, number: str, component: str) -> str:
    """The function's name, 3rd field of the generated name (empty when the
    name is not the generated one)."""
    name = shock.name
    if name[:8].strip() == number and name[8:16].strip() == component:
        return name[16:24].strip()
    return ""


def shock_mesh(result, shock):
    """The mesh numbering a nonlinearity's nodes: the basis's, or on a model of
    substructures a substructure mesh holding its first node, when all that
    hold it give it the same number (None otherwise: it is written by name)."""
    numbering = result.basis.numbering
    mesh = getattr(numbering, "mesh", None)
    if mesh is not None or getattr(numbering, "model", None) is None:
        return mesh
    holders = [
        sub.macro.mesh
        for sub in numbering.model.substructures
        if shock.node_1 in sub.macro.mesh.node_index
    ]
    numbers = {h.node_index[shock.node_1] for h in holders}
    return holders[0] if len(numbers) == 1 else None


def node_number(mesh, name: str | None, by_name: bool = False) -> str:
    """code_aster 17 writes nodes by number (1-based index) in tables; code_aster
    15 and older by name (``by_name``: the deck's version, see asterlite.legacy.version)."""
    if name is None:
        return ""
    if by_name or mesh is None:
        return str(name)
    index = mesh.node_index.get(name)
    return str(index + 1) if index is not None else str(name)


def time_window(ctx, occ, times) -> slice | np.ndarray:
    times = np.asarray(times)
    start = occ.get("INST_INIT")
    stop = occ.get("INST_FIN")
    eps = 1e-9 * max(abs(times[-1] - times[0]), 1e-300)
    keep = np.ones(times.size, bool)
    if start is not None:
        keep &= times >= start - eps
    if stop is not None:
        keep &= times <= stop + eps
    if keep.sum() < 2:
        ctx.error(
            "fewer than two archived instants between INST_INIT and INST_FIN", "INST_FIN", occ
        )
    kept = np.flatnonzero(keep)
    if kept[-1] - kept[0] + 1 == kept.size:  # one stretch (always): views, no copies
        return slice(int(kept[0]), int(kept[-1]) + 1)
    return kept


def truncated_window(ctx, occ, times, order) -> slice:
    """The window of code_aster 15's statch (OPTION='USURE'): from index
    int((INST_INIT - t0)/dt) to int((INST_FIN - t0)/dt), dt the mean archive step
    over the first n-2 instants, on code_aster's archived times (the integrator's
    running sum of its steps, :func:`summed_times`); truncation, so an instant a
    rounding below the bound starts the window one archived instant early."""
    times = summed_times(np.asarray(times, dtype=float), np.asarray(order))
    n = times.size
    dt = (times[n - 3] - times[0]) / (n - 3) if n >= 4 else times[1] - times[0]
    start = max(float(occ.get("INST_INIT", times[0])), times[0])
    stop = min(float(occ.get("INST_FIN", times[-1])), times[-1])
    first = int((start - times[0]) / dt)
    last = min(int((stop - times[0]) / dt), n - 1)
    if last - first < 1:
        ctx.error(
            "fewer than two archived instants between INST_INIT and INST_FIN", "INST_FIN", occ
        )
    ctx.log(
        f"note: code_aster 15 deck: window t={times[first]:g}..{times[last]:g} "
        "(its statch truncated the bounds to archive indices)"
    )
    return slice(first, last + 1)


def summed_times(times, order):
    """The archived instants of a fixed-step run as code_aster's integrator
    reached them, t0 + dt + dt + ... in floating point (asterlite archives the
    exact grid t0 + k dt); other runs: as archived."""
    steps = order - order[0]
    if times.size < 2 or steps[-1] <= 0 or np.any(np.diff(steps) <= 0):
        return times
    step = (times[-1] - times[0]) / steps[-1]
    if not np.allclose(times, times[0] + steps * step, rtol=0.0, atol=1e-9 * abs(step)):
        return times
    running = np.add.accumulate(np.concatenate([[times[0]], np.full(int(steps[-1]), step)]))
    return running[steps]


def windowed(fields, window) -> ArchivedFields:
    """The shock's fields restricted to the window, each made when first read
    (a table reads a few of the 36 archived quantities)."""
    return ArchivedFields({name: window_of(fields, name, window) for name in fields})


def window_of(fields, name: str, window):
    return lambda: np.asarray(fields[name])[window]


def impact_rows(table, labels, t, fields, occ, weights=None) -> None:
    vn = fields["VN"] if "VN" in fields else np.zeros_like(t)
    summary = stats.detect_impacts(
        t,
        fields["FN"],
        vn,
        float(occ.get("SEUIL_FORCE", 0.0)),
        float(occ.get("DUREE_REPOS", 0.0)),
        weights,
    )
    impacts = summary.columns
    table.add_rows(
        {**labels, "CALCUL": "IMPACT"},
        {
            "CHOC": impacts["number"],
            "INSTANT": impacts["instant"],
            "F_MAX": impacts["f_max"],
            "IMPULSION": impacts["impulse"],
            "T_CHOC": impacts["duration"],
            "V_IMPACT": impacts["v_impact"],
            "NB_IMPACT": impacts["n_sub_impacts"],
        },
    )
    table.add_row(
        {
            **labels,
            "CALCUL": "GLOBAL",
            "F_MAX_ABS": summary.f_max_abs,
            "F_MAX_MOY": summary.f_max_mean,
            "F_MAX_ETYPE": summary.f_max_std,
        }
    )
    n_classes = int(occ.get("NB_CLASSE", 10)) or 10
    lower, upper, proba = stats.histogram(summary.peaks, n_classes)
    for k in range(n_classes):
        table.add_row(
            {
                **labels,
                "CALCUL": "PROBA",
                "CLASSE": k + 1,
                "DEBUT": lower[k],
                "FIN": upper[k],
                "PROBA": proba[k],
            }
        )


def buckling_rows(table, labels, shock, number, times, mesh, by_name=False) -> None:
    """A FLAMBAGE connection that buckled: residual crushing and instant."""
    if shock.relation != "FLAMBAGE":
        return
    crush = shock_quantity(shock, "VINT9")  # VINT9: crushing (VINT1 is the normal force)
    if crush is None or crush[-1] <= 0:
        return
    first = int(np.argmax(crush > 0))
    force = float(crush[-1])
    nodes = [labels["NOEUD"]]
    if shock.node_2:
        force /= 2  # shared between the two nodes
        nodes.append(node_number(mesh, shock.node_2, by_name))
    for node in nodes:
        table.add_row(
            {
                **labels,
                "NOEUD": node,
                "CALCUL": "FLAMBAGE",
                "CHOC": number,
                "FLAMBAGE": "OUI",
                "ECRAS_RESI": force,
                "INST_FLAMB": float(times[first]),
            }
        )


def _blocks(n: int, n_blocks: int) -> list[slice]:
    size = max(n // max(n_blocks, 1), 1)
    return [slice(b * size, (b + 1) * size) for b in range(max(n_blocks, 1))]


def block_signal_stats(x, blocks) -> stats.SignalStats:
    """Statistics averaged over NB_BLOC blocks (means of means, quadratic
    means of deviations and RMS), extrema over all blocks."""
    parts = [stats.signal_stats(x[b]) for b in blocks]
    return stats.SignalStats(
        float(np.mean([p.mean for p in parts])),
        float(np.sqrt(np.mean([p.std**2 for p in parts]))),
        float(np.sqrt(np.mean([p.rms**2 for p in parts]))),
        max(p.max for p in parts),
        min(p.min for p in parts),
    )


def wear_rows(table, labels, t, fields, occ) -> None:
    threshold = float(occ.get("SEUIL_FORCE", 0.0))
    rest = float(occ.get("DUREE_REPOS", 0.0))
    blocks = _blocks(t.size, int(occ.get("NB_BLOC", 1)))
    zeros = np.zeros_like(t)
    local = [fields.get(k, zeros) for k in ("DXLOC", "DYLOC", "DZLOC")]
    radius, angle = stats.polar(local[1], local[2])
    signals = [
        ("DEPL_X", local[0]),
        ("DEPL_Y", local[1]),
        ("DEPL_Z", local[2]),
        ("DEPL_RADIAL", radius),
        ("DEPL_ANGULAIRE", angle),
    ]
    for calcul, signal in signals:
        s = block_signal_stats(signal, blocks)
        table.add_row(
            {**labels, "CALCUL": calcul, "MOYEN": s.mean, "ECART_TYPE": s.std, "RMS": s.rms,
             "MAXI": s.max, "MINI": s.min}
        )  # fmt: skip

    fn = fields["FN"]
    parts = [stats.normal_force_stats(fn[b], threshold) for b in blocks]
    table.add_row(
        {
            **labels,
            "CALCUL": "FORCE_NORMALE",
            "MOYEN_T_TOTAL": float(np.mean([p.mean_total for p in parts])),
            "MOYEN_T_CHOC": float(np.mean([p.mean_contact for p in parts])),
            "RMS_T_TOTAL": float(np.sqrt(np.mean([p.rms_total**2 for p in parts]))),
            "RMS_T_CHOC": float(np.sqrt(np.mean([p.rms_contact**2 for p in parts]))),
            "MAXI": max(0.0, max(p.max for p in parts)),
        }
    )
    for calcul, key in (("FORCE_TANG_1", "FT1"), ("FORCE_TANG_2", "FT2")):
        s = block_signal_stats(fields.get(key, zeros), blocks)
        table.add_row(
            {**labels, "CALCUL": calcul, "MOYEN": s.mean, "ECART_TYPE": s.std, "RMS": s.rms,
             "MAXI": max(0.0, s.max), "MINI": min(0.0, s.min)}
        )  # fmt: skip

    counts = [stats.count_shocks(t[b], fn[b], threshold, rest) for b in blocks]
    n_shocks = sum(c.n_shocks for c in counts)
    n_rebounds = sum(c.n_rebounds for c in counts)
    contact_time = sum(c.total_contact_time for c in counts)
    rebound_time = sum(c.n_rebounds * c.mean_rebound for c in counts)
    acquisition = acquisition_time(t, blocks)
    durations = [c for c in counts if c.n_shocks]
    table.add_row(
        {
            **labels,
            "CALCUL": "STAT_CHOC",
            "NB_CHOC_S": int(n_shocks / acquisition) if acquisition > 0 else 0,
            "NB_REBON_CHOC": n_rebounds // n_shocks if n_shocks else 0,
            "T_CHOC_MOYEN": contact_time / n_shocks if n_shocks else 0.0,
            "T_CHOC_MAXI": max((c.max_duration for c in counts), default=0.0),
            "T_CHOC_MINI": min((c.min_duration for c in durations), default=0.0),
            "T_REBON_MOYEN": rebound_time / n_rebounds if n_rebounds else 0.0,
            "%_T_CHOC": int(100.0 * contact_time / acquisition) if acquisition > 0 else 0,
        }
    )

    power = history_wear_power(t, fields, int(occ.get("NB_BLOC", 1)))
    table.add_row({**labels, "CALCUL": "PUIS_USURE", "PUIS_USURE": power})


def acquisition_time(t, blocks) -> float:
    """Analysed duration: mean step (from the first n-2 samples, as code_aster)
    times the number of samples analysed."""
    n = t.size
    dt = (t[n - 3] - t[0]) / (n - 3) if n >= 4 else (t[1] - t[0])
    used = sum(len(range(*b.indices(n))) for b in blocks)
    return dt * used
