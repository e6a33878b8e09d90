"""POST_RCCM: RCC-M checks; asterlite computes the B3600 equivalent moment.

``TYPE_RESU_MECA='B3600'``, ``OPTION='MOMENT_EQUIVALENT'``: from the
``EFGE_ELNO`` field CALC_CHAMP stored on RESU_MECA's RESULTAT, on the cells
of ZONE_ANALYSE (TOUT or GROUP_MA), at the orders TOUT_ORDRE / NUME_ORDRE /
INST, the table of MT, MFY, MFZ and MEQ = sqrt(MT² + MFY² + MFZ²), each the
signed value of largest magnitude over the orders; or from an EFGE_ELNO
field given as CHAM_GD, its values. Each row has the node's curvilinear
abscissa (ABSC_CURV) when the mesh has one (:mod:`asterlite.post.rccm`).
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.modes import FieldOnElements
from asterlite.fem.selection import select_cells
from asterlite.post.rccm import moment_equivalent_table, moment_equivalent_values
from asterlite.post.restitution import selection_from_keywords


def run(ctx, kw):
    if kw.get("OPTION") != "MOMENT_EQUIVALENT":
        ctx.unsupported(f"POST_RCCM OPTION={kw.get('OPTION')!r}", "OPTION", kw)
    occ = kw.factor("RESU_MECA")[0]
    zone = kw.factor("ZONE_ANALYSE")[0]
    if occ.get("RESULTAT") is None:
        table, cells, mesh, count = _from_field(ctx, zone, occ)
    else:
        table, cells, mesh, count = _from_result(ctx, zone, occ)
    table.title = kw.get("TITRE") or ""
    ctx.log(
        f"POST_RCCM B3600 MOMENT_EQUIVALENT: {len(cells)} cells, {count} orders, "
        f"MEQ max {max(table.column('MEQ'), default=0.0):.6g}"
    )
    return table


def _abscissa(ctx, mesh):
    """The mesh's curvilinear abscissa carte (None, with a note, when absent)."""
    if mesh.curvilinear_abscissa is None:
        ctx.log("the mesh has no curvilinear abscissa (MODI_MAILLAGE ABSC_CURV): no ABSC_CURV")
    return mesh.curvilinear_abscissa


def _moments(ctx, occ, values, components, orders, where: str):
    try:
        return moment_equivalent_values(values, components, orders)
    except ValueError as exc:
        ctx.error(str(exc), where, occ)


def _from_result(ctx, zone, occ):
    """EFGE_ELNO of a result: each quantity's extreme over the chosen orders."""
    result = occ["RESULTAT"]
    name = occ.get("NOM_CHAM", "EFGE_ELNO")
    field = (getattr(result, "element_fields", None) or {}).get(name)
    if field is None:
        ctx.error(f"{name} is not computed on the result (CALC_CHAMP first)", "NOM_CHAM", occ)
    if field.sub_points > 1:
        ctx.unsupported(f"POST_RCCM on {name} of multifibre beams", "NOM_CHAM", occ)
    mesh = result.numbering.mesh
    cells = analysed_cells(ctx, zone, mesh, field.cells)
    orders = selected_orders(ctx, occ, result, field.values.shape[0])
    rows = {int(c): i for i, c in enumerate(field.cells)}
    values = field.values[:, [rows[int(c)] for c in cells]]
    maxima = _moments(ctx, occ, values, field.components, orders, "NOM_CHAM")
    head = {"RESULTAT": result.name or "", "NOM_CHAM": name}
    nodes = [mesh.cell_nodes[int(c)] for c in cells]
    table = moment_equivalent_table(maxima, cells, nodes, head, _abscissa(ctx, mesh))
    return table, cells, mesh, len(orders)


def _from_field(ctx, zone, occ):
    """An EFGE_ELNO field given alone (CREA_CHAMP EXTR): its values as they are."""
    field = occ["CHAM_GD"]
    if not isinstance(field, FieldOnElements) or field.field_name != "EFGE_ELNO":
        what = getattr(field, "field_name", None) or field.aster_type
        ctx.error(f"CHAM_GD must be an EFGE_ELNO field, not {what}", "CHAM_GD", occ)
    mesh = field.mesh
    cells = analysed_cells(ctx, zone, mesh, field.cells)
    rows = {int(c): i for i, c in enumerate(field.cells)}
    values = np.asarray(field.values)[None, [rows[int(c)] for c in cells]]
    moments = _moments(ctx, occ, values, field.components, [0], "CHAM_GD")
    head = {"CHAM_GD": field.name or ""}
    nodes = [mesh.cell_nodes[int(c)] for c in cells]
    table = moment_equivalent_table(moments, cells, nodes, head, _abscissa(ctx, mesh))
    return table, cells, mesh, 1


def analysed_cells(ctx, zone, mesh, carried) -> np.ndarray:
    """ZONE_ANALYSE's cells that carry the field, in mesh order."""
    chosen = select_cells(ctx, zone, mesh, all_cells=carried)
    cells = np.intersect1d(np.asarray(chosen, dtype=int), np.asarray(carried, dtype=int))
    if not cells.size:
        ctx.error("no cell of ZONE_ANALYSE carries the field", "GROUP_MA", zone)
    return cells


def selected_orders(ctx, occ, result, n_orders: int) -> np.ndarray:
    """Indices (into the field's orders) of TOUT_ORDRE / NUME_ORDRE / INST."""
    times = np.asarray(getattr(result, "times", np.arange(n_orders)), dtype=float)
    order = np.asarray(getattr(result, "order", np.arange(1, n_orders + 1)))
    selection = selection_from_keywords(ctx, occ, times, order)
    return np.asarray(selection.lower, dtype=int)
