"""AFFE_CHAR_CINE: imposed DOF values (MECA_IMPO) as a kinematic load.

code_aster removes these DOFs from the assembled system (ASSE_MATRICE
CHAR_CINE) and lifts the right-hand side by the imposed values; asterlite
keeps them as one-term relations, which the elimination shared with
AFFE_CHAR_MECA DDL_IMPO applies: the same solution, one mechanism.
EVOL_IMPO (values taken from a result) is refused by name.
"""

from __future__ import annotations

from asterlite.commands import affe_char_meca

from asterlite.concepts.assembly import KinematicLoad
from asterlite.fem.selection import as_tuple

# the components asterlite's mechanical models carry
_HONOURED = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ", "GRX")


def impose(ctx, kw, evaluator=None):
    """The kinematic load of MECA_IMPO. AFFE_CHAR_CINE_F gives
    ``evaluator(model, occ, in_time, in_frequency)``: the value of a function
    at a node, its dependence on INST kept in ``in_time[(node, component)]``,
    on FREQ in ``in_frequency``."""
    if kw.get("EVOL_IMPO") is not None:
        ctx.unsupported("AFFE_CHAR_CINE EVOL_IMPO (imposed values from a result)", "EVOL_IMPO", kw)
    model = kw["MODELE"]
    components = model.node_components()
    load = KinematicLoad(model=model)
    for occ in kw.factor("MECA_IMPO"):
        for name in occ.keys():
            if name not in _HONOURED and name not in ("TOUT", "GROUP_MA", "GROUP_NO", "NOEUD"):
                if occ.get(name) is not None:
                    ctx.unsupported(f"MECA_IMPO component {name}", name, occ)
        first = len(load.relations)
        in_time: dict = {}
        in_frequency: dict = {}
        value_at = affe_char_meca.constant_value
        if evaluator is not None:
            value_at = evaluator(model, occ, in_time, in_frequency)
        affe_char_meca._ddl_impo(
            ctx, model, components, load, occ, value_at=value_at, skip_absent=True
        )
        for relation in load.relations[first:]:
            node, component, _ = relation.terms[0]
            relation.rhs_in_time = in_time.get((node, component))
            relation.rhs_in_frequency = in_frequency.get((node, component))
    if not load.relations:
        ctx.error("no DOF is imposed", "MECA_IMPO", kw)
    ctx.log(f"kinematic load: {len(load.relations)} imposed DOFs")
    return load


def run(ctx, kw):
    if kw.get("NOM_CMP") is not None and as_tuple(kw.get("NOM_CMP")):
        ctx.unsupported("AFFE_CHAR_CINE NOM_CMP (with EVOL_IMPO)", "NOM_CMP", kw)
    return impose(ctx, kw)
