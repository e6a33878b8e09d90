"""POST_RELEVE_T: field values at nodes into a table (``OPERATION='EXTRACTION'``).

For each ACTION occurrence, on a result (dyna_trans, dyna_harmo, mode_meca,
mult_elas) or a nodal field (CHAM_GD; complex values taken as FORMAT_C
says: modulus, real or imaginary part): the components NOM_CMP (or every component with
TOUT_CMP) of NOM_CHAM at the nodes of GROUP_NO / NOEUD, at the chosen steps
(TOUT_ORDRE by default, NUME_ORDRE, NUME_MODE, INST, FREQ, LIST_*, NOM_CAS).
One row per step and node, with code_aster's columns::

    INTITULE RESU NOM_CHAM NUME_ORDRE [INST | NUME_MODE FREQ | NOM_CAS]
    NOEUD COOR_X COOR_Y [COOR_Z] <components>

(a CHAM_GD gives CHAM_GD instead of RESU / NOM_CHAM / access columns).
Nodes are named by number, as code_aster 17 writes them. RESULTANTE sums the
listed components over the nodes (one row per step, no NOEUD / COOR_*);
MOMENT with POINT adds the moment about POINT of the resultant's
translation components (DX, DY, DZ read as forces) plus the listed
rotation components.
"""

from __future__ import annotations

import numpy as np
from asterlite.commands.impr_resu import chosen_steps

from asterlite.concepts.assembly import NodalField
from asterlite.concepts.harmonic import DynaHarmo
from asterlite.concepts.table import Table
from asterlite.io.med_writer import dofs_to_nodal
from asterlite.io.result_store import (
    element_field_names,
    is_physical_result,
    nodal_field_names,
    nodal_series,
    result_steps,
)
from asterlite.post.restitution import as_tuple, node_indices

TRANSLATIONS = ("DX", "DY", "DZ")
ROTATIONS = ("DRX", "DRY", "DRZ")


def run(ctx, kw):
    table = Table(title=kw.get("TITRE") or "")
    for occ in kw.factor("ACTION"):
        check_supported(ctx, occ)
        block = extraction(ctx, occ)
        for row, types in block:
            table.add_row(row, types)
    return table


def check_supported(ctx, occ) -> None:
    operations = as_tuple(occ["OPERATION"])
    other = [op for op in operations if op != "EXTRACTION"]
    if other:
        ctx.unsupported(f"OPERATION={other[0]!r} (EXTRACTION only)", "OPERATION", occ)
    if occ.get("REPERE", "GLOBAL") != "GLOBAL":
        ctx.unsupported(f"REPERE={occ['REPERE']!r} (GLOBAL only)", "REPERE", occ)
    if occ.get("MOYE_NOEUD", "OUI") != "OUI":
        ctx.unsupported("MOYE_NOEUD='NON' (nodal fields only)", "MOYE_NOEUD", occ)


def node_number(mesh, node: int) -> str:
    """code_aster 17 names nodes by their 1-based number in tables."""
    return str(int(node) + 1)


def requested_components(occ) -> tuple[str, ...]:
    if occ.get("TOUT_CMP") == "OUI":
        return ()
    if occ.get("RESULTANTE") is not None:
        return tuple(as_tuple(occ["RESULTANTE"])) + tuple(as_tuple(occ.get("MOMENT")))
    return tuple(as_tuple(occ.get("NOM_CMP")))


def extraction(ctx, occ) -> list[tuple[dict, dict]]:
    """Rows (with their column types) of one ACTION occurrence."""
    nodes = node_indices(ctx, occ, mesh_of(ctx, occ), allow_all=False)
    comps = requested_components(occ)
    if occ.get("RESULTAT") is not None:
        labels, steps, (nodes, comps, values) = result_values(ctx, occ, nodes, comps)
    else:
        labels, steps, (nodes, comps, values) = field_values(ctx, occ, nodes, comps)
    check_components(ctx, occ, comps, values)
    if occ.get("RESULTANTE") is not None:
        return resultant_rows(ctx, occ, labels, steps, nodes, comps, values)
    mesh = mesh_of(ctx, occ)
    axes = ("COOR_X", "COOR_Y", "COOR_Z")[: max(2, min(mesh.dim, 3))]
    absent = absent_components(occ, nodes, comps)
    rows = []
    for k, step in enumerate(steps):
        for j, node in enumerate(nodes):
            row = {**labels, **step, "NOEUD": node_number(mesh, node)}
            row.update({a: float(mesh.coords[node, i]) for i, a in enumerate(axes)})
            row.update({c: float(values[k, j, i]) for i, c in enumerate(comps) if not absent[j, i]})
            rows.append((row, COLUMN_TYPES))
    return rows


def absent_components(occ, nodes, comps) -> np.ndarray:
    """(node, component) cells a row leaves empty, as code_aster does: a
    component of the numbering that this node does not carry (a rotation at
    a solid's node beside beams). Components the numbering does not know
    (fields computed by CALC_CHAMP) are taken as present."""
    source = occ.get("RESULTAT") or occ.get("CHAM_GD")
    dofs = set(source.numbering.dofs)
    known = {c for _, c in dofs}
    return np.array(
        [[c in known and (int(n), c) not in dofs for c in comps] for n in nodes], dtype=bool
    ).reshape(len(nodes), len(comps))


COLUMN_TYPES = {
    "INTITULE": "K16",
    "RESU": "K8",
    "CHAM_GD": "K8",
    "NOM_CHAM": "K16",
    "NUME_ORDRE": "I",
    "NUME_MODE": "I",
    "NOM_CAS": "K16",
    "NOEUD": "K8",
}


def mesh_of(ctx, occ):
    source = occ.get("RESULTAT") or occ.get("CHAM_GD")
    return source.numbering.mesh


def result_values(ctx, occ, nodes, comps):
    result = occ["RESULTAT"]
    if not (is_physical_result(result) or isinstance(result, DynaHarmo)):
        ctx.unsupported(f"POST_RELEVE_T on a {result.aster_type}", "RESULTAT", occ)
    name = occ["NOM_CHAM"]
    if name not in nodal_field_names(result):
        if name in element_field_names(result):
            ctx.unsupported(f"extraction of the element field {name}", "NOM_CHAM", occ)
        ctx.error(
            f"the result {result.name or ''} has no field {name} "
            f"(it has {', '.join(nodal_field_names(result)) or 'none'})",
            "NOM_CHAM",
            occ,
        )
    steps = result_steps(result)
    indices = chosen_steps(ctx, occ, steps)
    nodes, comps, values = nodal_series(result, name, nodes, comps)
    values = as_real(occ, values)
    labels = {"INTITULE": occ["INTITULE"], "RESU": result.name or "", "NOM_CHAM": name}
    access = [{"NUME_ORDRE": int(steps.orders[i]), **steps.parameters(i)} for i in indices]
    return labels, access, (nodes, comps, values[indices])


def field_values(ctx, occ, nodes, comps):
    field = occ["CHAM_GD"]
    if not isinstance(field, NodalField):
        ctx.unsupported(f"CHAM_GD of type {field.aster_type}", "CHAM_GD", occ)
    labels = {"INTITULE": occ["INTITULE"], "CHAM_GD": field.name or ""}
    nodes, comps, values = dofs_to_nodal(field.numbering, field.values[None, :], nodes, comps)
    return labels, [{}], (nodes, comps, as_real(occ, values))


def as_real(occ, values: np.ndarray) -> np.ndarray:
    """A complex field's values as FORMAT_C asks: MODULE, REEL or IMAG (rvrecu)."""
    if not np.iscomplexobj(values):
        return values
    form = occ.get("FORMAT_C", "MODULE")
    if form == "REEL":
        return values.real
    if form == "IMAG":
        return values.imag
    return np.abs(values)


def check_components(ctx, occ, comps, values) -> None:
    if not comps:
        ctx.error("no component to extract at these nodes", "NOM_CMP", occ)
    if values.shape[1] == 0:
        ctx.error("no value of the field at the requested nodes", "GROUP_NO", occ)


def resultant_rows(ctx, occ, labels, steps, nodes, comps, values):
    """One row per step: sums over the nodes (and moments about POINT)."""
    mesh = mesh_of(ctx, occ)
    sums = values.sum(axis=1)  # (n_steps, n_comp)
    moments = as_tuple(occ.get("MOMENT"))
    arms = None
    if moments:
        point = np.zeros(3)
        given = np.asarray(as_tuple(occ["POINT"]), dtype=float)
        point[: given.size] = given[:3]
        arms = mesh.coords[nodes] - point  # (n_nodes, 3)
    rows = []
    for k, step in enumerate(steps):
        row = {**labels, **step}
        for i, c in enumerate(comps):
            if c in as_tuple(occ["RESULTANTE"]):
                row[c] = float(sums[k, i])
        if arms is not None:
            row.update(moment_about(arms, comps, values[k], moments))
        rows.append((row, COLUMN_TYPES))
    return rows


def moment_about(arms, comps, values, moments) -> dict[str, float]:
    """Σ r × F (F from DX, DY, DZ) plus Σ of the rotation components, for the
    moment components asked."""
    force = np.zeros((len(arms), 3))
    for a, c in enumerate(TRANSLATIONS):
        if c in comps:
            force[:, a] = values[:, comps.index(c)]
    total = np.cross(arms, force).sum(axis=0)
    out = {}
    for a, c in enumerate(ROTATIONS):
        if c in moments:
            own = values[:, comps.index(c)].sum() if c in comps else 0.0
            out[c] = float(total[a] + own)
    return out
