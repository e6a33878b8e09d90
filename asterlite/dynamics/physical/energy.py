"""Energy balance of a physical transient (DYNA_VIBRA PHYS, when asked),
as code_aster's enerca accumulates it after each step (op0048)::

    TRAV_EXT  += Δu · (F_n + F_{n+1}) / 2      work of the external loads
    ENER_CIN  += v̄ · M Δv                      = ½ v M v
    ENER_TOT  += Δu · K ū                      = ½ u K u (strain energy)
    TRAV_AMOR += Δu · C v̄                      damping
    TRAV_LIAI  = 0                              (no IMPE_ABSO here)
    DISS_SCH   = TRAV_EXT - ENER_CIN - ENER_TOT - TRAV_AMOR - TRAV_LIAI

with ū, v̄ the step means and Δu, Δv the increments; one row per step in
the result's PARA_CALC table.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.table import Table

COLUMNS = ("TRAV_EXT", "ENER_CIN", "ENER_TOT", "TRAV_AMOR", "TRAV_LIAI", "DISS_SCH")


class EnergyBalance:
    def __init__(self, system, t0: float):
        self.system = system
        self.force = system.forces([t0])[0]
        self.totals = dict.fromkeys(COLUMNS, 0.0)
        self.rows: list[dict] = []

    def __call__(self, t, force, q0, v0, q1, v1) -> None:
        system = self.system
        du, dv = q1 - q0, v1 - v0
        u_mean, v_mean = 0.5 * (q0 + q1), 0.5 * (v0 + v1)
        work = float(du @ (0.5 * (self.force + force)))
        kinetic = float(v_mean @ (system.mass @ dv))
        internal = float(du @ (system.reduced_stiffness() @ u_mean))
        damping = float(du @ (system.damping @ v_mean)) if system.damping is not None else 0.0
        totals = self.totals
        totals["TRAV_EXT"] += work
        totals["ENER_CIN"] += kinetic
        totals["ENER_TOT"] += internal
        totals["TRAV_AMOR"] += damping
        totals["DISS_SCH"] += work - kinetic - internal - damping
        self.force = np.array(force, dtype=float)
        self.rows.append({"INST": float(t), **totals})

    def resume(self, previous, t: float) -> None:
        """Continue a reused result's PARA_CALC table: its rows up to t are
        kept, the new rows accumulate from zero again (as code_aster: the
        balance of a continuation counts only its own steps)."""
        tol = 1.0e-9 * max(1.0, abs(t))
        kept = [dict(row) for row in previous.rows if row.get("INST", 0.0) <= t + tol]
        self.rows = kept + self.rows

    def table(self):
        table = Table(title="PARA_CALC")
        table.add_column("INST", "R")
        for name in COLUMNS:
            table.add_column(name, "R")
        for row in self.rows:
            table.add_row(row)
        return table
