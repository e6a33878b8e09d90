"""CALC_CHAR_CINE: the nodal field, on a numbering, of the values kinematic
loads impose at INST (zero on the other DOFs)."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import NodalField
from asterlite.fem.selection import as_tuple


def run(ctx, kw):
    numbering = kw["NUME_DDL"]
    instant = float(kw.get("INST", 0.0))
    values = np.zeros(numbering.n_dofs)
    for load in as_tuple(kw["CHAR_CINE"]):
        for relation in load.relations:
            node, component, coefficient = relation.terms[0]
            index = numbering.index.get((node, component))
            if index is None:
                ctx.error(
                    f"the numbering has no DOF {component} at node "
                    f"{numbering.mesh.node_names[node]}",
                    "CHAR_CINE",
                    kw,
                )
            if relation.rhs_in_frequency is not None:
                ctx.unsupported(
                    "CALC_CHAR_CINE of a value given as a function of FREQ (it evaluates "
                    "the loads at INST)",
                    "CHAR_CINE",
                    kw,
                )
            value = relation.rhs
            if relation.rhs_in_time is not None:
                value = float(relation.rhs_in_time.evaluate([instant])[0])
            values[index] = value / coefficient
    return NodalField(numbering=numbering, values=values)
