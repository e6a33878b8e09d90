"""OBSERVATION: the fields of a result as sensors would measure them
(code_aster's observation_ops macro).

For each field of NOM_CHAM (DEPL, VITE, ACCE on the result's DOFs,
EPSI_NOEU from CALC_CHAMP), at the chosen orders:

1. EPSI_MOYENNE (EPSI_NOEU only): each occurrence is a strain gauge; its
   nodes (NOEUD, GROUP_NO, nodes of GROUP_MA) all take the gauge's mean
   strain, and the field is the gauges' nodes only. A component (not in
   MASQUE) whose values over the gauge stray from the mean by more than
   SEUIL_VARI x |mean| gives a warning.
2. PROJECTION='OUI': collocation onto the nodes of MODELE_2 (VIS_A_VIS,
   DISTANCE_MAX as PROJ_CHAMP), where a cell lacking some values
   interpolates with the others as code_aster's cnsprj does; DEPL, VITE,
   ACCE lie on the DOFs of MODELE_2, zero where the projection does not
   reach.
3. MODI_REPERE: TENS_2D / TENS_3D occurrences turn EPSI_NOEU at the nodes of
   their GROUP_MA, VECT_2D / VECT_3D occurrences turn DEPL (not VITE nor
   ACCE, as in code_aster) at their NOEUD / GROUP_NO / GROUP_MA nodes, into
   the frame of REPERE: UTILISATEUR (ANGL_NAUT), CYLINDRIQUE (ORIGINE,
   AXE_Z, per node), DIR_JAUGE (VECT_X / VECT_Y, see
   :func:`asterlite.post.observation.gauge_axes`) or NORMALE (at each node
   of the occurrence on MODELE_2's mesh, VECT_X or VECT_Y with the normal
   of MODELE_1's skin cells collocated there, 3D meshes).
4. FILTRE: the occurrences naming the field keep the DDL_ACTIF components
   at their nodes; a field no occurrence names is kept whole.

The result has the type of RESULTAT and holds the observed fields only, on
MODELE_2 when projected, else on MODELE_1. The order selection (TOUT_ORDRE,
NUME_ORDRE, NUME_MODE, FREQ, LIST_FREQ, INST, LIST_INST; frequencies and
instants within 1e-6 relative) applies to every field. A mode_meca keeps
MATR_RIGI and MATR_MASS when a FILTRE applies, and an unfiltered DEPL lies
on MATR_RIGI's numbering, as code_aster does. NOEUD_CMP, CAS_FIGURE and
NORMALE on a plane mesh are refused by name.
"""

from __future__ import annotations

import copy

import numpy as np
from asterlite.commands.modi_repere import cylindrical_axes
from asterlite.commands.proj_champ import place

from asterlite.catalog.keywords import Keywords
from asterlite.concepts.assembly import DofNumbering
from asterlite.concepts.harmonic import DynaHarmo
from asterlite.concepts.modes import ModeResult
from asterlite.fem.element_errors import ElementError
from asterlite.fem.frames import rotation_from_angles
from asterlite.fem.node_normals import node_normals
from asterlite.fem.selection import as_tuple, select_cells, select_nodes
from asterlite.post import observation as obs
from asterlite.post.harmonic import frequency_indices
from asterlite.post.restitution import nearest_archived

_DOF_FIELDS = ("DEPL", "VITE", "ACCE")
_OBSERVABLE = (*_DOF_FIELDS, "EPSI_NOEU")
# the field each MODI_REPERE type turns in code_aster's macro
_TURNED = {"TENS_2D": "EPSI_NOEU", "TENS_3D": "EPSI_NOEU", "VECT_2D": "DEPL", "VECT_3D": "DEPL"}
_PRECISION = 1.0e-6  # OBSERVATION has no CRITERE/PRECISION: PROJ_CHAMP's defaults


def run(ctx, kw):
    _refuse(ctx, kw)
    source = kw["RESULTAT"]
    model_1, model_2 = kw["MODELE_1"], kw["MODELE_2"]
    names = list(as_tuple(kw["NOM_CHAM"]))
    for name in names:
        if name not in _OBSERVABLE:
            ctx.error(
                f"OBSERVATION observes DEPL, VITE, ACCE or EPSI_NOEU, not {name}", "NOM_CHAM", kw
            )
    _check_keyword_targets(ctx, kw, names)
    if source.numbering.mesh is not model_1.mesh:
        ctx.error("RESULTAT does not lie on the mesh of MODELE_1", "MODELE_1", kw)
    states = _states(ctx, kw, source)
    projecting = kw["PROJECTION"] == "OUI"
    mesh_1 = model_1.mesh
    mesh = model_2.mesh if projecting else mesh_1
    model = model_2 if projecting else model_1
    if projecting:
        placement, targets = place(ctx, kw, mesh_1, model_2.mesh, model_2)
        target_dofs = set(_model_numbering(model_2).dofs)
    else:
        # PROJ_CHAMP's options reach only its copy of the result onto itself
        kw.mark_used("DISTANCE_MAX", "DISTANCE_ALARME")
        _check_self_pairs(ctx, kw)
    observed = {}
    for name in names:
        field = _source_field(ctx, kw, source, name, states)
        if name == "EPSI_NOEU" and kw.factor("EPSI_MOYENNE"):
            field = _gauges(ctx, kw, field, mesh_1, states)
        if projecting:
            field = obs.project(field, placement, targets)
            if name in _DOF_FIELDS:
                # on MODELE_2's DOFs, zero where the projection does not reach (PROJ_CHAMP)
                field.defined = _dof_mask(field, target_dofs)
        _turn(ctx, kw, name, field, mesh)
        chosen = _filters(ctx, kw, name, mesh)
        if chosen:
            field = obs.keep(field, chosen)
        observed[name] = (field, bool(chosen))
        ctx.log(
            f"OBSERVATION {name}: {int(field.defined.sum())} values at {field.nodes.size} nodes, "
            f"{len(states)} orders" + (" (filtered)" if chosen else "")
        )
    return _result(ctx, kw, source, states, observed, mesh, model)


def _refuse(ctx, kw) -> None:
    if kw.get("NOEUD_CMP") is not None:
        ctx.unsupported("OBSERVATION with a selection by NOEUD_CMP", "NOEUD_CMP", kw)
    if kw.get("CAS_FIGURE") is not None:
        ctx.unsupported("OBSERVATION with a forced projection case (CAS_FIGURE)", "CAS_FIGURE", kw)
    if kw.get("LIST_ORDRE") is not None:
        ctx.error(
            "LIST_ORDRE comes with one of TOUT_ORDRE, NUME_ORDRE, ... (the command's rule), "
            "a pair code_aster's PROJ_CHAMP refuses",
            "LIST_ORDRE",
            kw,
        )
    for occ in kw.factor("VIS_A_VIS"):
        if occ.get("GROUP_NO_1") is not None:
            ctx.unsupported(
                "OBSERVATION VIS_A_VIS with cells chosen by GROUP_NO_1", "GROUP_NO_1", occ
            )
        if as_tuple(occ.get("GROUP_MA_1")) != as_tuple(occ.get("GROUP_MA_2")):
            ctx.error(
                "VIS_A_VIS: GROUP_MA_1 and GROUP_MA_2 must name the same groups", "GROUP_MA_2", occ
            )
    for occ in kw.factor("MODI_REPERE"):
        if occ["REPERE"] == "NORMALE" and kw["MODELE_1"].mesh.dim != 3:
            ctx.unsupported(
                "OBSERVATION MODI_REPERE REPERE='NORMALE' on a plane mesh", "REPERE", occ
            )
        if occ.get("TOUT") is not None:
            ctx.error(
                "MODI_REPERE/TOUT: code_aster's OBSERVATION turns fields only where NOEUD, "
                "GROUP_NO or GROUP_MA say",
                "TOUT",
                occ,
            )
    # informative options of PROJ_CHAMP and the result (messages, nodal fields anyway)
    kw.mark_used("ALARME", "TYPE_CHAM", "TITRE", "INFO")


def _check_keyword_targets(ctx, kw, names) -> None:
    """Occurrences naming a field NOM_CHAM does not observe would change nothing."""
    if kw.factor("EPSI_MOYENNE") and "EPSI_NOEU" not in names:
        ctx.error(
            "EPSI_MOYENNE averages EPSI_NOEU, which NOM_CHAM does not give", "EPSI_MOYENNE", kw
        )
    for occ in kw.factor("MODI_REPERE"):
        turned = _TURNED[occ["TYPE_CHAM"]]
        if turned not in names:
            ctx.error(
                f"TYPE_CHAM={occ['TYPE_CHAM']!r} turns {turned}, which NOM_CHAM does not give",
                "TYPE_CHAM",
                occ,
            )
    for occ in kw.factor("FILTRE"):
        name = occ["NOM_CHAM"]
        if name not in names:
            ctx.error(f"FILTRE names {name}, which NOM_CHAM does not give", "NOM_CHAM", occ)
        family = "E" if name == "EPSI_NOEU" else "D"
        wrong = [c for c in as_tuple(occ["DDL_ACTIF"]) if not c.startswith(family)]
        if wrong:
            ctx.error(f"DDL_ACTIF {wrong[0]} is not a component of {name}", "DDL_ACTIF", occ)


def _check_self_pairs(ctx, kw) -> None:
    if kw.factor("VIS_A_VIS"):
        ctx.unsupported(
            "OBSERVATION VIS_A_VIS with PROJECTION='NON' (a copy of the result onto part of "
            "its own mesh)",
            "VIS_A_VIS",
            kw,
        )


# ---------------------------------------------------------------- orders


def _states(ctx, kw, source) -> np.ndarray:
    """Indices of the chosen stored states of ``source``."""
    if isinstance(source, ModeResult):
        orders, access = np.arange(1, source.n_modes + 1), np.asarray(source.frequencies)
    elif isinstance(source, DynaHarmo):
        orders, access = np.asarray(source.order), np.asarray(source.frequencies)
    else:
        orders, access = np.asarray(source.order), np.asarray(source.times)
    harmonic_like = isinstance(source, (ModeResult, DynaHarmo))
    if kw.get("TOUT_ORDRE") == "OUI":
        return np.arange(len(orders))
    for key in ("NUME_ORDRE", "NUME_MODE"):
        if kw.get(key) is not None:
            if key == "NUME_MODE" and not isinstance(source, ModeResult):
                ctx.error("NUME_MODE selects modes of a mode_meca", key, kw)
            known = orders if key == "NUME_ORDRE" else np.asarray(source.mode_numbers)
            lookup = {int(o): i for i, o in enumerate(known)}
            wanted = [int(v) for v in as_tuple(kw[key])]
            missing = [w for w in wanted if w not in lookup]
            if missing:
                ctx.error(f"{key} {missing[0]} is not in the result", key, kw)
            return np.array([lookup[w] for w in wanted], dtype=int)
    for key in ("FREQ", "LIST_FREQ", "INST", "LIST_INST"):
        if kw.get(key) is None:
            continue
        if key.endswith("FREQ") != harmonic_like:
            ctx.error(f"{key} does not select the orders of a {source.aster_type}", key, kw)
        wanted = getattr(kw[key], "values", kw[key])
        try:
            if harmonic_like:
                return np.asarray(frequency_indices(access, wanted, _PRECISION, "RELATIF"))
            return nearest_archived(access, wanted, _PRECISION, "RELATIF")
        except Exception as exc:  # CommandError naming the value
            ctx.error(str(exc), key, kw)
    return np.arange(len(orders))  # the catalogue's rule makes one of them present


# ---------------------------------------------------------------- fields


def _source_field(ctx, kw, source, name, states) -> obs.ObservedField:
    if name == "EPSI_NOEU":
        field = (getattr(source, "node_fields", None) or {}).get(name)
        if field is None:
            ctx.error(
                "the result has no EPSI_NOEU: compute it first (CALC_CHAMP DEFORMATION="
                "'EPSI_NOEU')",
                "NOM_CHAM",
                kw,
            )
        return obs.ObservedField.from_node_field(field, states)
    if isinstance(source, ModeResult):
        if name != "DEPL":
            ctx.error(f"a mode_meca holds no {name}", "NOM_CHAM", kw)
        values = np.asarray(source.shapes).T
    else:
        if name not in source.fields:
            ctx.error(f"the result has no field {name}", "NOM_CHAM", kw)
        values = np.asarray(source.fields[name])
    return obs.ObservedField.from_dofs(source.numbering, values[states])


def _gauges(ctx, kw, field, mesh, states) -> obs.ObservedField:
    gauges = []
    for occ in kw.factor("EPSI_MOYENNE"):
        nodes = select_nodes(ctx, occ, mesh)
        threshold = float(as_tuple(occ["SEUIL_VARI"])[0])
        gauges.append((nodes, threshold, as_tuple(occ.get("MASQUE"))))
    if mesh.dim == 2:
        # a plane mesh's gauges average the four plane strain components
        plane = [c for c in ("EPXX", "EPYY", "EPZZ", "EPXY") if c in field.components]
        field = obs.keep(field, [(field.nodes, tuple(plane))])
    try:
        averaged, variations = obs.gauge_average(field, gauges)
    except ValueError as exc:
        ctx.error(str(exc), "EPSI_MOYENNE", kw)
    occurrences = kw.factor("EPSI_MOYENNE")
    for index, variation in variations:
        where = as_tuple(occurrences[index].get("GROUP_MA")) or as_tuple(
            occurrences[index].get("GROUP_NO") or occurrences[index].get("NOEUD")
        )
        ctx.log(
            f"<A> gauge {', '.join(where)}: {variation.component} varies over the gauge by more "
            f"than SEUIL_VARI={gauges[index][1]:g} of its mean at order index "
            f"{int(states[variation.state]) + 1}"
        )
    return averaged


def _dof_mask(field, dofs: set) -> np.ndarray:
    mask = np.zeros_like(field.defined)
    for r, node in enumerate(field.nodes):
        for c, component in enumerate(field.components):
            mask[r, c] = (int(node), component) in dofs
    return mask


def _model_numbering(model) -> DofNumbering:
    from asterlite.commands.nume_ddl import numbering_for

    return numbering_for(model, [])


# ---------------------------------------------------------------- frames


def _turn(ctx, kw, name, field, mesh) -> None:
    for occ in kw.factor("MODI_REPERE"):
        kind = occ["TYPE_CHAM"]
        if _TURNED[kind] != name:
            continue
        tensor = kind.startswith("TENS")
        if occ["REPERE"] == "NORMALE":
            _turn_to_normals(ctx, kw, occ, name, field, mesh)
            continue
        if tensor:
            if occ.get("GROUP_MA") is None:
                ctx.error(
                    f"TYPE_CHAM={kind!r} turns strains at the nodes of cells: give GROUP_MA",
                    "GROUP_MA",
                    occ,
                )
            cells = select_cells(ctx, occ, mesh)
            nodes = mesh.nodes_of_cells(cells)
        else:
            nodes = select_nodes(ctx, occ, mesh)
        rows = field.rows_of(nodes)
        axes = _axes(ctx, occ, mesh.coords[field.nodes[rows]])
        names = as_tuple(occ["NOM_CMP"])
        if rows.size == 0:
            ctx.log(f"OBSERVATION {name}: no node of MODI_REPERE's selection holds a value")
            continue
        if kind.endswith("2D") and not obs.plane_rotation(axes):
            ctx.unsupported(
                f"TYPE_CHAM={kind!r} in a frame that does not turn about Z only", "REPERE", occ
            )
        try:
            turn = obs.rotate_tensors if tensor else obs.rotate_vectors
            turn(field, rows, names, axes)
        except ValueError as exc:
            ctx.error(f"{name}: {exc}", "NOM_CMP", occ)
        ctx.log(f"OBSERVATION {name} turned ({kind}, REPERE={occ['REPERE']}) at {rows.size} nodes")


def _turn_to_normals(ctx, kw, occ, name, field, mesh) -> None:
    """REPERE='NORMALE': at each node the occurrence names on MODELE_2's
    mesh, the frame of the normal there (MODELE_1's skin normals collocated
    onto MODELE_2's nodes, as code_aster's macro does) and VECT_X or VECT_Y."""
    sensors = kw["MODELE_2"].mesh
    normals = _sensor_normals(ctx, kw, occ)
    names = as_tuple(occ["NOM_CMP"])
    vect_x, vect_y = occ.get("VECT_X"), occ.get("VECT_Y")
    turn = obs.rotate_tensors if occ["TYPE_CHAM"].startswith("TENS") else obs.rotate_vectors
    count = 0
    for node in select_nodes(ctx, occ, sensors):
        label = sensors.node_names[int(node)]
        at = normals.rows_of([node])
        if at.size == 0 or not normals.defined[at[0]].all():
            ctx.error(f"no normal of MODELE_1's skin reaches node {label}", "REPERE", occ)
        own = node if mesh is sensors else mesh.find_node(label)
        rows = field.rows_of([own]) if own is not None else np.array([], dtype=int)
        if rows.size == 0:
            continue
        axes = obs.normal_axes(normals.values[0, at[0]].real, vect_x, vect_y)[None]
        try:
            turn(field, rows, names, axes)
        except ValueError as exc:
            ctx.error(f"{name}: {exc}", "NOM_CMP", occ)
        count += 1
    ctx.log(f"OBSERVATION {name} turned ({occ['TYPE_CHAM']}, REPERE=NORMALE) at {count} nodes")


def _sensor_normals(ctx, kw, occ) -> obs.ObservedField:
    """The unit normals of every cell of MODELE_1's mesh (skin cells, as
    code_aster's CREA_CHAMP NORMALE needs), collocated onto MODELE_2's nodes."""
    model_1, model_2 = kw["MODELE_1"], kw["MODELE_2"]
    mesh_1 = model_1.mesh
    cells = np.arange(mesh_1.n_cells)
    nodes = np.unique(mesh_1.nodes_of_cells(cells))
    try:
        normals = node_normals(mesh_1, cells, nodes, 3, log=ctx.log)
    except ElementError as exc:
        ctx.error(f"REPERE='NORMALE' takes the normals of every cell of MODELE_1: {exc}",
                  "REPERE", occ)  # fmt: skip
    field = obs.ObservedField(
        nodes, ("DX", "DY", "DZ"), normals[None], np.ones((nodes.size, 3), dtype=bool)
    )
    # the macro's own PROJ_CHAMP: the two models, none of the command's options
    alone = Keywords({"MODELE_1": model_1}, path=occ.path, location=occ.location)
    placement, targets = place(ctx, alone, mesh_1, model_2.mesh, model_2)
    return obs.project(field, placement, targets)


def _axes(ctx, occ, points) -> np.ndarray:
    """(n, 3, 3) global-to-local rotations at ``points``."""
    repere = occ["REPERE"]
    if repere == "CYLINDRIQUE":
        origin = np.zeros(3)
        given = np.asarray(as_tuple(occ["ORIGINE"]), dtype=float)
        origin[: given.size] = given
        return cylindrical_axes(points, origin, np.asarray(as_tuple(occ["AXE_Z"]), dtype=float))
    if repere == "UTILISATEUR":
        angles = np.zeros(3)
        given = np.radians(np.asarray(as_tuple(occ["ANGL_NAUT"]), dtype=float))
        angles[: given.size] = given
        rotation = rotation_from_angles(angles)
    else:
        vect_x, vect_y = occ.get("VECT_X"), occ.get("VECT_Y")
        try:
            rotation = obs.gauge_axes(vect_x, vect_y)
        except ValueError as exc:
            ctx.error(str(exc), "VECT_Y", occ)
    return np.broadcast_to(rotation, (len(points), 3, 3))


# ---------------------------------------------------------------- filter


def _filters(ctx, kw, name, mesh) -> list:
    chosen = []
    for occ in kw.factor("FILTRE"):
        if occ["NOM_CHAM"] != name:
            continue
        chosen.append((select_nodes(ctx, occ, mesh), as_tuple(occ["DDL_ACTIF"])))
    return chosen


# ---------------------------------------------------------------- result


def _result(ctx, kw, source, states, observed, mesh, model):
    dof_names = [n for n in observed if n in _DOF_FIELDS]
    numbering, values = _dof_layout(ctx, kw, source, observed, dof_names, mesh, model)
    node_fields = {n: f.node_field(n) for n, (f, _) in observed.items() if n not in _DOF_FIELDS}
    if isinstance(source, ModeResult):
        result = _modes(ctx, kw, source, states, observed, numbering, values)
    elif isinstance(source, DynaHarmo):
        result = DynaHarmo(
            numbering=numbering,
            frequencies=np.asarray(source.frequencies)[states].copy(),
            order=np.asarray(source.order)[states].copy(),
            fields=values,
            model=model,
            materials=source.materials,
            characteristics=source.characteristics,
        )
    else:
        result = copy.copy(source)
        result.name = None
        result.numbering = numbering
        result.times = np.asarray(source.times)[states].copy()
        result.order = np.asarray(source.order)[states].copy()
        result.fields = values
        result.model = model
        result.mass_matrix = None
        result.loads = ()
        result.modal_source = None
        result.tables = {}
    if not isinstance(source, ModeResult):
        kw.mark_used("MATR_RIGI", "MATR_MASS")  # code_aster reads them for a mode_meca only
    result.element_fields = {}
    result.node_fields = node_fields
    return result


def _dof_layout(ctx, kw, source, observed, names, mesh, model):
    """The numbering the DOF fields share and their (n_states, n_dofs) values."""
    if not names:
        return source.numbering if source.numbering.mesh is mesh else _model_numbering(model), {}
    layouts = {n: observed[n][0].dofs() for n in names}
    first = layouts[names[0]]
    for name in names[1:]:
        if set(layouts[name]) != set(first):
            ctx.unsupported(
                f"OBSERVATION of {names[0]} and {name} on different DOFs (FILTRE): asterlite "
                "keeps one numbering per result",
                "FILTRE",
                kw,
            )
    numbering = _target(ctx, kw, source, observed, names, first, mesh, model)
    values = {}
    for name in names:
        field = observed[name][0]
        index = {dof: k for k, dof in enumerate(field.dofs())}
        own = field.dof_values()
        out = np.zeros((own.shape[0], numbering.n_dofs), dtype=own.dtype)
        for j, dof in enumerate(numbering.dofs):
            if dof in index:
                out[:, j] = own[:, index[dof]]
        values[name] = out
    return numbering, values


def _target(ctx, kw, source, observed, names, dofs, mesh, model) -> DofNumbering:
    filtered = any(observed[n][1] for n in names)
    stiffness = kw.get("MATR_RIGI") if isinstance(source, ModeResult) else None
    if not filtered and stiffness is not None:
        # code_aster copies an unfiltered mode_meca onto MATR_RIGI's numbering
        if stiffness.numbering.mesh is not mesh:
            ctx.error("MATR_RIGI is not on the mesh of the observed fields", "MATR_RIGI", kw)
        return stiffness.numbering
    if source.numbering.mesh is mesh and set(source.numbering.dofs) == set(dofs):
        return source.numbering
    return DofNumbering(mesh=mesh, dofs=list(dofs), model=model)


def _modes(ctx, kw, source, states, observed, numbering, values) -> ModeResult:
    result = source.select(states)
    result.name = None
    result.numbering = numbering
    if "DEPL" in values:
        result.shapes = values["DEPL"].T.copy()
    else:
        result.shapes = np.zeros((numbering.n_dofs, len(states)))
    result.mass = result.stiffness = result.damping = None
    if kw.get("MATR_RIGI") is None and kw.get("MATR_MASS") is None:
        ctx.log("<A> OBSERVATION of a mode_meca without MATR_RIGI / MATR_MASS: none kept")
    if any(filtered for _, filtered in observed.values()):
        # code_aster keeps the matrices with the filtered modes
        result.stiffness, result.mass = kw.get("MATR_RIGI"), kw.get("MATR_MASS")
    return result
