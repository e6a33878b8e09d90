"""DEFI_LIST_INST METHODE='MANUEL': the instants of DEFI_LIST (LIST_INST or
VALE, strictly increasing) and the ECHEC occurrences (event, action, step
subdivision) kept for the nonlinear solvers that read them."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.lists import TimeStepping
from asterlite.post.restitution import values_of


def run(ctx, kw):
    occ = kw.factor("DEFI_LIST")[0]
    given = occ["LIST_INST"] if occ.get("LIST_INST") is not None else occ["VALE"]
    instants = np.asarray(values_of(given), dtype=float).ravel()
    if instants.size < 2 or np.any(np.diff(instants) <= 0.0):
        ctx.error("the instants must be at least two, strictly increasing", "DEFI_LIST", occ)
    failures = [{k: v for k, v in dict(f).items() if v is not None} for f in kw.factor("ECHEC")]
    ctx.log(
        f"list of instants: {instants.size} from {instants[0]:g} to {instants[-1]:g}; "
        + "; ".join(
            f"on {f['EVENEMENT']}: {f['ACTION']}"
            + (f" by {f['SUBD_PAS']} to level {f['SUBD_NIVEAU']}" if "SUBD_PAS" in f else "")
            for f in failures
        )
    )
    return TimeStepping(values=instants, failures=failures)
