"""MECA_STATIQUE: K u(t) = sum_i f_i(t) F_i with the relations of the loads,
at each instant of LIST_INST (between INST_INIT and INST_FIN) or at INST
(0 by default), f_i the load's FONC_MULT at t (1 without): it scales the
load's forces and the values it imposes (DDL_IMPO, LIAISON_*), as code_aster
does. The result is an ``evol_elas`` of DEPL fields; OPTION='SIEF_ELGA'
(code_aster's default) leaves the stresses to CALC_CHAMP, and a deck that
asks for it is refused by name.
"""

from __future__ import annotations

import numpy as np
from asterlite.commands.nume_ddl import numbering_for

from asterlite.concepts.static_result import EvolElas
from asterlite.fem.assemble import assemble_blocks, assemble_terms
from asterlite.fem.elements import ElementError
from asterlite.fem.loads import load_terms
from asterlite.fem.options import option_blocks
from asterlite.modal.static_modes import StaticModeError, static_solve
from asterlite.post.restitution import values_of


def _instants(ctx, kw) -> np.ndarray:
    if kw.get("LIST_INST") is None:
        return np.array([float(kw.get("INST") or 0.0)])
    times = np.asarray(values_of(kw["LIST_INST"]), dtype=float)
    start, end = kw.get("INST_INIT"), kw.get("INST_FIN")
    keep = np.ones(times.size, dtype=bool)
    tolerance = 1.0e-6 * max(1.0, float(np.max(np.abs(times))) if times.size else 1.0)
    if start is not None:
        keep &= times >= float(start) - tolerance
    if end is not None:
        keep &= times <= float(end) + tolerance
    if not keep.any():
        ctx.error("no instant of LIST_INST lies between INST_INIT and INST_FIN", "LIST_INST", kw)
    return times[keep]


def _multipliers(occ, times) -> np.ndarray:
    function = occ.get("FONC_MULT")
    if function is None:
        return np.ones(times.size)
    return np.array([float(function(float(t))) for t in times])


def run(ctx, kw):
    if ctx.reuse is not None or kw.get("RESULTAT") is not None:
        ctx.unsupported("MECA_STATIQUE reuse (instants added to a result)", "RESULTAT", kw)
    if kw.get("OPTION", "SIEF_ELGA") == "SIEF_ELGA" and "OPTION" in kw.given:
        ctx.unsupported(
            "MECA_STATIQUE OPTION='SIEF_ELGA' (compute it with CALC_CHAMP)", "OPTION", kw
        )
    model = kw["MODELE"]
    characteristics, materials = kw.get("CARA_ELEM"), kw.get("CHAM_MATER")
    occurrences = kw.factor("EXCIT")
    loads = [occ["CHARGE"] for occ in occurrences]
    numbering = numbering_for(model, loads, characteristics, materials)
    try:
        stiffness = assemble_blocks(
            option_blocks(model, characteristics, "RIGI_MECA", materials=materials), numbering
        )
    except NotImplementedError as exc:
        ctx.unsupported(str(exc), "MODELE", kw)
    except (ElementError, ValueError) as exc:
        ctx.error(str(exc), "CARA_ELEM", kw)
    times = _instants(ctx, kw)
    forces = np.zeros((numbering.n_dofs, times.size))
    relation_rhs = []
    seen = set()
    for occ in occurrences:
        load, scale = occ["CHARGE"], _multipliers(occ, times)
        try:
            vector = assemble_terms(load_terms(load, characteristics, materials), numbering)
        except (ElementError, ValueError) as exc:
            ctx.error(str(exc), "CHARGE", occ)
        forces += np.outer(vector, scale)
        if id(load) not in seen:  # numbering_for takes each load's relations once
            seen.add(id(load))
            relation_rhs.extend(np.outer([r.rhs for r in load.relations], scale))
    relation_rhs = np.array(relation_rhs).reshape(len(numbering.relations), times.size)
    try:
        depl = static_solve(stiffness, numbering, forces, relation_rhs)
    except StaticModeError as exc:
        ctx.error(str(exc), "EXCIT", kw)
    ctx.log(
        f"MECA_STATIQUE: {numbering.n_dofs} DOFs, {len(numbering.relations)} relations, "
        f"{times.size} instants"
    )
    return EvolElas(
        numbering=numbering,
        times=times,
        order=np.arange(1, times.size + 1),
        fields={"DEPL": np.asarray(depl).T.copy()},
        model=model,
        materials=materials,
        characteristics=characteristics,
        # CALC_CHAMP without EXCIT takes the beams' distributed loads off with these
        loads=tuple((occ["CHARGE"], occ.get("FONC_MULT") or 1.0) for occ in occurrences),
    )
