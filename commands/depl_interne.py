"""DEPL_INTERNE: displacements inside a superelement (code_aster's op0089).

A field (cham_no) on the mesh holding the superelement gives the
superelement's own field: its external DOFs read at the super-cell's nodes
(in its own frame when DEFI_MAILLAGE turned it),
its interior u_i = Φ_ie u_e (the static modes of its Guyan condensation),
its blocked DOFs zero, plus with NOM_CAS the load case's interior response
(ssdein). A result (mode_meca, dyna_harmo, dyna_trans, evol_elas) needs a
superelement of a measured projection (PROJ_MESU): every field is carried
to the measurement mesh, each sensor getting Y V u_e (the identified modes'
combination the interface motion gives, code_aster's cnsprm), the other
components of the sensor nodes zero, and the parameters copied.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from asterlite.concepts.assembly import DofNumbering, NodalField
from asterlite.concepts.harmonic import DynaHarmo
from asterlite.concepts.modes import ModeResult
from asterlite.concepts.transient import DynaTrans
from asterlite.fem.dofs import sort_components


def run(ctx, kw):
    given = kw["DEPL_GLOBAL"]
    name = str(kw["SUPER_MAILLE"])
    mesh = given.numbering.mesh
    cells = getattr(mesh, "super_cells", {})
    if name not in cells:
        ctx.error(f"the mesh of DEPL_GLOBAL has no super-cell {name}", "SUPER_MAILLE", kw)
    cell = cells[name]
    if isinstance(given, NodalField):
        return _interior(ctx, kw, given, cell)
    if cell.macro.measured is None:
        ctx.error(
            "DEPL_INTERNE of a result needs a superelement of a measured projection "
            "(MACR_ELEM_STAT PROJ_MESU)",
            "SUPER_MAILLE",
            kw,
        )
    for keyword in ("RIGI", "MASS"):
        if keyword not in cell.macro.matrices:
            ctx.error(f"the superelement has no {keyword}_MECA matrix", "SUPER_MAILLE", kw)
    return _measured(ctx, kw, given, cell)


def _external_rows(ctx, kw, numbering, cell) -> np.ndarray:
    macro = cell.macro
    nodes = np.repeat(cell.nodes, len(macro.components))
    components = list(macro.components) * len(cell.nodes)
    rows = numbering.dof_indices(nodes, components)
    if np.any(rows < 0):
        ctx.error("DEPL_GLOBAL lacks DOFs of the super-cell's nodes", "DEPL_GLOBAL", kw)
    return rows


def _interior(ctx, kw, given, cell) -> NodalField:
    macro = cell.macro
    case = str(kw.get("NOM_CAS", " ")).strip()
    if case and case not in macro.load_cases:
        ctx.error(f"the superelement has no load case {case}", "NOM_CAS", kw)
    if macro.guyan is None:
        ctx.error(
            "the superelement has no interior static modes (RIGI_MECA of a finite-element "
            "superelement)",
            "SUPER_MAILLE",
            kw,
        )
    external = given.values[_external_rows(ctx, kw, given.numbering, cell)]
    to_local = cell.to_local()
    if to_local is not None:  # a turned super-cell: its own frame
        external = to_local @ external
    values = np.zeros(macro.numbering.n_dofs, dtype=np.asarray(given.values).dtype)
    free = ~macro.blocked_external
    values[macro.guyan.external] = external[free]
    values[macro.guyan.interior] = macro.guyan.interior_values(external[free])
    if case:  # the case's own interior response, external DOFs held
        values = values + cell.load_case(case)[1]
    return NodalField(numbering=macro.numbering, values=values)


def _measured(ctx, kw, given, cell):
    macro = cell.macro
    sensors = macro.sensors.sensors
    numbering = given.numbering
    rows = _external_rows(ctx, kw, numbering, cell)
    # the measurement mesh's DOFs: every component of DEPL_GLOBAL and of the sensors
    components = sort_components({c for _, c in numbering.dofs} | {c for _, _, c in sensors})
    sensor_nodes = sorted({int(n) for n, _, _ in sensors})
    dofs = [(node, c) for node in sensor_nodes for c in components]
    target = DofNumbering(
        mesh=macro.sensors.measurement_model.mesh,
        dofs=dofs,
        model=macro.sensors.measurement_model,
    )
    transfer = np.zeros((target.n_dofs, len(rows)))
    to_local = cell.to_local()
    to_sensors = macro.measured.identified_at_sensors @ macro.measured.to_modes
    for k, (node, direction, component) in enumerate(sensors):
        transfer[target.index[(int(node), component)]] += to_sensors[k]
        if component.startswith("D") and component[1:] in ("1", "2", "3"):
            # a sensor along an axis is also written on that axis's component
            axis = np.flatnonzero(np.abs(direction) > 100.0 * np.finfo(float).eps)
            if axis.size == 1:
                transfer[target.index[(int(node), ("DX", "DY", "DZ")[axis[0]])]] = to_sensors[k]

    if to_local is not None:  # a turned super-cell: its own frame first
        transfer = transfer @ to_local

    def carried(values):
        """(n_states, n_dofs) on DEPL_GLOBAL's DOFs -> on the sensors' DOFs."""
        return np.asarray(values)[:, rows] @ transfer.T

    ctx.log(f"DEPL_INTERNE: {len(sensors)} sensors of the measurement mesh")
    if isinstance(given, ModeResult):
        return dataclasses.replace(
            given,
            numbering=target,
            shapes=carried(given.shapes.T).T.copy(),
            frequencies=np.asarray(given.frequencies).copy(),
            parameters={k: np.asarray(v).copy() for k, v in given.parameters.items()},
            mass=None,
            stiffness=None,
            damping=None,
        )
    fields = {name: carried(values) for name, values in given.fields.items()}
    if isinstance(given, DynaHarmo):
        return DynaHarmo(
            numbering=target,
            frequencies=np.asarray(given.frequencies).copy(),
            order=np.asarray(given.order).copy(),
            fields=fields,
            model=macro.sensors.measurement_model,
        )
    if isinstance(given, DynaTrans):
        return type(given)(
            numbering=target,
            times=np.asarray(given.times).copy(),
            order=np.asarray(given.order).copy(),
            fields=fields,
            model=macro.sensors.measurement_model,
        )
    ctx.unsupported(f"DEPL_INTERNE of a {given.aster_type}", "DEPL_GLOBAL", kw)
