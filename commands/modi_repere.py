"""MODI_REPERE: the fields of a result expressed in another frame.

Each AFFE occurrence gives a frame and where it applies (its cells, or nodes);
each MODI_CHAM a field and how its components transform: TENS_3D (six
components xx yy zz xy xz yz: ``S' = R S R^T``) or VECT_3D (DX DY DZ, and
DRX DRY DRZ when the field has rotations: ``v' = R v``), ``R`` the rows of
the new axes in the global frame.

- REPERE='UTILISATEUR': one frame, from ANGL_NAUT (degrees) or VECT_X/VECT_Y;
- REPERE='CYLINDRIQUE': at each point (the cell's node for *_ELNO, the node
  for *_NOEU and nodal vectors) the axes (e_r, e_z, e_theta) about the axis
  through ORIGINE along AXE_Z, as code_aster's cylrep builds them (e_r from
  the point's distance to the axis, e_theta = e_z x e_r; on the axis, e_r is
  chosen normal to AXE_Z).
- REPERE='COQUE', 'COQUE_INTR_UTIL', 'COQUE_UTIL_INTR': element fields of
  DKT plates (TYPE_CHAM COQUE_GENE: EFGE/DEGE/EGRU/SIEF; TENS_3D:
  SIGM/EPSI) turned in each cell's plane (asterlite.fem.shell_frames): from
  the CARA_ELEM frame to the one of the single AFFE occurrence (ANGL_REP or
  VECTEUR; (0, 0) on the other cells), to the cell's intrinsic frame, or
  from it. Every cell of the field is turned, as code_aster's calcul does.

Values outside the AFFE selections keep their global components. The new
result holds every order of the input (TOUT_ORDRE), or of a dyna_harmo /
dyna_trans those NUME_ORDRE, INST or FREQ choose (rsutnu); the other frames
(COQUE_UTIL_CYL, GLOBAL_UTIL), 2D fields, beam generalised forces, NOM_CMP
with a shell frame and CHAM_GD are refused by name.
"""

from __future__ import annotations

import copy

import numpy as np

from asterlite.concepts.harmonic import DynaHarmo
from asterlite.concepts.transient import DynaTrans
from asterlite.errors import CommandError
from asterlite.fem.frames import angles_from_x_and_y, rotation_from_angles
from asterlite.fem.plate_elements import PLATE_MODELISATIONS
from asterlite.fem.selection import as_tuple, select_cells, select_nodes
from asterlite.fem.shell_frames import (
    GENERALISED,
    TENSOR,
    angles_from_vector,
    change_shell_frame,
    frame_axes,
)
from asterlite.io.result_store import result_steps, select_steps

_TENSOR = ("XX", "YY", "ZZ", "XY", "XZ", "YZ")
_PAIRS = ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))
_VECTOR = ("DX", "DY", "DZ")
_ROTATIONS = ("DRX", "DRY", "DRZ")


def cylindrical_axes(points: np.ndarray, origin, axis) -> np.ndarray:
    """(n, 3, 3) rows e_r, e_z, e_theta at ``points`` (n, 3) (code_aster's cylrep)."""
    z = np.asarray(axis, dtype=float)
    z = z / np.linalg.norm(z)
    r = np.asarray(points, dtype=float) - np.asarray(origin, dtype=float)
    r = r - np.outer(r @ z, z)
    length = np.linalg.norm(r, axis=1)
    on_axis = length < np.finfo(float).eps
    fallback = np.array([z[1], -z[0], 0.0]) if (z[0] or z[1]) else np.array([1.0, 0.0, 0.0])
    r[on_axis] = fallback / np.linalg.norm(fallback)
    r[~on_axis] /= length[~on_axis, None]
    theta = np.cross(z, r)
    theta /= np.linalg.norm(theta, axis=1)[:, None]
    return np.stack([r, np.broadcast_to(z, r.shape), theta], axis=1)


def _user_axes(ctx, occ) -> np.ndarray:
    if occ.get("ANGL_NAUT") is not None:
        angles = np.zeros(3)
        given = np.radians(np.asarray(as_tuple(occ["ANGL_NAUT"]), dtype=float))
        angles[: given.size] = given
    else:
        angles = angles_from_x_and_y(occ["VECT_X"], occ["VECT_Y"])
    return rotation_from_angles(angles)


def _frames(ctx, kw, mesh):
    """[(cells, nodes, axes_at(points) -> (n, 3, 3))] for each AFFE occurrence."""
    repere = kw["REPERE"]
    if repere not in ("UTILISATEUR", "CYLINDRIQUE"):
        ctx.unsupported(f"MODI_REPERE REPERE={repere!r}", "REPERE", kw)
    out = []
    for occ in kw.factor("AFFE"):
        cells = (
            select_cells(ctx, occ, mesh) if not (occ.get("GROUP_NO") or occ.get("NOEUD")) else []
        )
        nodes = select_nodes(ctx, occ, mesh)
        if repere == "UTILISATEUR":
            rotation = _user_axes(ctx, occ)

            def axes_at(points, rotation=rotation):
                return np.broadcast_to(rotation, (len(points), 3, 3))
        else:
            origin = np.zeros(3)
            given = np.asarray(as_tuple(occ.get("ORIGINE") or (0.0, 0.0, 0.0)), dtype=float)
            origin[: given.size] = given
            if occ.get("AXE_Z") is None:
                ctx.error("REPERE='CYLINDRIQUE' needs AXE_Z", "AXE_Z", occ)
            axis = np.asarray(as_tuple(occ["AXE_Z"]), dtype=float)

            def axes_at(points, origin=origin, axis=axis):
                return cylindrical_axes(points, origin, axis)

        out.append((np.asarray(cells, dtype=int), np.asarray(nodes, dtype=int), axes_at))
    return out


def _tensor_columns(ctx, components, occ) -> list[int]:
    names = as_tuple(occ.get("NOM_CMP"))
    if names:
        if len(names) != 6:
            ctx.error("TENS_3D: NOM_CMP gives the six components xx yy zz xy xz yz", "NOM_CMP", occ)
    else:
        names = tuple(
            next((c for c in components if c.endswith(s) and len(c) == 4), "") for s in _TENSOR
        )
    missing = [n for n in names if n not in components]
    if missing or not names:
        ctx.error(
            f"{occ['NOM_CHAM']} has no tensor components {', '.join(missing) or '(xx..yz)'}",
            "NOM_CMP",
            occ,
        )
    return [components.index(n) for n in names]


def _rotate_tensors(values: np.ndarray, columns: list[int], axes: np.ndarray) -> None:
    """values (..., n_points, n_comp) in place, axes (n_points, 3, 3)."""
    t = np.zeros(values.shape[:-1] + (3, 3), dtype=values.dtype)
    for k, (i, j) in enumerate(_PAIRS):
        t[..., i, j] = t[..., j, i] = values[..., columns[k]]
    rotated = np.einsum("pai,...pij,pbj->...pab", axes, t, axes)
    for k, (i, j) in enumerate(_PAIRS):
        values[..., columns[k]] = rotated[..., i, j]


def _element_field(ctx, field, occ, frames, mesh, kind) -> None:
    if field.name.endswith("_ELGA"):
        ctx.unsupported(f"MODI_REPERE of {field.name} (Gauss-point fields)", "NOM_CHAM", occ)
    columns = _tensor_columns(ctx, field.components, occ)
    cells = np.asarray(field.cells, dtype=int)
    for chosen, _, axes_at in frames:
        rows = np.nonzero(np.isin(cells, chosen))[0]
        for row in rows:
            # a field on cells of several types is padded to the largest node count
            nodes = list(mesh.cell_nodes[int(cells[row])])[: field.values.shape[2]]
            axes = axes_at(mesh.coords[nodes])
            _rotate_tensors(field.values[:, row, : len(nodes)], columns, axes)


def _node_field(ctx, field, occ, frames, mesh) -> None:
    columns = _tensor_columns(ctx, field.components, occ)
    nodes = np.asarray(field.nodes, dtype=int)
    for _, chosen, axes_at in frames:
        rows = np.nonzero(np.isin(nodes, chosen))[0]
        if rows.size:
            block = field.values[:, rows]
            _rotate_tensors(block, columns, axes_at(mesh.coords[nodes[rows]]))
            field.values[:, rows] = block


def _dof_vectors(ctx, values, numbering, occ, frames, mesh) -> np.ndarray:
    """Nodal vectors (n_orders, n_dofs): DX DY DZ of each selected node and,
    when the field has rotations, DRX DRY DRZ too (code_aster's selectCompN
    and chrpno turn both triplets of a DEPL-like field)."""
    values = np.array(values, copy=True)
    has_rotations = any(component in _ROTATIONS for _, component in numbering.dofs)
    for _, chosen, axes_at in frames:
        index = numbering.dof_indices(np.repeat(chosen, 3), list(_VECTOR) * len(chosen))
        index = index.reshape(-1, 3)
        whole = np.all(index >= 0, axis=1)
        if not np.all(whole):
            missing = mesh.node_names[int(chosen[np.nonzero(~whole)[0][0]])]
            ctx.error(f"node {missing} has not the DX, DY, DZ of a VECT_3D", "TYPE_CHAM", occ)
        axes = axes_at(mesh.coords[chosen])  # (n, 3, 3)
        vectors = values[:, index]  # (o, n, 3)
        values[:, index] = np.einsum("nij,onj->oni", axes, vectors)
        if has_rotations:
            _turn_rotations(values, numbering, chosen, axes)
    return values


def _turn_rotations(values, numbering, chosen, axes) -> None:
    """DRX DRY DRZ of the chosen nodes in the new axes; a rotation a node does
    not carry counts as zero and stays absent."""
    index = numbering.dof_indices(np.repeat(chosen, 3), list(_ROTATIONS) * len(chosen))
    index = index.reshape(-1, 3)
    carried = index >= 0
    rows = np.flatnonzero(carried.any(axis=1))
    if rows.size == 0:
        return
    vectors = np.zeros((values.shape[0], rows.size, 3), dtype=values.dtype)
    for k, row in enumerate(rows):
        present = carried[row]
        vectors[:, k, present] = values[:, index[row, present]]
    turned = np.einsum("nij,onj->oni", axes[rows], vectors)
    for k, row in enumerate(rows):
        present = carried[row]
        values[:, index[row, present]] = turned[:, k, present]


# REPERE='COQUE*': the fields code_aster turns for each TYPE_CHAM (chrpel)
# and their components (asterlite.fem.shell_frames layouts)
_SHELL_REPERES = ("COQUE", "COQUE_INTR_UTIL", "COQUE_UTIL_INTR")
_SHELL_FIELDS = {
    "COQUE_GENE": ("EFGE_ELGA", "EFGE_ELNO", "EGRU_ELNO", "DEGE_ELGA", "DEGE_ELNO", "SIEF_ELGA"),
    "TENS_3D": ("SIGM_ELGA", "SIGM_ELNO", "EPSI_ELGA", "EPSI_ELNO"),
}
_SHELL_COMPONENTS = {
    "COQUE_GENE": (
        ("NXX", "NYY", "NXY", "MXX", "MYY", "MXY", "QX", "QY"),
        ("EXX", "EYY", "EXY", "KXX", "KYY", "KXY", "GAX", "GAY"),
    ),
    "TENS_3D": (
        ("SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"),
        ("EPXX", "EPYY", "EPZZ", "EPXY", "EPXZ", "EPYZ"),
    ),
}


def _shell_angles(occ) -> tuple[float, float]:
    if occ.get("VECTEUR") is not None:
        return angles_from_vector(as_tuple(occ["VECTEUR"]))
    alpha, beta = (float(v) for v in as_tuple(occ["ANGL_REP"]))
    return alpha, beta


def _shell_field(ctx, kw, occ, result, characteristics, mesh):
    """The element field MODI_CHAM names, in the frame REPERE='COQUE*' asks."""
    repere, kind, name = kw["REPERE"], occ["TYPE_CHAM"], occ["NOM_CHAM"]
    if kind not in _SHELL_FIELDS:
        ctx.unsupported(f"MODI_REPERE REPERE={repere!r} of TYPE_CHAM={kind!r}", "TYPE_CHAM", occ)
    if name not in _SHELL_FIELDS[kind]:
        ctx.error(
            f"REPERE={repere!r} with TYPE_CHAM={kind!r} turns {', '.join(_SHELL_FIELDS[kind])}, "
            f"not {name}",
            "NOM_CHAM",
            occ,
        )
    if occ.get("NOM_CMP") is not None:
        ctx.unsupported(f"NOM_CMP with REPERE={repere!r}", "NOM_CMP", occ)
    source = (getattr(result, "element_fields", None) or {}).get(name)
    if source is None:
        ctx.error(f"the result has no {name} field", "NOM_CHAM", occ)
    layout_names = next(
        (names for names in _SHELL_COMPONENTS[kind] if set(names) <= set(source.components)), None
    )
    if layout_names is None:
        ctx.error(f"{name} has not the components of a {kind} field", "TYPE_CHAM", occ)
    cells = np.asarray(source.cells, dtype=int)
    model = getattr(result, "model", None)
    modelisations = getattr(model, "cell_modelisation", {})
    other = [int(c) for c in cells if modelisations.get(int(c)) not in PLATE_MODELISATIONS]
    if other:
        ctx.unsupported(
            f"REPERE={repere!r} of {name} on cells that are not DKT plates "
            f"({mesh.cell_names[other[0]]})",
            "NOM_CHAM",
            occ,
        )
    if characteristics is None:
        ctx.error(f"REPERE={repere!r} needs the plates' CARA_ELEM", "CARA_ELEM", kw)
    shells = characteristics.shells
    user = frame_axes(mesh, cells, [_shell_angles(shells.get(int(c), {})) for c in cells])
    target = None
    if repere == "COQUE":
        (where,) = kw.factor("AFFE")
        chosen = set(select_cells(ctx, where, mesh).tolist())
        given = _shell_angles(where)
        angles = [given if int(c) in chosen else (0.0, 0.0) for c in cells]
        target = frame_axes(mesh, cells, angles)
    columns = [source.components.index(c) for c in layout_names]
    layout = GENERALISED if kind == "COQUE_GENE" else TENSOR
    field = copy.copy(source)
    values = np.array(source.values, copy=True)
    values[..., columns] = change_shell_frame(values[..., columns], layout, repere, user, target)
    field.values = values
    return field


def _shell_frames(ctx, kw, result):
    """The checks REPERE='COQUE*' makes before turning fields (one AFFE
    occurrence naming cells); the CARA_ELEM of the plates' frames, or None."""
    repere = kw["REPERE"]
    occurrences = kw.factor("AFFE")
    if len(occurrences) != 1:
        ctx.error(
            f"REPERE={repere!r} takes one AFFE occurrence, not {len(occurrences)}", "AFFE", kw
        )
    (occ,) = occurrences
    if occ.get("GROUP_NO") is not None or occ.get("NOEUD") is not None:
        key = "GROUP_NO" if occ.get("GROUP_NO") is not None else "NOEUD"
        ctx.error(f"REPERE={repere!r} turns element fields: AFFE names cells, not nodes", key, occ)
    if repere != "COQUE":
        # code_aster turns every cell of the field between its own frames: the
        # cells AFFE names only choose ANGL_REP for REPERE='COQUE' (chrpel)
        occ.mark_used("TOUT", "GROUP_MA", "MAILLE")
    return kw.get("CARA_ELEM") or getattr(result, "characteristics", None)


def _chosen_orders(ctx, kw, result, source):
    """The result on the orders NUME_ORDRE / INST / FREQ choose (code_aster's
    rsutnu: the new result holds those orders only), else on all of them."""
    access = {k.lower(): as_tuple(kw[k]) for k in ("NUME_ORDRE", "INST", "FREQ") if k in kw}
    if not access:
        kw.mark_used("CRITERE", "PRECISION")  # they qualify an INST / FREQ choice only
        return result
    key = next(k for k in ("NUME_ORDRE", "INST", "FREQ") if k in kw)
    if result is source:
        ctx.unsupported(f"MODI_REPERE {key} with reuse=", key, kw)
    if not isinstance(result, DynaHarmo | DynaTrans):
        ctx.unsupported(f"MODI_REPERE {key} of a {result.aster_type}", key, kw)
    try:
        rows = select_steps(
            result_steps(result),
            precision=float(kw.get("PRECISION", 1e-6) or 1e-6),
            criterion=kw.get("CRITERE", "RELATIF"),
            **access,
        )
    except CommandError as exc:
        ctx.error(exc.message, key, kw)
    rows = np.asarray(rows, dtype=int)
    result.order = np.asarray(result.order)[rows]
    if isinstance(result, DynaHarmo):
        result.frequencies = np.asarray(result.frequencies)[rows]
        if result.reactions is not None:
            result.reactions = (result.reactions[0], np.asarray(result.reactions[1])[rows])
    else:
        result.times = np.asarray(result.times)[rows]
    result.fields = {name: np.asarray(v)[rows] for name, v in result.fields.items()}
    for attribute in ("element_fields", "node_fields"):
        held = getattr(result, attribute, None)
        if isinstance(held, dict):
            setattr(result, attribute, {n: _on_rows(f, rows) for n, f in held.items()})
    source_modes = getattr(result, "modal_source", None)
    if source_modes is not None:
        basis, coordinates = source_modes
        result.modal_source = (basis, {n: np.asarray(q)[rows] for n, q in coordinates.items()})
    return result


def _on_rows(field, rows):
    field = copy.copy(field)
    field.values = np.asarray(field.values)[rows]
    return field


def run(ctx, kw):
    if kw.get("CHAM_GD") is not None:
        ctx.unsupported("MODI_REPERE CHAM_GD (fields outside a result)", "CHAM_GD", kw)
    source = kw["RESULTAT"]
    # every order: the default, and the only value of TOUT_ORDRE
    kw.mark_used("TOUT_ORDRE")
    result = source if ctx.reuse is source else copy.copy(source)
    if result is not source:
        for attribute in ("fields", "element_fields", "node_fields"):
            if isinstance(getattr(source, attribute, None), dict):
                setattr(result, attribute, dict(getattr(source, attribute)))
    result = _chosen_orders(ctx, kw, result, source)
    numbering = result.numbering
    mesh = numbering.mesh
    if kw["REPERE"] in _SHELL_REPERES:
        characteristics = _shell_frames(ctx, kw, result)
        for occ in kw.factor("MODI_CHAM"):
            if occ.get("TOUT") is None and occ.get("GROUP_MA") is not None:
                ctx.unsupported("MODI_CHAM GROUP_MA (AFFE says where)", "GROUP_MA", occ)
            field = _shell_field(ctx, kw, occ, result, characteristics, mesh)
            # NOM_CHAM_RESU (EGRU_ELNO): the turned field beside the input one
            stored = occ.get("NOM_CHAM_RESU")
            if stored is not None and (stored, occ["NOM_CHAM"]) != ("EGRU_ELNO", "EFGE_ELNO"):
                ctx.error("NOM_CHAM_RESU is EGRU_ELNO, of an EFGE_ELNO", "NOM_CHAM_RESU", occ)
            field.name = stored or occ["NOM_CHAM"]
            result.element_fields[field.name] = field
            ctx.log(f"MODI_REPERE {occ['NOM_CHAM']} ({occ['TYPE_CHAM']}) to REPERE={kw['REPERE']}")
        return result
    frames = _frames(ctx, kw, mesh)
    for occ in kw.factor("MODI_CHAM"):
        kind, name = occ["TYPE_CHAM"], occ["NOM_CHAM"]
        if kind not in ("TENS_3D", "VECT_3D"):
            ctx.unsupported(f"MODI_REPERE TYPE_CHAM={kind!r}", "TYPE_CHAM", occ)
        if occ.get("TOUT") is None and occ.get("GROUP_MA") is not None:
            ctx.unsupported("MODI_CHAM GROUP_MA (AFFE says where)", "GROUP_MA", occ)
        element = getattr(result, "element_fields", {}).get(name)
        nodal = getattr(result, "node_fields", {}).get(name)
        if element is not None and element.sub_points > 1:
            ctx.unsupported(
                f"MODI_REPERE of {name} on sub-points (multifibre beams)", "NOM_CHAM", occ
            )
        if kind == "TENS_3D" and element is not None:
            field = copy.copy(element)
            field.values = np.array(element.values, copy=True)
            _element_field(ctx, field, occ, frames, mesh, kind)
            result.element_fields[name] = field
        elif kind == "TENS_3D" and nodal is not None:
            field = copy.copy(nodal)
            field.values = np.array(nodal.values, copy=True)
            _node_field(ctx, field, occ, frames, mesh)
            result.node_fields[name] = field
        elif kind == "VECT_3D" and name in getattr(result, "fields", {}):
            result.fields[name] = _dof_vectors(
                ctx, result.fields[name], numbering, occ, frames, mesh
            )
        else:
            ctx.error(f"the result has no {name} field of type {kind}", "NOM_CHAM", occ)
        ctx.log(f"MODI_REPERE {name} ({kind}) to REPERE={kw['REPERE']}")
    return result
