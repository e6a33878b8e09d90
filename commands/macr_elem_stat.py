"""MACR_ELEM_STAT: a static superelement condensed on its external nodes
(code_aster's op0086).

DEFINITION names the model, EXTERIEUR the external nodes (their DOFs are
the components the model gives them). RIGI_MECA, MASS_MECA and AMOR_MECA
compute the condensed matrices, in the same call or in later ones
(reuse): from the finite elements by static (Guyan) condensation, the
interior held by CHAR_MACR_ELEM's relations taken homogeneous (its imposed
values would only matter to condensed load cases); external DOFs it blocks
have no stiffness or mass in the superelement and stay blocked in the
models using it (NUME_DDL adds those relations), as a relation between
external DOFs only does; one binding external and interior DOFs is refused; or, with PROJ_MESU and
MODE_MESURE, from the measured projection as code_aster's crmeri / crmema /
crmeam do (:mod:`asterlite.substructure.static_condensation`). Masses and
damping need the stiffness first, as in code_aster; a finite-element
superelement has no AMOR_MECA (code_aster refuses it too). CAS_CHARGE
condenses load cases of a finite-element superelement (the superelements
it holds bring their case of the same name): f_c = Uᵀ (f - K u_p) with u_p
the response, external DOFs held, to the forces and to the imposed values of its loads' relations
(those of CHAR_MACR_ELEM; other kinematic conditions are refused).
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from asterlite.commands.nume_ddl import numbering_for

from asterlite.concepts.modes import ModeResult
from asterlite.concepts.static_substructure import LoadCase, StaticMacroElement
from asterlite.fem.assemble import assemble_blocks, assemble_terms
from asterlite.fem.constraints import relation_matrix
from asterlite.fem.elements import ElementError
from asterlite.fem.loads import load_terms
from asterlite.fem.options import option_blocks
from asterlite.fem.selection import select_nodes
from asterlite.substructure import static_condensation as sc


def run(ctx, kw):
    macro = kw.get("MACR_ELEM") or ctx.reuse
    if kw.factor("DEFINITION"):
        if macro is not None:
            ctx.error("the superelement is already defined (DEFINITION given again)", "DEFINITION")
        macro = _define(ctx, kw)
    elif macro is None:
        ctx.error("give DEFINITION (or the superelement to complete in MACR_ELEM)", "DEFINITION")
    if kw.factor("RIGI_MECA"):
        if "RIGI" in macro.matrices:
            ctx.error("the superelement's stiffness is already computed", "RIGI_MECA")
        macro.matrices["RIGI"] = _stiffness(ctx, kw, macro)
    for keyword, kind in (("MASS_MECA", "MASS"), ("AMOR_MECA", "AMOR")):
        if not kw.factor(keyword):
            continue
        if "RIGI" not in macro.matrices:
            ctx.error(f"{keyword} needs the stiffness first (RIGI_MECA)", keyword)
        if kind in macro.matrices:
            ctx.error(f"the superelement's {keyword} is already computed", keyword)
        macro.matrices[kind] = _other(ctx, kw, macro, kind, keyword)
    for occ in kw.factor("CAS_CHARGE"):
        _load_case(ctx, occ, macro)
    ctx.log(
        f"MACR_ELEM_STAT: {len(macro.external_nodes)} external nodes, {macro.n_external} "
        f"external DOFs; matrices {', '.join(sorted(macro.matrices))}"
    )
    return macro


def _define(ctx, kw) -> StaticMacroElement:
    definition = kw.factor("DEFINITION")[0]
    model = definition["MODELE"]
    mesh = model.mesh
    exterior = kw.factor("EXTERIEUR")[0]
    nodes = np.asarray(select_nodes(ctx, exterior, mesh), dtype=int)
    carried = model.node_components()
    missing = [mesh.node_names[n] for n in nodes if n not in carried]
    if missing:
        ctx.error(f"external nodes outside the model: {', '.join(missing[:5])}", "EXTERIEUR")
    components = {carried[n] for n in nodes}
    if len(components) != 1:
        ctx.unsupported(
            "MACR_ELEM_STAT with external nodes carrying different components",
            "EXTERIEUR",
            kw,
        )
    macro = StaticMacroElement(
        model=model, mesh=mesh, external_nodes=nodes, components=components.pop()
    )
    macro.definition = definition
    characteristics = definition.get("CARA_ELEM")
    if characteristics is not None and characteristics.model is not model:
        ctx.error("CARA_ELEM was built on another model", "CARA_ELEM", definition)
    load = definition.get("CHAR_MACR_ELEM")
    if load is not None and load.model is not model:
        ctx.error("CHAR_MACR_ELEM was built on another model", "CHAR_MACR_ELEM", definition)
    materials = definition.get("CHAM_MATER")
    if materials is not None and materials.mesh is not mesh:
        ctx.error("CHAM_MATER lies on another mesh", "CHAM_MATER", definition)
    if definition.get("PROJ_MESU") is not None:
        if load is not None:
            ctx.unsupported(
                "MACR_ELEM_STAT PROJ_MESU with CHAR_MACR_ELEM", "CHAR_MACR_ELEM", definition
            )
        _measured(ctx, definition, macro)
    return macro


def _measured(ctx, definition, macro: StaticMacroElement) -> None:
    """The superelement of a measured projection (crmeri's T and V)."""
    projection = definition["PROJ_MESU"]
    sensors = getattr(projection, "measurement", None)
    if sensors is None:
        ctx.error("PROJ_MESU is not a PROJ_MESU_MODAL result of displacements", "PROJ_MESU")
    modes = definition["MODE_MESURE"]
    if not isinstance(modes, ModeResult) or modes.numbering.mesh is not (
        sensors.measurement_model.mesh
    ):
        ctx.error("MODE_MESURE does not lie on the measurement mesh of PROJ_MESU", "MODE_MESURE")
    basis = sensors.basis
    if basis.numbering.mesh is not macro.mesh:
        ctx.error("PROJ_MESU's basis does not lie on the superelement's mesh", "PROJ_MESU")
    nodes = np.repeat(macro.external_nodes, len(macro.components))
    components = list(macro.components) * len(macro.external_nodes)
    rows = basis.numbering.dof_indices(nodes, components)
    if np.any(rows < 0):
        ctx.error("PROJ_MESU's basis lacks external DOFs of the superelement", "PROJ_MESU")
    identified = np.zeros((len(sensors.sensors), modes.n_modes))
    for k, (node, direction, _) in enumerate(sensors.sensors):
        for axis, name in enumerate(("DX", "DY", "DZ")):
            if direction[axis] != 0.0:
                identified[k] += direction[axis] * modes.shapes_at([node], name)[0]
    mass = np.asarray(modes.generalized_mass, dtype=float)
    if not np.all(np.isfinite(mass)):
        ctx.error("MODE_MESURE has no generalized masses (MASS_GENE)", "MODE_MESURE")
    damping = modes.parameters.get("AMOR_GENE")
    try:
        macro.measured = sc.measured(
            sensors.observation,
            basis.shapes[rows, :],
            identified,
            modes.omega2,
            mass,
            None if damping is None else np.asarray(damping, dtype=float),
        )
    except sc.CondensationError as exc:
        ctx.error(str(exc), "PROJ_MESU")
    macro.sensors = sensors
    macro.measured_modes = modes


def _external_dofs(ctx, macro, numbering) -> np.ndarray:
    nodes = np.repeat(macro.external_nodes, len(macro.components))
    components = list(macro.components) * len(macro.external_nodes)
    return numbering.dof_indices(nodes, components)


def _stiffness(ctx, kw, macro: StaticMacroElement) -> np.ndarray:
    if macro.measured is not None:
        return macro.measured.matrix("RIGI")
    definition = macro.definition
    loads = [definition["CHAR_MACR_ELEM"]] if definition.get("CHAR_MACR_ELEM") else []
    numbering = numbering_for(macro.model, loads)
    external = _external_dofs(ctx, macro, numbering)
    b_matrix, _ = relation_matrix(numbering.relations, numbering.index, numbering.n_dofs)
    b_matrix = sp.csr_matrix(b_matrix)
    counts = np.diff(b_matrix.indptr)
    single = b_matrix.indices[b_matrix.indptr[:-1][counts == 1]]
    # an external DOF CHAR_MACR_ELEM blocks stays blocked where the
    # superelement is placed (a relation of the models using it)
    macro.blocked_external = np.isin(external, single)
    free = external[~macro.blocked_external]
    # a relation between external DOFs only goes with them too; one binding
    # external and interior DOFs is refused
    is_free_external = np.zeros(numbering.n_dofs, dtype=bool)
    is_free_external[free] = True
    position = np.full(numbering.n_dofs, -1)
    position[external] = np.arange(external.size)
    inside, macro.external_relations = [], []
    for row in np.flatnonzero(counts > 1):
        dofs = b_matrix.indices[b_matrix.indptr[row] : b_matrix.indptr[row + 1]]
        coefficients = b_matrix.data[b_matrix.indptr[row] : b_matrix.indptr[row + 1]]
        touching = is_free_external[dofs]
        if touching.all():
            macro.external_relations.append((position[dofs], coefficients.copy()))
        elif touching.any():
            ctx.unsupported(
                "MACR_ELEM_STAT CHAR_MACR_ELEM with a relation binding external and interior DOFs",
                "CHAR_MACR_ELEM",
                definition,
            )
        else:
            inside.append(row)
    rows = np.concatenate([np.flatnonzero(counts <= 1), inside]).astype(int)
    b_matrix = b_matrix[np.sort(rows)]
    stiffness = _assembled(ctx, macro, "RIGI_MECA", numbering)
    try:
        macro.guyan = sc.constrained_guyan(stiffness, b_matrix, free)
    except sc.CondensationError as exc:
        ctx.error(str(exc), "DEFINITION")
    macro.numbering = numbering
    macro.stiffness = stiffness
    macro.inside_relations = np.sort(rows)
    macro.blocked = single
    return _on_external(macro, macro.guyan.stiffness)


def _on_external(macro, condensed: np.ndarray) -> np.ndarray:
    """A matrix of the free external DOFs on all of them (zero on the blocked)."""
    keep = np.flatnonzero(~macro.blocked_external)
    out = np.zeros((macro.n_external, macro.n_external))
    out[np.ix_(keep, keep)] = condensed
    return out


def _other(ctx, kw, macro: StaticMacroElement, kind: str, keyword: str):
    if macro.measured is not None:
        if kind == "AMOR" and macro.measured.generalized_damping is None:
            # as code_aster, computed from MODE_MESURE's AMOR_GENE: refused
            # where it is used, since the deck may never assemble it
            return None
        return macro.measured.matrix(kind)
    if kind == "AMOR":
        ctx.unsupported(
            "MACR_ELEM_STAT AMOR_MECA of a finite-element superelement (code_aster builds it "
            "only from a measured projection)",
            keyword,
            kw,
        )
    mass = _assembled(ctx, macro, "MASS_MECA", macro.numbering)
    return _on_external(macro, macro.guyan.condense(mass))


def _assembled(ctx, macro, option, numbering):
    definition = macro.definition
    try:
        blocks = option_blocks(
            macro.model,
            definition.get("CARA_ELEM"),
            option,
            materials=definition.get("CHAM_MATER"),
        )
    except NotImplementedError as exc:
        ctx.unsupported(str(exc), "MODELE", definition)
    except (ElementError, ValueError) as exc:
        ctx.error(str(exc), "DEFINITION")
    return assemble_blocks(blocks, numbering)


def _load_case(ctx, occ, macro: StaticMacroElement) -> None:
    """CAS_CHARGE: the condensed load of the case's loads and the interior
    response that DEPL_INTERNE NOM_CAS adds (code_aster's sschge)."""
    name = str(occ["NOM_CAS"])
    if "RIGI" not in macro.matrices or macro.guyan is None:
        ctx.error("CAS_CHARGE needs the finite-element stiffness first (RIGI_MECA)", "CAS_CHARGE")
    if name in macro.load_cases:
        ctx.error(f"the load case {name} is already defined", "NOM_CAS", occ)
    loads = list(np.atleast_1d(occ.get("CHARGE") or ()))
    numbering = macro.numbering
    known = {id(r) for r in numbering.relations}
    definition = macro.definition
    forces = np.zeros(numbering.n_dofs)
    for load in loads:
        if load.model is not macro.model:
            ctx.error("a CHARGE of the case was built on another model", "CHARGE", occ)
        if any(id(r) not in known for r in load.relations):
            ctx.unsupported(
                "CAS_CHARGE with kinematic conditions other than CHAR_MACR_ELEM's", "CHARGE", occ
            )
        try:
            terms = load_terms(load, definition.get("CARA_ELEM"), definition.get("CHAM_MATER"))
            forces += assemble_terms(terms, numbering)
        except NotImplementedError as exc:
            ctx.unsupported(str(exc), "CHARGE", occ)
        except (ElementError, ValueError, KeyError) as exc:
            ctx.error(f"CAS_CHARGE {name}: {exc}", "CHARGE", occ)
    for cell in macro.model.substructures.values():
        # the superelements inside bring their case of the same name (ss2mm2)
        if name in cell.macro.load_cases:
            try:
                forces += assemble_terms(cell.load_terms(name), numbering)
            except ValueError as exc:
                ctx.unsupported(str(exc), "CAS_CHARGE", occ)
    given = {id(r) for load in loads for r in load.relations}
    values = np.array([r.rhs if id(r) in given else 0.0 for r in numbering.relations])
    b_matrix, _ = relation_matrix(numbering.relations, numbering.index, numbering.n_dofs)
    carried = np.setdiff1d(np.arange(len(values)), macro.inside_relations)
    if np.any(values[carried] != 0.0):
        ctx.unsupported("CAS_CHARGE imposing a value on a relation of external DOFs", "CHARGE", occ)
    b_matrix, values = (
        sp.csr_matrix(b_matrix)[macro.inside_relations],
        values[macro.inside_relations],
    )
    try:
        condensed, interior = sc.condensed_load(
            macro.guyan, macro.stiffness, b_matrix, values, forces
        )
    except sc.CondensationError as exc:
        ctx.error(str(exc), "CAS_CHARGE")
    full = np.zeros(macro.n_external)
    full[np.flatnonzero(~macro.blocked_external)] = condensed
    macro.load_cases[name] = LoadCase(
        vector=full,
        interior=interior,
        follows=occ.get("SUIV", "OUI") == "OUI",
        forces=forces,
        relations=b_matrix,
        values=values,
    )
    ctx.log(f"CAS_CHARGE {name}: {len(loads)} loads condensed")
