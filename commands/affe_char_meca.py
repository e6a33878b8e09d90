"""AFFE_CHAR_MECA: kinematic relations (DDL_IMPO, LIAISON_DDL, LIAISON_UNIF,
LIAISON_SOLIDE, LIAISON_GROUP, LIAISON_CHAMNO, LIAISON_ELEM 3D_POU and 3D_POU_ARLEQUIN, FACE_IMPO)
and loads (FORCE_NODALE, PESANTEUR, FORCE_POUTRE, FORCE_ELEC, FORCE_TUYAU, FORCE_ARETE
on the edges of DKT plates; FORCE_FACE, PRES_REP,
FORCE_INTERNE on 3D solids; PRES_REP, FORCE_CONTOUR on the edges and
FORCE_INTERNE on the surfaces of plane models) on a model."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import LinearRelation, MechanicalLoad
from asterlite.fem.elements import ElementError
from asterlite.fem.frames import rotation_from_angles
from asterlite.fem.laplace_force import DIRECT, DIST, FINITE, INFINITE, TRANS, SecondConductor
from asterlite.fem.node_normals import node_normals
from asterlite.fem.pipe_elements import FOURIER_COMPONENTS, PIPE_MODELISATIONS
from asterlite.fem.plane_elements import EDGE_CELLS, PLANE_MODELISATIONS, surface_cells
from asterlite.fem.selection import (
    as_tuple,
    cell_group_members,
    named_nodes,
    node_group_members,
    select_cells,
    select_nodes,
)
from asterlite.fem.skin import inward_faces, is_plane
from asterlite.fem.solid_beam_link import face_section, solid_beam_relations
from asterlite.fem.solid_reference import FACE_CELLS, VOLUME_CELLS

_DDL_COMPONENTS = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ", "GRX", *FOURIER_COMPONENTS)
_FORCE_COMPONENTS = {"FX": "DX", "FY": "DY", "FZ": "DZ", "MX": "DRX", "MY": "DRY", "MZ": "DRZ"}
_ENCASTRE = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")
_BLOCAGE = {
    "DEPLACEMENT": ("DX", "DY", "DZ"),
    "ROTATION": ("DRX", "DRY", "DRZ"),
    # the ovalisation terms of pipe elements
    "TUYAU_FOURIER": FOURIER_COMPONENTS,
}


def constant_value(raw, node: int, key: str) -> float:
    """A value of AFFE_CHAR_MECA (AFFE_CHAR_MECA_F gives functions of the node)."""
    return float(raw)


def _ddl_impo(
    ctx, model, components, load, occ, value_at=constant_value, skip_absent=False
) -> None:
    """``skip_absent``: a component a node does not carry is passed over
    (AFFE_CHAR_CINE builds its field on the components that exist)."""
    mesh = model.mesh
    everywhere = occ.get("TOUT") == "OUI" or skip_absent
    nodes = select_nodes(ctx, occ, mesh, all_nodes=list(components))
    imposed = {c: occ[c] for c in _DDL_COMPONENTS if occ.get(c) is not None}
    given = {c for c in _DDL_COMPONENTS if occ.get(c) is not None}
    optional: set[str] = set()
    if occ.get("LIAISON") == "ENCASTRE":
        imposed.update({c: 0.0 for c in _ENCASTRE if c not in given})
        optional |= set(_ENCASTRE) - given
    for kind in as_tuple(occ.get("BLOCAGE")):
        if kind not in _BLOCAGE:
            ctx.unsupported(f"DDL_IMPO BLOCAGE={kind!r}", "BLOCAGE", occ)
        # BLOCAGE fixes the components the nodes carry (none is required,
        # but TUYAU_FOURIER needs Fourier DOFs on each node, as code_aster)
        imposed.update({c: 0.0 for c in _BLOCAGE[kind] if c not in given})
        optional |= set(_BLOCAGE[kind]) - given
    excluded = set(node_group_members(ctx, occ, mesh, "SANS_GROUP_NO"))
    if occ.get("SANS_GROUP_MA"):
        excluded |= set(mesh.nodes_of_cells(cell_group_members(ctx, occ, mesh, "SANS_GROUP_MA")))
    if excluded:
        nodes = np.array([n for n in nodes if int(n) not in excluded], dtype=int)
    if "TUYAU_FOURIER" in as_tuple(occ.get("BLOCAGE")):
        for node in nodes:
            if not set(FOURIER_COMPONENTS) & set(components.get(int(node), ())):
                ctx.error(
                    f"BLOCAGE='TUYAU_FOURIER': node {mesh.node_names[node]} carries no "
                    "Fourier DOF of a pipe element",
                    "BLOCAGE",
                    occ,
                )
    if not imposed:
        ctx.error("no component is imposed", None, occ)
    for comp, value in imposed.items():
        applied = 0
        for node in nodes:
            carried = components.get(int(node), ())
            if comp not in carried:
                if everywhere or comp in optional:
                    continue
                ctx.error(
                    f"node {mesh.node_names[node]} has no {comp} DOF in this model",
                    comp,
                    occ,
                )
            imposed_value = value_at(value, int(node), comp)
            load.relations.append(LinearRelation([(int(node), comp, 1.0)], imposed_value))
            applied += 1
        if applied == 0 and comp not in optional and not skip_absent:
            ctx.error(f"no node of the selection carries {comp}", comp, occ)


def _liaison_ddl(ctx, model, components, load, occ) -> None:
    mesh = model.mesh
    nodes = node_group_members(ctx, occ, mesh) + named_nodes(ctx, occ, mesh)
    ddl = as_tuple(occ.get("DDL"))
    coefs = as_tuple(occ.get("COEF_MULT"))
    if not (len(nodes) == len(ddl) == len(coefs)):
        ctx.error(
            f"LIAISON_DDL needs as many nodes ({len(nodes)}), DDL ({len(ddl)}) and "
            f"COEF_MULT ({len(coefs)})",
            "DDL",
            occ,
        )
    terms = []
    for node, comp, coef in zip(nodes, ddl, coefs, strict=True):
        if comp not in components.get(int(node), ()):
            ctx.error(f"node {mesh.node_names[node]} has no {comp} DOF in this model", "DDL", occ)
        terms.append((int(node), comp, float(coef)))
    load.relations.append(LinearRelation(terms, float(occ.get("COEF_IMPO", 0.0) or 0.0)))


def _group_nodes(ctx, occ, mesh) -> np.ndarray:
    """Nodes of GROUP_NO / GROUP_MA minus SANS_GROUP_NO / SANS_GROUP_MA."""
    nodes = select_nodes(ctx, occ, mesh)
    excluded = set(node_group_members(ctx, occ, mesh, "SANS_GROUP_NO"))
    if occ.get("SANS_GROUP_MA"):
        excluded |= set(mesh.nodes_of_cells(cell_group_members(ctx, occ, mesh, "SANS_GROUP_MA")))
    return np.array([n for n in nodes if int(n) not in excluded], dtype=int)


def _liaison_unif(ctx, model, components, load, occ) -> None:
    """Same (unknown) value of each DDL on every node: u_i - u_first = 0."""
    mesh = model.mesh
    nodes = _group_nodes(ctx, occ, mesh)
    if len(nodes) < 2:
        ctx.error("LIAISON_UNIF needs at least two nodes", "GROUP_NO", occ)
    for comp in as_tuple(occ.get("DDL")):
        for node in nodes:
            if comp not in components.get(int(node), ()):
                ctx.error(
                    f"node {mesh.node_names[node]} has no {comp} DOF in this model", "DDL", occ
                )
        first = int(nodes[0])
        for node in nodes[1:]:
            load.relations.append(LinearRelation([(int(node), comp, 1.0), (first, comp, -1.0)]))


def _liaison_solide(ctx, model, components, load, occ) -> None:
    """Rigid body motion of a set of nodes (small displacements).

    With rotations on a master node m: u_i = u_m + theta_m x (x_i - x_m) and
    theta_i = theta_m. Without rotation DOFs, every pair distance is kept:
    (u_i - u_j) . (x_i - x_j) = 0 for pairs spanning the set (3D: a chain
    through non-aligned nodes), as code_aster does for translation-only nodes.
    """
    mesh = model.mesh
    nodes = _group_nodes(ctx, occ, mesh)
    if len(nodes) < 2:
        return
    dim = 2 if model.dim == 2 else 3
    trans = ("DX", "DY", "DZ")[:dim]
    rots = ("DRZ",) if dim == 2 else ("DRX", "DRY", "DRZ")
    with_rotation = [n for n in nodes if all(r in components.get(int(n), ()) for r in rots)]
    if with_rotation:
        master = int(with_rotation[0])
        xm = mesh.coords[master]
        for node in nodes:
            node = int(node)
            if node == master:
                continue
            d = mesh.coords[node] - xm
            carried = components.get(node, ())
            if dim == 3:
                rows = {
                    "DX": [("DRY", d[2]), ("DRZ", -d[1])],
                    "DY": [("DRZ", d[0]), ("DRX", -d[2])],
                    "DZ": [("DRX", d[1]), ("DRY", -d[0])],
                }
            else:
                rows = {"DX": [("DRZ", -d[1])], "DY": [("DRZ", d[0])]}
            for comp in trans:
                if comp not in carried:
                    ctx.error(f"node {mesh.node_names[node]} has no {comp} DOF", "GROUP_NO", occ)
                terms = [(node, comp, 1.0), (master, comp, -1.0)]
                terms += [(master, r, -c) for r, c in rows[comp] if c != 0.0]
                load.relations.append(LinearRelation(terms))
            for r in rots:
                if r in carried:
                    load.relations.append(LinearRelation([(node, r, 1.0), (master, r, -1.0)]))
        return
    ctx.unsupported("LIAISON_SOLIDE on nodes without rotation DOFs", "GROUP_NO", occ)


def _face_impo(ctx, model, components, load, occ) -> None:
    """Components imposed on every node of the faces (edges in 2D), and DNOR
    (DTAN in 2D): u . n = value with n the mean unit normal at the node, as
    code_aster's cafaci/canort build them."""

    mesh = model.mesh
    cells = [int(c) for c in cell_group_members(ctx, occ, mesh, "GROUP_MA")]
    # a plane model's skin is made of edges (its mesh may have a constant Z)
    edges = all(mesh.cell_types[c] in ("SEG2", "SEG3") for c in cells)
    dim = 2 if model.dim == 2 or (edges and is_plane(mesh)) else 3
    excluded_cells = set()
    if occ.get("SANS_GROUP_MA"):
        excluded_cells = {int(c) for c in cell_group_members(ctx, occ, mesh, "SANS_GROUP_MA")}
        cells = [c for c in cells if c not in excluded_cells]
    excluded = set(node_group_members(ctx, occ, mesh, "SANS_GROUP_NO"))
    if excluded_cells:
        excluded |= set(mesh.nodes_of_cells(sorted(excluded_cells)))
    nodes = [int(n) for n in sorted(set(mesh.nodes_of_cells(cells))) if int(n) not in excluded]
    if not nodes:
        ctx.error("FACE_IMPO: no node left on the faces", "GROUP_MA", occ)
    translations = ("DX", "DY", "DZ")[:dim]
    for key in ("DNOR", "DTAN"):
        if occ.get(key) is None:
            continue
        if key == "DTAN" and dim == 3:
            ctx.error("DTAN is defined on edges of plane models only (code_aster)", key, occ)
        try:
            vectors = node_normals(mesh, cells, nodes, dim, tangent=key == "DTAN", log=ctx.log)
        except ElementError as exc:
            ctx.error(str(exc), key, occ)
        for node, vector in zip(nodes, vectors, strict=True):
            carried = components.get(node, ())
            if not all(c in carried for c in translations):
                ctx.error(f"node {mesh.node_names[node]} has no {translations} DOFs", key, occ)
            terms = [(node, c, float(v)) for c, v in zip(translations, vector, strict=True) if v]
            load.relations.append(LinearRelation(terms, float(occ[key])))
    for comp in _DDL_COMPONENTS + ("PRES", "PHI", "TEMP"):
        if occ.get(comp) is None:
            continue
        applied = 0
        for node in nodes:
            if comp in components.get(node, ()):
                load.relations.append(LinearRelation([(node, comp, 1.0)], float(occ[comp])))
                applied += 1
        if applied == 0:
            ctx.error(f"no node of the faces carries {comp}", comp, occ)


def _group_side(ctx, occ, mesh, side: str) -> list[int]:
    """The nodes of GROUP_NO_<side> or of the cells of GROUP_MA_<side>, in order."""
    if occ.get(f"GROUP_NO_{side}"):
        nodes = node_group_members(ctx, occ, mesh, f"GROUP_NO_{side}")
    else:
        cells = cell_group_members(ctx, occ, mesh, f"GROUP_MA_{side}")
        nodes = mesh.nodes_of_cells(cells).tolist()
    return [int(n) for n in dict.fromkeys(nodes)]


def _paired_nodes(ctx, occ, mesh) -> list[tuple[int, int]]:
    """code_aster's pairing (pacoap): each node of list 1, moved by ANGL_NAUT
    about CENTRE then TRAN, takes the nearest node of list 2; the lists have
    the same length and no node of list 2 may be taken twice."""

    first, second = _group_side(ctx, occ, mesh, "1"), _group_side(ctx, occ, mesh, "2")
    if len(first) != len(second):
        ctx.error(
            f"LIAISON_GROUP pairs {len(first)} nodes with {len(second)}: the lists must "
            "have the same length",
            "GROUP_NO_2" if occ.get("GROUP_NO_2") else "GROUP_MA_2",
            occ,
        )
    vector = {}
    for key in ("TRAN", "CENTRE"):
        given = np.asarray(as_tuple(occ.get(key) or (0.0, 0.0, 0.0)), dtype=float)
        vector[key] = np.pad(given, (0, 3 - given.size))
    angles = np.asarray(as_tuple(occ.get("ANGL_NAUT") or (0.0, 0.0, 0.0)), dtype=float)
    rotation = rotation_from_angles(np.radians(np.pad(angles, (0, 3 - angles.size))))
    moved = (mesh.coords[first] - vector["CENTRE"]) @ rotation + vector["CENTRE"] + vector["TRAN"]
    targets = mesh.coords[second]
    pairs, taken = [], {}
    for node, x in zip(first, moved, strict=True):
        nearest = second[int(np.argmin(np.sum((targets - x) ** 2, axis=1)))]
        if nearest in taken:
            names = mesh.node_names
            ctx.error(
                f"LIAISON_GROUP: nodes {names[taken[nearest]]} and {names[node]} both face "
                f"node {names[nearest]}",
                "GROUP_NO_1" if occ.get("GROUP_NO_1") else "GROUP_MA_1",
                occ,
            )
        taken[nearest] = node
        pairs.append((node, nearest))
    return pairs


def _liaison_group(ctx, model, components, load, occ) -> None:
    """sum_k COEF_MULT_1[k] u1[DDL_1[k]] + sum_k COEF_MULT_2[k] u2[DDL_2[k]] = COEF_IMPO
    for each pair of nodes (code_aster's caliag); DNOR refused."""
    mesh = model.mesh
    sides = {}
    for side in ("1", "2"):
        ddl = as_tuple(occ[f"DDL_{side}"])
        coefs = as_tuple(occ[f"COEF_MULT_{side}"])
        if len(ddl) != len(coefs):
            ctx.error(f"DDL_{side} and COEF_MULT_{side} differ in length", f"DDL_{side}", occ)
        if "DNOR" in ddl:
            ctx.unsupported("LIAISON_GROUP DDL_1/DDL_2='DNOR'", f"DDL_{side}", occ)
        sides[side] = list(zip(ddl, (float(c) for c in coefs), strict=True))
    excluded = set(node_group_members(ctx, occ, mesh, "SANS_GROUP_NO"))
    for node_1, node_2 in _paired_nodes(ctx, occ, mesh):
        if node_1 in excluded or node_2 in excluded:
            continue
        terms = []
        for node, side in ((node_1, "1"), (node_2, "2")):
            for comp, coef in sides[side]:
                if comp not in components.get(node, ()):
                    ctx.error(
                        f"node {mesh.node_names[node]} has no {comp} DOF in this model",
                        f"DDL_{side}",
                        occ,
                    )
                terms.append((node, comp, coef))
        load.relations.append(LinearRelation(terms, float(occ["COEF_IMPO"])))


def _liaison_chamno(ctx, model, components, load, occ) -> None:
    """sum over the field's non-zero values v_i u_i = COEF_IMPO (code_aster's calich)."""
    field = occ["CHAM_NO"]
    numbering = field.numbering
    values = np.asarray(field.values, dtype=float)
    terms = []
    mesh = model.mesh
    for row in np.flatnonzero(values):
        node, comp = numbering.dofs[int(row)]
        if numbering.mesh is not mesh:
            ctx.error("CHAM_NO is not on the mesh of the model", "CHAM_NO", occ)
        if comp not in components.get(int(node), ()):
            ctx.error(
                f"node {mesh.node_names[node]} has no {comp} DOF in this model", "CHAM_NO", occ
            )
        terms.append((int(node), comp, float(values[row])))
    if not terms:
        ctx.error("CHAM_NO holds no non-zero value: no relation to write", "CHAM_NO", occ)
    load.relations.append(LinearRelation(terms, float(occ["COEF_IMPO"])))


def _liaison_elem(ctx, model, components, load, occ) -> None:
    """OPTION='3D_POU': the beam node follows the mean motion of the solid's
    face (asterlite.fem.solid_beam_link); '3D_POU_ARLEQUIN': the beam is tied
    to the solid it runs in (commands.liaison_arlequin); the other options
    are refused."""

    option = occ["OPTION"]
    if option == "3D_POU_ARLEQUIN":
        from asterlite.commands.liaison_arlequin import arlequin_link

        arlequin_link(ctx, model, components, load, occ)
        return
    if option != "3D_POU":
        ctx.unsupported(f"LIAISON_ELEM OPTION={option!r}", "OPTION", occ)
    mesh = model.mesh
    faces = cell_group_members(ctx, occ, mesh, "GROUP_MA_1")
    if occ.get("GROUP_NO_2"):
        beam = node_group_members(ctx, occ, mesh, "GROUP_NO_2")
    else:
        beam = sorted(set(mesh.nodes_of_cells(cell_group_members(ctx, occ, mesh, "GROUP_MA_2"))))
    where = "GROUP_NO_2" if occ.get("GROUP_NO_2") else "GROUP_MA_2"
    if len(beam) != 1:
        ctx.error(f"LIAISON_ELEM 3D_POU needs one beam node, {len(beam)} given", where, occ)
    beam_node = int(beam[0])
    missing = [c for c in _ENCASTRE if c not in components.get(beam_node, ())]
    if missing:
        name = mesh.node_names[beam_node]
        ctx.error(f"beam node {name} carries no {', '.join(missing)} in this model", where, occ)
    try:
        section = face_section(mesh, faces)
    except ElementError as exc:
        ctx.error(str(exc), "GROUP_MA_1", occ)
    for node in section.nodes:
        carried = components.get(int(node), ())
        if any(r in carried for r in ("DRX", "DRY", "DRZ")):
            ctx.error(
                f"face node {mesh.node_names[node]} carries rotations: 3D_POU links the "
                "faces of a solid (nodes with DX, DY, DZ only)",
                "GROUP_MA_1",
                occ,
            )
        if not all(c in carried for c in ("DX", "DY", "DZ")):
            ctx.error(
                f"face node {mesh.node_names[node]} is not in the 3D model", "GROUP_MA_1", occ
            )
    _warn_link_geometry(ctx, mesh, faces, section, beam_node, float(occ["ANGL_MAX"]))
    for terms, rhs in solid_beam_relations(section, beam_node):
        load.relations.append(LinearRelation(terms, rhs))


def _warn_link_geometry(ctx, mesh, faces, section, beam_node, angle_max) -> None:
    """code_aster's alarms: faces not plane within ANGL_MAX degrees, beam node
    farther than 1 % of the equivalent radius from the centroid."""
    normals = []
    for cell in faces:
        x = mesh.coords[list(mesh.cell_nodes[cell][:3])]
        n = np.cross(x[1] - x[0], x[2] - x[0])
        normals.append(n / np.linalg.norm(n))
    cosines = np.clip(np.abs(np.asarray(normals) @ normals[0]), -1.0, 1.0)
    worst = float(np.degrees(np.arccos(cosines.min())))
    if worst > angle_max:
        ctx.log(f"alarm: LIAISON_ELEM faces are not plane: normals {worst:.3g} degrees apart")
    radius = np.sqrt(section.area / np.pi)
    offset = float(np.linalg.norm(mesh.coords[beam_node] - section.centroid))
    if offset > 1.0e-2 * radius:
        ctx.log(
            f"alarm: LIAISON_ELEM beam node {mesh.node_names[beam_node]} is {offset:.4g} "
            f"from the centroid {section.centroid.tolist()} of the faces"
        )


_BEAM_LOAD_GLOBAL = ("FX", "FY", "FZ", "MX", "MY", "MZ")
_BEAM_LOAD_LOCAL = ("N", "VY", "VZ", "MT", "MFY", "MFZ")
_BEAM_LOADED = ("POU_D_E", "POU_D_T", "POU_D_TG", "POU_D_EM", "POU_D_TGM", "BARRE")


def beam_load_cells(ctx, model, occ) -> np.ndarray:
    """The beam (and bar) cells of a FORCE_POUTRE occurrence; with TOUT='OUI'
    the other cells of the model are left out, otherwise they are an error."""
    if occ.get("TYPE_CHARGE", "FORCE") != "FORCE":
        ctx.unsupported("FORCE_POUTRE TYPE_CHARGE='VENT'", "TYPE_CHARGE", occ)
    cells = select_cells(ctx, occ, model.mesh, all_cells=sorted(model.cell_modelisation))
    kept = []
    for cell in cells:
        if model.cell_modelisation.get(int(cell)) in _BEAM_LOADED:
            kept.append(int(cell))
        elif model.cell_modelisation.get(int(cell)) in PIPE_MODELISATIONS:
            # code_aster loads pipes too (te0583), asterlite not yet
            ctx.unsupported("FORCE_POUTRE on pipe elements (TUYAU_3M, TUYAU_6M)", "GROUP_MA", occ)
        elif occ.get("TOUT") != "OUI":
            ctx.error(
                f"FORCE_POUTRE on cell {model.mesh.cell_names[cell]}, which is not a beam",
                "GROUP_MA",
                occ,
            )
    return np.array(kept, dtype=int)


def beam_load_keys(ctx, occ) -> tuple[tuple[str, ...], bool]:
    """The component names of the occurrence's frame, and whether it is local."""
    given_global = [k for k in _BEAM_LOAD_GLOBAL if occ.get(k) is not None]
    given_local = [k for k in _BEAM_LOAD_LOCAL if occ.get(k) is not None]
    if given_global and given_local:
        ctx.error("FORCE_POUTRE mixes global (FX...) and local (N, VY...) components", None, occ)
    return (_BEAM_LOAD_LOCAL, True) if given_local else (_BEAM_LOAD_GLOBAL, False)


def _force_poutre(ctx, model, load, occ) -> None:
    keys, local = beam_load_keys(ctx, occ)
    values = {k: float(occ[k]) for k in keys if occ.get(k) is not None}
    cells = beam_load_cells(ctx, model, occ)
    load.extra.setdefault("FORCE_POUTRE", []).append(
        {"CELLS": cells, "VALUES": values, "LOCAL": local}
    )


#: the modelisations whose elements compute the Laplace force (code_aster's
#: CHAR_MECA_FRELEC; its POU_D_EM and POU_D_TGM are not asterlite's)
_CONDUCTORS = ("POU_D_E", "POU_D_T", "POU_D_TG")


def _point(occ, key) -> tuple[float, float, float]:
    values = [float(v) for v in as_tuple(occ.get(key))]
    # code_aster reads three values; fewer leave the others at zero
    return tuple(values + [0.0] * (3 - len(values)))[:3]


def _second_conductor(occ) -> SecondConductor:
    position = occ.get("POSITION")
    if position is None:
        return SecondConductor(DIRECT, tuple(float(occ.get(k) or 0.0) for k in ("FX", "FY", "FZ")))
    if position == "PARA":
        if occ.get("DIST") is not None:
            return SecondConductor(DIST, (float(occ["DIST"]), 0.0, 0.0), _point(occ, "POINT2"))
        return SecondConductor(TRANS, _point(occ, "TRANS"))
    kind = INFINITE if position == "INFI" else FINITE
    return SecondConductor(kind, _point(occ, "POINT1"), _point(occ, "POINT2"))


def _force_elec(ctx, model, load, occ) -> None:
    """The second conductor of each beam cell; a later occurrence replaces an
    earlier one on the cells they share (code_aster fills one map of values
    per cell). Cells of other elements carry no Laplace force, as in
    code_aster, whose other elements do not compute it."""
    cells = select_cells(ctx, occ, model.mesh, all_cells=sorted(model.cell_modelisation))
    conductor = _second_conductor(occ)
    on_cells = load.extra.setdefault("FORCE_ELEC", {})
    skipped = 0
    for cell in cells:
        if model.cell_modelisation.get(int(cell)) in _CONDUCTORS:
            on_cells[int(cell)] = conductor
        else:
            skipped += 1
    if skipped:
        ctx.log(f"FORCE_ELEC: {skipped} cells are not beams and carry no Laplace force")


def _force_nodale(ctx, model, components, load, occ, value_at=constant_value) -> None:
    mesh = model.mesh
    if occ.get("ANGL_NAUT") is not None:
        ctx.unsupported("FORCE_NODALE with ANGL_NAUT", "ANGL_NAUT", occ)
    nodes = select_nodes(ctx, occ, mesh, all_nodes=list(components))
    given = {k: occ[k] for k in _FORCE_COMPONENTS if occ.get(k) is not None}
    if not given:
        ctx.error("no force component is given", None, occ)
    for key, value in given.items():
        comp = _FORCE_COMPONENTS[key]
        for node in nodes:
            if comp not in components.get(int(node), ()):
                ctx.error(f"node {mesh.node_names[node]} has no {comp} DOF in this model", key, occ)
            load.nodal_forces.append((int(node), comp, value_at(value, int(node), key)))


def _cells_of_3d_model(ctx, model, occ, kinds, what: str) -> np.ndarray:
    """Cells of the occurrence that the model carries with MODELISATION='3D'
    and whose type is among ``kinds`` (faces for surface loads, volumes for
    volume loads); TOUT='OUI' takes those of the whole model."""
    return _cells_carrying(ctx, model, occ, {"3D": kinds}, what)


def _cells_carrying(ctx, model, occ, accepted: dict, what: str) -> np.ndarray:
    """Cells of the occurrence whose modelisation is a key of ``accepted`` and
    whose type is among its value; TOUT='OUI' takes those of the whole model."""
    mesh = model.mesh
    everywhere = occ.get("TOUT") == "OUI"
    cells = select_cells(ctx, occ, mesh, all_cells=sorted(model.cell_modelisation))
    kept = []
    for cell in cells:
        modelisation = model.cell_modelisation.get(int(cell))
        if modelisation in accepted and mesh.cell_types[cell] in accepted[modelisation]:
            kept.append(int(cell))
        elif not everywhere:
            if modelisation is not None and modelisation not in accepted:
                # the element may carry the load in code_aster (shells, 2D...):
                # asterlite has not implemented it there, which says nothing of the deck
                ctx.unsupported(f"{what} on {modelisation} cells", "GROUP_MA", occ)
            state = (
                "not in the model" if modelisation is None else f"a {mesh.cell_types[cell]} cell"
            )
            ctx.error(f"{what} on cell {mesh.cell_names[cell]}, which is {state}", "GROUP_MA", occ)
    if not kept:
        ctx.error(f"{what}: no cell of the model can carry it", "GROUP_MA", occ)
    return np.array(kept, dtype=int)


def _check_outward(ctx, model, faces, occ) -> None:
    """VERI_NORM='OUI': pressure faces on the skin of the model's volumes must
    point outwards (code_aster stops otherwise)."""

    mesh = model.mesh
    volumes = [c for c in model.cell_modelisation if mesh.cell_types[c] in VOLUME_CELLS]
    wrong = inward_faces(mesh, faces, volumes)
    if wrong:
        names = ", ".join(mesh.cell_names[c] for c in wrong[:5])
        ctx.error(
            f"{len(wrong)} faces point into the volume ({names}): orient them with "
            "MODI_MAILLAGE/ORIE_PEAU, or give VERI_NORM='NON'",
            "GROUP_MA",
            occ,
        )


def pres_rep(ctx, model, load, occ, pressure: float, shear, kw) -> None:
    """One PRES_REP occurrence of uniform ``pressure`` (and ``shear``,
    CISA_2D, on edges): faces of 3D models, edges of plane ones."""
    edges = dict.fromkeys(PLANE_MODELISATIONS, EDGE_CELLS)
    accepted = {"3D": FACE_CELLS, **edges}
    cells = _cells_carrying(ctx, model, occ, accepted, "PRES_REP")
    on_edges = np.array([model.cell_modelisation[c] != "3D" for c in cells], dtype=bool)
    if shear is not None and not on_edges.all():
        ctx.error("CISA_2D applies to edges of plane models only", "CISA_2D", occ)
    if (~on_edges).any():
        faces = cells[~on_edges]
        if kw.get("VERI_NORM", "OUI") == "OUI":
            _check_outward(ctx, model, faces, occ)
        load.extra.setdefault("PRES_REP", []).append({"CELLS": faces, "PRES": pressure})
    if on_edges.any():
        load.extra.setdefault("PRES_REP_2D", []).append(
            {"CELLS": cells[on_edges], "PRES": pressure, "CISA_2D": float(shear or 0.0)}
        )


def _solid_loads(ctx, model, load, kw) -> None:
    """FORCE_FACE, PRES_REP (faces of 3D models, edges of plane ones),
    FORCE_CONTOUR (edges of plane models) and FORCE_INTERNE (volumes, plane
    surfaces)."""

    edges = dict.fromkeys(PLANE_MODELISATIONS, EDGE_CELLS)
    surfaces = {name: tuple(surface_cells(name)) for name in PLANE_MODELISATIONS}
    plane = any(m in PLANE_MODELISATIONS for m in model.cell_modelisation.values())
    for occ in kw.factor("FORCE_FACE"):
        force = [float(occ.get(k) or 0.0) for k in ("FX", "FY", "FZ")]
        cells = _cells_of_3d_model(ctx, model, occ, FACE_CELLS, "FORCE_FACE")
        load.extra.setdefault("FORCE_FACE", []).append({"CELLS": cells, "FORCE": force})
    for occ in kw.factor("PRES_REP"):
        shear = occ.get("CISA_2D")
        pres_rep(ctx, model, load, occ, float(occ.get("PRES") or 0.0), shear, kw)
    for occ in kw.factor("FORCE_CONTOUR"):
        if not plane:
            ctx.error("FORCE_CONTOUR applies to edges of plane models", "GROUP_MA", occ)
        if any(occ.get(k) for k in ("FZ", "MX", "MY", "MZ")):
            ctx.unsupported("FORCE_CONTOUR FZ, MX, MY, MZ (shell contours)", "FZ", occ)
        force = [float(occ.get(k) or 0.0) for k in ("FX", "FY")]
        cells = _cells_carrying(ctx, model, occ, edges, "FORCE_CONTOUR")
        load.extra.setdefault("FORCE_CONTOUR", []).append({"CELLS": cells, "FORCE": force})
    for occ in kw.factor("FORCE_INTERNE"):
        force = [float(occ.get(k) or 0.0) for k in ("FX", "FY", "FZ")]
        accepted = {"3D": VOLUME_CELLS, **surfaces}
        cells = _cells_carrying(ctx, model, occ, accepted, "FORCE_INTERNE")
        flat = np.array([model.cell_modelisation[c] != "3D" for c in cells], dtype=bool)
        if (~flat).any():
            load.extra.setdefault("FORCE_INTERNE", []).append(
                {"CELLS": cells[~flat], "FORCE": force}
            )
        if flat.any():
            load.extra.setdefault("FORCE_INTERNE_2D", []).append(
                {"CELLS": cells[flat], "FORCE": force[:2]}
            )


def _force_tuyau(ctx, model, load, occ) -> None:
    """FORCE_TUYAU: a pressure inside the pipe cells of the selection (the
    other cells have no such load, as in code_aster), assembled with the
    cells' frames (asterlite.fem.pipe_elements.pipe_pressure_terms)."""
    cells = select_cells(ctx, occ, model.mesh, all_cells=sorted(model.cell_modelisation))
    pipes = [int(c) for c in cells if model.cell_modelisation.get(int(c)) in PIPE_MODELISATIONS]
    if not pipes:
        ctx.error("FORCE_TUYAU: no pipe element (TUYAU_3M, TUYAU_6M) among the cells", None, occ)
    pressure = occ.get("PRES")
    if pressure is not None:
        load.extra.setdefault("FORCE_TUYAU", []).append(
            {"CELLS": np.array(pipes, dtype=int), "PRES": float(pressure)}
        )


def _force_arete(ctx, model, components, load, occ) -> None:
    """FORCE_ARETE on the edges (SEG2) of DKT plates: forces and moments per
    unit length in the global frame, half of each times the edge's length at
    each of its nodes (code_aster's te0034); on other elements refused by name."""
    mesh = model.mesh
    given = {k: float(occ[k]) for k in _FORCE_COMPONENTS if occ.get(k) is not None}
    cells = _cells_carrying(ctx, model, occ, {"DKT": ("SEG2",)}, "FORCE_ARETE")
    for cell in cells:
        nodes = [int(n) for n in mesh.cell_nodes[int(cell)]]
        half = 0.5 * float(np.linalg.norm(mesh.coords[nodes[1]] - mesh.coords[nodes[0]]))
        for key, value in given.items():
            comp = _FORCE_COMPONENTS[key]
            for node in nodes:
                if comp not in components.get(node, ()):
                    ctx.error(f"node {mesh.node_names[node]} has no {comp} DOF", key, occ)
                load.nodal_forces.append((node, comp, value * half))


#: the factor keywords read one occurrence at a time, in the order their terms
#: are added to the load
_OCCURRENCE_READERS = (
    ("DDL_IMPO", _ddl_impo),
    ("LIAISON_DDL", _liaison_ddl),
    ("FORCE_NODALE", _force_nodale),
    ("FORCE_ARETE", _force_arete),
    ("LIAISON_UNIF", _liaison_unif),
    ("LIAISON_SOLIDE", _liaison_solide),
    (
        "FORCE_POUTRE",
        lambda ctx, model, _components, load, occ: _force_poutre(ctx, model, load, occ),
    ),
    ("FORCE_ELEC", lambda ctx, model, _components, load, occ: _force_elec(ctx, model, load, occ)),
    ("FORCE_TUYAU", lambda ctx, model, _components, load, occ: _force_tuyau(ctx, model, load, occ)),
    ("LIAISON_ELEM", _liaison_elem),
    ("FACE_IMPO", _face_impo),
    ("LIAISON_GROUP", _liaison_group),
    ("LIAISON_CHAMNO", _liaison_chamno),
)


def run(ctx, kw):
    model = kw["MODELE"]
    components = model.node_components()
    load = MechanicalLoad(model=model)
    if not kw.factor("PRES_REP"):
        # VERI_NORM checks the faces of loads along their normal (PRES_REP here):
        # without them code_aster has nothing to check
        kw.mark_used("VERI_NORM")
    for keyword, reader in _OCCURRENCE_READERS:
        for occ in kw.factor(keyword):
            reader(ctx, model, components, load, occ)
    _solid_loads(ctx, model, load, kw)
    if kw.get("PESANTEUR"):
        occ = kw.factor("PESANTEUR")[0]
        load.extra["PESANTEUR"] = {
            "GRAVITE": float(occ["GRAVITE"]),
            "DIRECTION": tuple(float(x) for x in as_tuple(occ["DIRECTION"])),
            "CELLS": select_cells(ctx, occ, model.mesh) if occ.get("GROUP_MA") else None,
        }
    if kw.get("EVOL_CHAR") is not None:
        _evol_char(ctx, model, load, kw)
    if kw.get("VECT_ASSE") is not None:
        _vect_asse(ctx, load, kw)
    single_lagrange(kw, load)
    ctx.log(f"load: {len(load.relations)} relations, {len(load.nodal_forces)} nodal forces")
    return load


def single_lagrange(kw, load) -> None:
    """DOUBLE_LAGRANGE='NON': code_aster dualises the load's relations with one
    multiplier each instead of two; the solution is the same, its numbering
    and the multipliers' values are not (asterlite.fem.lagrange_layout)."""
    if kw.get("DOUBLE_LAGRANGE", "OUI") == "NON":
        for relation in load.relations:
            relation.double_lagrange = False


def _vect_asse(ctx, load, kw) -> None:
    """VECT_ASSE: an assembled vector taken as the load's nodal forces, DOF by
    DOF (code_aster adds it to the load vectors as it is)."""
    vector = kw["VECT_ASSE"]
    values = np.asarray(getattr(vector, "values", None))
    numbering = getattr(vector, "numbering", None)
    if numbering is None or values.ndim != 1 or len(values) != numbering.n_dofs:
        ctx.error("VECT_ASSE must be an assembled vector (cham_no)", "VECT_ASSE", kw)
    if np.iscomplexobj(values):
        ctx.unsupported("AFFE_CHAR_MECA/VECT_ASSE of a complex vector", "VECT_ASSE", kw)
    load.extra["VECT_ASSE"] = [
        (int(node), str(component), float(value))
        for (node, component), value in zip(numbering.dofs, values, strict=True)
        if value != 0.0
    ]


def _evol_char(ctx, model, load, kw) -> None:
    """EVOL_CHAR: a history of nodal forces (FORC_NODA), applied by the
    commands that take load histories (asterlite.fem.loads.load_history)."""
    history = kw["EVOL_CHAR"]
    if history.numbering.mesh is not model.mesh:
        ctx.error("EVOL_CHAR is on another mesh than MODELE", "EVOL_CHAR", kw)
    other = [name for name in history.fields if name != "FORC_NODA"]
    if other or "FORC_NODA" not in history.fields:
        ctx.unsupported(
            f"EVOL_CHAR with the fields {', '.join(history.fields)} (FORC_NODA only)",
            "EVOL_CHAR",
            kw,
        )
    load.extra["EVOL_CHAR"] = history
