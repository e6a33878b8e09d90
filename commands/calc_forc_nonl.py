"""CALC_FORC_NONL: a dyna_trans whose DEPL field at each chosen order of
RESULTAT is the FONL_NOEU nodal force vector of the behaviours
(code_aster's op0183), on the result's numbering, at the result's instants
and order numbers.

Only discrete elements under DIS_CHOC contribute (asterlite.fem.discrete_contact);
ELAS contributes nothing, as in code_aster, where no element computes
FONL_NOEU for it. The last COMPORTEMENT occurrence naming a cell gives its
relation. Other relations and DEFORMATION values are refused by name."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.transient import DynaTrans
from asterlite.fem.discrete_contact import dis_choc_nodal_forces
from asterlite.fem.elements import ElementError
from asterlite.fem.selection import select_cells
from asterlite.post.restitution import selection_from_keywords

RELATIONS = ("ELAS", "DIS_CHOC")
_ORDER_KEYWORDS = ("NUME_ORDRE", "LIST_ORDRE", "INST", "LIST_INST")


def _contact_cells(ctx, kw, model) -> np.ndarray:
    mesh = model.mesh
    relation_of: dict[int, str] = {}
    for occ in kw.factor("COMPORTEMENT"):
        relation = occ["RELATION"]
        if relation not in RELATIONS:
            ctx.unsupported(
                f"RELATION={relation!r} in CALC_FORC_NONL ({', '.join(RELATIONS)})",
                "RELATION",
                occ,
            )
        if occ.get("DEFORMATION", "PETIT") != "PETIT":
            ctx.unsupported(f"DEFORMATION={occ['DEFORMATION']!r}", "DEFORMATION", occ)
        if occ.get("TOUT") is None and occ.get("GROUP_MA") is None and occ.get("MAILLE") is None:
            cells = np.arange(mesh.n_cells)
        else:
            cells = select_cells(ctx, occ, mesh)
        for cell in cells:
            relation_of[int(cell)] = relation
    modelled = set(int(c) for c in model.cell_modelisation)
    return np.array(
        sorted(c for c, r in relation_of.items() if r == "DIS_CHOC" and c in modelled), dtype=int
    )


def run(ctx, kw):
    result = kw["RESULTAT"]
    for name in ("NUME_MODE", "NOEUD_CMP", "NOM_CAS", "FREQ", "LIST_FREQ"):
        if kw.get(name) is not None:
            ctx.unsupported(f"CALC_FORC_NONL/{name} (a result of instants is read)", name, kw)
    times = getattr(result, "times", None)
    depl = getattr(result, "fields", {}).get("DEPL")
    if times is None or depl is None:
        ctx.error("RESULTAT must be a result of instants with DEPL fields", "RESULTAT", kw)
    model = kw["MODELE"]
    materials = kw.get("CHAM_MATER") or result.materials
    characteristics = kw.get("CARA_ELEM") or result.characteristics
    cells = _contact_cells(ctx, kw, model)
    if cells.size and materials is None:
        ctx.error("DIS_CHOC needs the materials (CHAM_MATER)", "CHAM_MATER", kw)
    kw.mark_used("TOUT_ORDRE", "CRITERE", "PRECISION")
    if all(kw.get(k) is None for k in _ORDER_KEYWORDS):
        rows = np.arange(len(times))
    else:
        rows = selection_from_keywords(ctx, kw, times, result.order).lower
    values = np.asarray(depl, dtype=float)[rows]
    try:
        forces = dis_choc_nodal_forces(
            model, characteristics, materials, result.numbering, cells, values
        )
    except ElementError as exc:
        ctx.error(str(exc), "COMPORTEMENT", kw)
    ctx.log(
        f"CALC_FORC_NONL: {cells.size} DIS_CHOC cells, {rows.size} orders, "
        f"largest force {np.abs(forces).max() if forces.size else 0.0:g}"
    )
    return DynaTrans(
        numbering=result.numbering,
        times=np.asarray(times, dtype=float)[rows],
        order=np.asarray(result.order)[rows],
        fields={"DEPL": forces},
        model=getattr(result, "model", None) or model,
        materials=materials,
        characteristics=characteristics,
        mass_matrix=getattr(result, "mass_matrix", None),
    )
