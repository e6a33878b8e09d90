"""PROJ_CHAMP: nodal fields of a result (or one nodal field) projected from
mesh 1 onto the nodes of mesh 2 by collocation (METHODE 'AUTO' or
'COLLOCATION'), see asterlite.post.field_projection.

Mesh 1 is MAILLAGE_1 (or MODELE_1's mesh) and must carry the field; the
source cells are VIS_A_VIS's GROUP_MA_1 / MAILLE_1 (all cells otherwise),
the target nodes GROUP_MA_2 / GROUP_NO_2 / NOEUD_2 (otherwise the nodes
of MODELE_2's cells, or every node of MAILLAGE_2). The projected fields lie
on NUME_DDL when given, else on MODELE_2's DOFs, else on the target nodes
with the source's components; a DOF the projection does not reach holds
PROL_VALE (0 by default, as code_aster initialises its fields).
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import DofNumbering, NodalField
from asterlite.concepts.harmonic import DynaHarmo
from asterlite.concepts.modes import ModeResult
from asterlite.concepts.transient import DynaTrans
from asterlite.fem.dofs import sort_components
from asterlite.post import field_projection as fp
from asterlite.post.harmonic import frequency_indices
from asterlite.post.restitution import as_tuple, nearest_archived

# fields on the DOFs; nodal forces are interpolated as any nodal field, as code_aster does
_NODAL = ("DEPL", "VITE", "ACCE", "FORC_NODA", "REAC_NODA")
_REFUSED = (
    ("TRANSF_GEOM_1", "a geometric transformation of mesh 1"),
    ("TRANSF_GEOM_2", "a geometric transformation of mesh 2"),
    ("CAS_FIGURE", "a forced projection case"),
    ("NOEUD_CMP", "a selection by NOEUD_CMP"),
    ("NUME_MODE", "a selection by NUME_MODE"),
    ("NOM_PARA", "NOM_PARA"),
)


def run(ctx, kw):
    _refuse(ctx, kw)
    mesh_1 = kw["MAILLAGE_1"] if kw.get("MAILLAGE_1") is not None else kw["MODELE_1"].mesh
    model_2 = kw.get("MODELE_2")
    mesh_2 = kw["MAILLAGE_2"] if kw.get("MAILLAGE_2") is not None else model_2.mesh
    placement, _ = place(ctx, kw, mesh_1, mesh_2, model_2)
    if kw.get("CHAM_GD") is not None:
        return _project_field(ctx, kw, placement, mesh_1, mesh_2, model_2)
    return _project_result(ctx, kw, placement, mesh_1, mesh_2, model_2)


def place(ctx, kw, mesh_1, mesh_2, model_2) -> tuple[fp.Placement, np.ndarray]:
    """Where each target node of mesh 2 lies in the source cells of mesh 1
    (VIS_A_VIS pairs, or the whole meshes; DISTANCE_MAX), reported in the
    log; also the target nodes, in the order the pairs name them."""
    pairs = _pairs(ctx, kw, mesh_1, mesh_2, model_2)
    distance_max = kw.get("DISTANCE_MAX")
    placement = fp.Placement({}, [], 0.0)
    try:
        for cells, nodes, points in pairs:
            part = fp.place_nodes(mesh_1, cells, mesh_2, nodes, distance_max, points)
            placement.nodes.update(part.nodes)
            placement.unplaced.extend(n for n in part.unplaced if n not in placement.nodes)
            placement.farthest = max(placement.farthest, part.farthest)
    except fp.ProjectionUnsupported as exc:
        ctx.unsupported(f"{ctx.command}: {exc}", "METHODE" if "METHODE" in kw else None, kw)
    _report(ctx, kw, placement, mesh_2)
    targets = list(dict.fromkeys(int(n) for _, nodes, _ in pairs for n in nodes))
    return placement, np.asarray(targets, dtype=int)


# the dimension of the source cells each projection case uses
_CASE_DIMENSION = {"3D": 3, "2D": 2, "2.5D": 2, "1.5D": 1}


def _refuse(ctx, kw) -> None:
    if kw["PROJECTION"] == "NON" or kw.get("MATR_PROJECTION") is not None:
        ctx.unsupported(
            "PROJ_CHAMP correspondence concepts (PROJECTION='NON', MATR_PROJECTION)",
            "PROJECTION" if kw["PROJECTION"] == "NON" else "MATR_PROJECTION",
            kw,
        )
    method = kw["METHODE"]
    if method not in ("AUTO", "COLLOCATION"):
        ctx.unsupported(f"PROJ_CHAMP METHODE={method!r}", "METHODE", kw)
    for keyword, what in _REFUSED:
        if kw.get(keyword) is not None:
            ctx.unsupported(f"PROJ_CHAMP with {what}", keyword, kw)
    for occ in kw.factor("VIS_A_VIS"):
        refused = (
            ("TRANSF_GEOM_1", "a geometric transformation of mesh 1"),
            ("GROUP_NO_1", "cells chosen by GROUP_NO_1"),
        )
        for keyword, what in refused:
            if occ.get(keyword) is not None:
                ctx.unsupported(f"PROJ_CHAMP VIS_A_VIS with {what}", keyword, occ)
        if occ.get("CAS_FIGURE") not in (None, *_CASE_DIMENSION):
            ctx.unsupported(
                f"PROJ_CHAMP VIS_A_VIS CAS_FIGURE={occ['CAS_FIGURE']!r}", "CAS_FIGURE", occ
            )
    # messages only: what a node's distance to its cell prints in code_aster
    kw.mark_used("ALARME", "TYPE_CHAM", "TITRE", "INFO")


def _prolongation(kw) -> float:
    """The value of the DOFs the projection does not reach: PROL_VALE, or 0
    with PROL_ZERO='OUI' (code_aster 17 turns PROL_ZERO='OUI' into
    PROL_VALE=0.0, over a PROL_VALE given too)."""
    if kw.get("PROL_ZERO") == "OUI":
        return 0.0
    return kw.get("PROL_VALE") or 0.0


def _pairs(ctx, kw, mesh_1, mesh_2, model_2):
    """(source cells, target nodes) of each VIS_A_VIS occurrence, or of the whole meshes."""
    occurrences = kw.factor("VIS_A_VIS")
    if not occurrences:
        return [
            (
                fp.source_cells(mesh_1, _model_cells(kw.get("MODELE_1"))),
                _all_targets(mesh_2, model_2),
                None,
            )
        ]
    pairs = []
    for occ in occurrences:
        cells = None if occ.get("TOUT_1") == "OUI" else _cells(ctx, occ, mesh_1, "_1")
        nodes = (
            _all_targets(mesh_2, model_2)
            if occ.get("TOUT_2") == "OUI"
            else _nodes(ctx, occ, mesh_2)
        )
        dimension = _CASE_DIMENSION.get(occ.get("CAS_FIGURE"))
        chosen = fp.source_cells(mesh_1, cells, dimension)
        if dimension is not None and chosen.size == 0:
            ctx.error(
                f"CAS_FIGURE={occ['CAS_FIGURE']!r}: no cell of dimension {dimension} among "
                "the cells of mesh 1",
                "CAS_FIGURE",
                occ,
            )
        pairs.append((chosen, nodes, _transformed(ctx, occ, mesh_2, nodes)))
    return pairs


def _transformed(ctx, occ, mesh_2, nodes):
    """TRANSF_GEOM_2: the points where mesh 2's nodes are looked for in
    mesh 1, (f_x, f_y[, f_z]) of each node's (X, Y, Z); None without it."""
    functions = as_tuple(occ.get("TRANSF_GEOM_2"))
    if not functions:
        return None
    coords = np.asarray(mesh_2.coords, dtype=float)[nodes]
    if len(functions) > coords.shape[1]:
        ctx.error(
            f"TRANSF_GEOM_2 gives {len(functions)} functions for {coords.shape[1]} coordinates",
            "TRANSF_GEOM_2",
            occ,
        )
    at = {name: coords[:, k] for k, name in enumerate(("X", "Y", "Z")[: coords.shape[1]])}
    # two functions (a plane mesh): the third coordinate is kept
    points = coords.copy()
    for k, function in enumerate(functions):
        names = tuple(getattr(function, "nom_para", ()) or ())
        unknown = [p for p in names if p not in at and p != "TOUTPARA"]
        if unknown:
            ctx.error(
                f"TRANSF_GEOM_2: the function {function.name or ''} depends on "
                f"{', '.join(unknown)} (X, Y, Z expected)",
                "TRANSF_GEOM_2",
                occ,
            )
        # DEFI_CONSTANTE's TOUTPARA takes any value: the first coordinate
        values = function.evaluate_many(*[at.get(p, coords[:, 0]) for p in names])
        points[:, k] = np.broadcast_to(np.real(np.asarray(values, dtype=complex)), len(nodes))
    return points


def _model_cells(model):
    if model is None:
        return None
    return np.asarray(sorted(model.cell_modelisation), dtype=int)


def _all_targets(mesh_2, model_2) -> np.ndarray:
    if model_2 is None:
        return np.arange(mesh_2.n_nodes)
    return np.array(sorted(model_2.node_components()), dtype=int)


def _cells(ctx, occ, mesh, suffix) -> np.ndarray:
    chosen: list[int] = []
    for name in as_tuple(occ.get("GROUP_MA" + suffix)):
        if name not in mesh.cell_groups:
            ctx.error(f"mesh 1 has no cell group {name!r}", "GROUP_MA" + suffix, occ)
        chosen.extend(int(c) for c in mesh.cell_groups[name])
    for name in as_tuple(occ.get("MAILLE" + suffix)):
        found = mesh.find_cell(str(name))
        if found is None:
            ctx.error(f"mesh 1 has no cell {name!r}", "MAILLE" + suffix, occ)
        chosen.append(found)
    return np.array(list(dict.fromkeys(chosen)), dtype=int)


def _nodes(ctx, occ, mesh) -> np.ndarray:
    chosen: list[int] = []
    for name in as_tuple(occ.get("GROUP_MA_2")):
        if name not in mesh.cell_groups:
            ctx.error(f"mesh 2 has no cell group {name!r}", "GROUP_MA_2", occ)
        for cell in mesh.cell_groups[name]:
            chosen.extend(mesh.cell_nodes[cell])
    for name in as_tuple(occ.get("GROUP_NO_2")):
        if name not in mesh.node_groups:
            ctx.error(f"mesh 2 has no node group {name!r}", "GROUP_NO_2", occ)
        chosen.extend(int(n) for n in mesh.node_groups[name])
    for name in as_tuple(occ.get("NOEUD_2")):
        found = mesh.find_node(str(name))
        if found is None:
            ctx.error(f"mesh 2 has no node {name!r}", "NOEUD_2", occ)
        chosen.append(found)
    return np.array(list(dict.fromkeys(int(n) for n in chosen)), dtype=int)


def _report(ctx, kw, placement, mesh_2) -> None:
    ctx.log(f"{len(placement.nodes)} nodes of mesh 2 placed in mesh 1")
    if placement.unplaced:
        names = ", ".join(mesh_2.node_names[n] for n in placement.unplaced[:5])
        ctx.log(f"<A> {len(placement.unplaced)} nodes of mesh 2 not projected ({names}...)")
    alarm = kw.get("DISTANCE_ALARME")
    if placement.farthest and (alarm is None or placement.farthest > alarm):
        ctx.log(f"<A> a node was projected from {placement.farthest:.3e} outside its cell")


def _target_numbering(ctx, kw, mesh_2, model_2, source: DofNumbering) -> DofNumbering:
    numbering = kw.get("NUME_DDL")
    if numbering is not None:
        if numbering.mesh is not mesh_2:
            ctx.error("NUME_DDL is not a numbering of mesh 2", "NUME_DDL", kw)
        return numbering
    if model_2 is not None:
        from asterlite.commands.nume_ddl import numbering_for

        return numbering_for(model_2, [])
    components = sort_components({c for _, c in source.dofs})
    dofs = [(n, c) for n in range(mesh_2.n_nodes) for c in components]
    return DofNumbering(mesh=mesh_2, dofs=dofs)


def _check_source_mesh(ctx, kw, numbering, mesh_1, keyword) -> None:
    if numbering.mesh is not mesh_1:
        where = "MAILLAGE_1" if kw.get("MAILLAGE_1") is not None else "MODELE_1"
        ctx.error(f"the {keyword} does not lie on mesh 1", where, kw)


def _project_field(ctx, kw, placement, mesh_1, mesh_2, model_2) -> NodalField:
    field = kw["CHAM_GD"]
    if not isinstance(field, NodalField):
        ctx.unsupported("PROJ_CHAMP of an element field", "CHAM_GD", kw)
    _check_source_mesh(ctx, kw, field.numbering, mesh_1, "field")
    target = _target_numbering(ctx, kw, mesh_2, model_2, field.numbering)
    values, _ = fp.project_values(
        placement,
        field.numbering.index,
        np.asarray(field.values)[None, :],
        target.dofs,
        _prolongation(kw),
    )
    return NodalField(numbering=target, values=values[0])


def _project_result(ctx, kw, placement, mesh_1, mesh_2, model_2):
    result = kw["RESULTAT"]
    if isinstance(result, DynaHarmo):
        return _project_harmonic(ctx, kw, result, placement, mesh_1, mesh_2, model_2)
    if not isinstance(result, (DynaTrans, ModeResult)):
        ctx.unsupported(f"PROJ_CHAMP of a {result.aster_type}", "RESULTAT", kw)
    _check_source_mesh(ctx, kw, result.numbering, mesh_1, "result")
    target = _target_numbering(ctx, kw, mesh_2, model_2, result.numbering)
    default = _prolongation(kw)
    if isinstance(result, ModeResult):
        return _project_modes(ctx, kw, result, placement, target, default)
    names = _field_names(ctx, kw, list(result.fields))
    picked = _instants(ctx, kw, result.times, result.order)
    fields = {}
    for name in names:
        values, missed = fp.project_values(
            placement, result.numbering.index, result.fields[name][picked], target.dofs, default
        )
        fields[name] = values
    ctx.log(f"{len(names)} fields at {len(picked)} instants projected on {target.n_dofs} DOFs")
    return DynaTrans(
        numbering=target,
        times=result.times[picked].copy(),
        order=result.order[picked].copy(),
        fields=fields,
    )


def _project_harmonic(ctx, kw, result, placement, mesh_1, mesh_2, model_2) -> DynaHarmo:
    """A dyna_harmo: its complex nodal fields at the chosen frequencies (FREQ,
    LIST_FREQ within PRECISION / CRITERE, NUME_ORDRE, LIST_ORDRE or all)."""

    _check_source_mesh(ctx, kw, result.numbering, mesh_1, "result")
    target = _target_numbering(ctx, kw, mesh_2, model_2, result.numbering)
    names = _field_names(ctx, kw, list(result.fields))
    picked = None
    for key in ("FREQ", "LIST_FREQ"):
        if kw.get(key) is not None:
            wanted = getattr(kw[key], "values", kw[key])
            try:
                picked = frequency_indices(
                    result.frequencies, wanted, kw["PRECISION"], kw["CRITERE"]
                )
            except Exception as exc:  # CommandError naming the frequency
                ctx.error(str(exc), key, kw)
    if picked is None:
        picked = _instants(ctx, kw, result.frequencies, result.order)
    fields = {}
    for name in names:
        fields[name], _ = fp.project_values(
            placement,
            result.numbering.index,
            result.fields[name][picked],
            target.dofs,
            _prolongation(kw),
        )
    ctx.log(f"{len(names)} fields at {len(picked)} frequencies projected on {target.n_dofs} DOFs")
    return DynaHarmo(
        numbering=target,
        frequencies=np.asarray(result.frequencies)[picked].copy(),
        order=np.asarray(result.order)[picked].copy(),
        fields=fields,
        model=model_2,
    )


def _field_names(ctx, kw, available) -> list[str]:
    if kw.get("NOM_CHAM") is not None:
        names = list(as_tuple(kw["NOM_CHAM"]))
        for name in names:
            if name not in available:
                ctx.error(f"the result has no field {name}", "NOM_CHAM", kw)
            if name not in _NODAL:
                ctx.unsupported(f"PROJ_CHAMP of field {name} (nodal fields only)", "NOM_CHAM", kw)
        return names
    kw.mark_used("TOUT_CHAM")  # every field: the default
    return [n for n in available if n in _NODAL]


def _instants(ctx, kw, times, order) -> np.ndarray:
    times = np.asarray(times, dtype=float)
    for key in ("INST", "LIST_INST", "FREQ", "LIST_FREQ"):
        if kw.get(key) is not None:
            wanted = getattr(kw[key], "values", kw[key])
            try:
                return nearest_archived(times, wanted, kw["PRECISION"], kw["CRITERE"])
            except Exception as exc:  # CommandError with the instants
                ctx.error(str(exc), key, kw)
    for key in ("NUME_ORDRE", "LIST_ORDRE"):
        if kw.get(key) is not None:
            wanted = [int(v) for v in np.atleast_1d(getattr(kw[key], "values", kw[key]))]
            lookup = {int(o): i for i, o in enumerate(order)}
            missing = [w for w in wanted if w not in lookup]
            if missing:
                ctx.error(f"order {missing[0]} is not in the result", key, kw)
            return np.array([lookup[w] for w in wanted], dtype=int)
    kw.mark_used("TOUT_ORDRE")  # every stored state: the default
    return np.arange(times.size)


def _project_modes(ctx, kw, modes, placement, target, default) -> ModeResult:
    names = _field_names(ctx, kw, ["DEPL"])
    if names != ["DEPL"]:
        ctx.unsupported("PROJ_CHAMP of modes: DEPL only", "NOM_CHAM", kw)
    # NUME_ORDRE counts the stored modes from 1 (NUME_MODE is a parameter)
    orders = np.arange(1, modes.n_modes + 1)
    picked = _instants(ctx, kw, modes.frequencies, orders)
    shapes, _ = fp.project_values(
        placement, modes.numbering.index, modes.shapes[:, picked].T, target.dofs, default
    )
    projected = modes.select(picked)
    projected.numbering = target
    projected.shapes = shapes.T.copy()
    projected.mass = projected.stiffness = projected.damping = None
    return projected
