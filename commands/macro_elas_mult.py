"""MACRO_ELAS_MULT: linear static solutions for several load cases (NOM_CAS).

The stiffness of MODELE/CARA_ELEM is assembled on a numbering that carries
the kinematic relations of CHAR_MECA_GLOBAL and of the cases' loads (bound to
NUME_DDL=CO(...) when asked); each case solves K u = f_case with its own
imposed values, f_case taking the loads of CHAR_MECA_GLOBAL as well as its
own (as code_aster's macro does). The result is a mult_elas (``MultElasResult``)."""

from __future__ import annotations

import numpy as np
from asterlite.commands.nume_ddl import numbering_for

from asterlite.concepts.assembly import AssembledMatrix, DofNumbering
from asterlite.concepts.modes import MultElasResult
from asterlite.fem.assemble import assemble_blocks, assemble_terms
from asterlite.fem.constraints import ConstraintError
from asterlite.fem.elements import ElementError, element_blocks
from asterlite.fem.loads import load_terms
from asterlite.fem.selection import as_tuple
from asterlite.modal.renumber import transfer
from asterlite.modal.static_modes import StaticModeError, static_solve


def _case_terms(ctx, occ, kw, loads):
    """Every nodal term of a case's loads, as CALC_VECT_ELEM computes them."""
    terms = []
    for load in loads:
        try:
            terms.extend(load_terms(load, kw.get("CARA_ELEM"), kw.get("CHAM_MATER")))
        except NotImplementedError as exc:
            ctx.unsupported(str(exc), "CHAR_MECA", occ)
        except (ElementError, ValueError) as exc:
            ctx.error(str(exc), "CHAR_MECA", occ)
    return terms


def _relation_rhs(numbering: DofNumbering, active_loads) -> np.ndarray:
    """Right-hand sides of the numbering's relations for one case: the values
    of relations belonging to the global or the case's loads, zero for the
    relations of other cases' loads."""
    active = {id(r) for load in active_loads for r in load.relations}
    return np.array([r.rhs if id(r) in active else 0.0 for r in numbering.relations])


def run(ctx, kw):
    if kw.get("LIAISON_DISCRET") is not None:
        ctx.unsupported("MACRO_ELAS_MULT LIAISON_DISCRET", "LIAISON_DISCRET", kw)
    if kw.get("RESULTAT") is not None:
        ctx.unsupported("MACRO_ELAS_MULT RESULTAT (enriching a result)", "RESULTAT", kw)
    model = kw["MODELE"]
    global_loads = list(as_tuple(kw.get("CHAR_MECA_GLOBAL")))
    cases = kw.factor("CAS_CHARGE")
    case_loads = [list(as_tuple(occ.get("CHAR_MECA"))) for occ in cases]
    for occ in cases:
        if occ.get("MODE_FOURIER") is not None:
            ctx.unsupported("MACRO_ELAS_MULT MODE_FOURIER", "MODE_FOURIER", occ)
    given = kw.get("NUME_DDL")
    if isinstance(given, DofNumbering):
        numbering = given
    else:
        numbering = numbering_for(model, global_loads + [ld for c in case_loads for ld in c])
        if given is not None:  # NUME_DDL=CO("NAME"): bind the numbering built here
            ctx.bind(given, numbering)
    try:
        blocks = element_blocks(model, kw.get("CARA_ELEM"), "K", materials=kw.get("CHAM_MATER"))
        stiffness = assemble_blocks(blocks, numbering)
    except NotImplementedError as exc:
        ctx.unsupported(str(exc), "MODELE", kw)
    except (ElementError, ValueError, KeyError) as exc:
        ctx.error(f"stiffness: {exc}", "CARA_ELEM", kw)
    forces, rhs = [], []
    for occ, loads in zip(cases, case_loads, strict=True):
        if occ.get("VECT_ASSE") is not None:
            field = occ["VECT_ASSE"]
            forces.append(transfer(field.values, field.numbering, numbering))
        else:
            try:
                # code_aster's case vector takes CHAR_MECA_GLOBAL's loads too
                terms = _case_terms(ctx, occ, kw, loads + global_loads)
                forces.append(assemble_terms(terms, numbering))
            except KeyError as exc:
                ctx.error(f"load on a DOF the numbering lacks: {exc.args[0]}", "CHAR_MECA", occ)
        rhs.append(_relation_rhs(numbering, global_loads + loads))
    f = np.column_stack(forces)
    try:
        u = static_solve(stiffness, numbering, f, np.column_stack(rhs))
    except (StaticModeError, ConstraintError) as exc:
        ctx.error(str(exc), "CHAR_MECA_GLOBAL", kw)
    names = [str(occ.get("NOM_CAS") or f"CAS_{k + 1}") for k, occ in enumerate(cases)]
    for name, column in zip(names, u.T, strict=True):
        ctx.log(f"case {name}: max |u| = {np.max(np.abs(column), initial=0.0):.6g}")
    return MultElasResult(
        numbering=numbering,
        fields=np.asarray(u, dtype=float).reshape(numbering.n_dofs, -1),
        case_names=names,
        loads=f,
        stiffness=AssembledMatrix(numbering=numbering, matrix=stiffness, kind="RIGI"),
        model=model,
        materials=kw.get("CHAM_MATER"),
        characteristics=kw.get("CARA_ELEM"),
    )
