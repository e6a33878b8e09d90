"""DYNA_VIBRA/IMPRESSION NIVEAU, TOUT, INST_INIT, INST_FIN: a listing of the
shocks' local quantities at the archived instants, in the run's message log.

This is what code_aster's mdicho printed (up to version 12, in the RESULTAT
file): for each DIS_CHOC nonlinearity, a section per level asked for —
DEPL_LOC (node 1's local coordinates DXLOC, DYLOC, DZLOC), FORC_LOC (FN,
FT1, FT2), VITE_LOC (VN, VT1, VT2), TAUX_CHOC (the static restitution rate
of the modal basis at the shock nodes, VERI_CHOC's) — limited to the
archived instants in [INST_INIT, INST_FIN]; TOUT='OUI' stands for every
level. NIVEAU takes precedence over TOUT; without either nothing is listed.
The rows are ``archive index (1-based), instant, three values`` (1PD14.7,
1PD17.10).
"""

from __future__ import annotations

import numpy as np

from asterlite.io.relation_history import fortran_e

LEVELS = ("TAUX_CHOC", "DEPL_LOC", "FORC_LOC", "VITE_LOC")  # code_aster's print order
SECTIONS = {
    "DEPL_LOC": ("local displacements", ("DXLOC", "DYLOC", "DZLOC")),
    "FORC_LOC": ("contact forces", ("FN", "FT1", "FT2")),
    "VITE_LOC": ("local velocities", ("VN", "VT1", "VT2")),
}


def requested_levels(niveau: str | None, tout: str | None) -> tuple[str, ...]:
    """Levels to list: NIVEAU's one, every one for TOUT='OUI', else none."""
    if niveau:
        return (niveau,)
    if tout == "OUI":
        return LEVELS
    return ()


def archived_window(times: np.ndarray, first: float | None, last: float | None) -> np.ndarray:
    """Indices of the archived instants within [first, last] (bounds default
    to the first and last archived instants). The bounds allow for the
    rounding of accumulated steps (1e-9 of the time scale)."""
    times = np.asarray(times, dtype=float)
    slack = 1.0e-9 * max(1.0, float(np.max(np.abs(times))))
    lo = times[0] if first is None else first - slack
    hi = times[-1] if last is None else last + slack
    return np.flatnonzero((times >= lo) & (times <= hi))


def value_row(index: int, instant: float, values) -> str:
    text = f"{index:8d} " + fortran_e(instant, 7, 2, "D").rjust(14)
    return text + "".join(" " + fortran_e(float(v), 10, 2, "D").rjust(17) for v in values)


def listing_lines(result, levels, first=None, last=None, restitution=None) -> list[str]:
    """The listing of every DIS_CHOC nonlinearity of a TranGene.

    ``restitution``: {(shock name, node): rate}, needed for TAUX_CHOC."""
    shocks = [
        (rank, h) for rank, h in enumerate(result.shocks, start=1) if h.relation == "DIS_CHOC"
    ]
    window = archived_window(result.times, first, last)
    lines = [
        "***** shock results (DYNA_VIBRA/IMPRESSION) *****",
        f"number of shock locations: {len(shocks)}",
    ]
    for rank, history in shocks:
        lines.append(f"obstacle {rank}: {history.name} ({history.node_1})")
        for level in LEVELS:
            if level not in levels:
                continue
            if level == "TAUX_CHOC":
                lines += restitution_lines(history, restitution or {})
                continue
            title, names = SECTIONS[level]
            lines.append(f"{title} at shock node {history.node_1} ({', '.join(names)})")
            lines.append(f"number of archived instants: {len(result.times)}")
            lines.append("  archive  instant        " + "".join(n.ljust(18) for n in names))
            for i in window:
                values = [history.fields[name][i] for name in names]
                lines.append(value_row(int(i) + 1, float(result.times[i]), values))
    return lines


def restitution_lines(history, restitution: dict) -> list[str]:
    lines = []
    for node in (history.node_1, history.node_2):
        rate = restitution.get((history.name, node))
        if node is None or rate is None:
            continue
        lines.append(f"static restitution rate at shock node {node}: " + fortran_e(rate, 5, 2, "D"))
    return lines


__all__ = ["LEVELS", "requested_levels", "listing_lines", "archived_window"]
