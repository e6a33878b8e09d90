"""CREA_RESU OPERATION='CONV_RESU' and 'KUCV': a result's nodal field turned
into the displacements of a dyna_trans or the nodal forces of an evol_char
(a load history for AFFE_CHAR_MECA EVOL_CHAR), as code_aster's crcore and
crkucv do it. KUCV's forces are C v + K u of RESU_INIT at each instant.

At each instant t of INST / LIST_INST, the field NOM_CHAM_INIT of RESU_INIT
at t (found within PRECISION / CRITERE) is copied onto the DOFs of NUME_DDL
(or MATR_RIGI's numbering) by node and component, then:

- DDL_EXCLUS: that component is set to zero at every node;
- GROUP_NO_INTERF: each node of the group takes the field at
  t - dt·int(delay/dt) instead, delay = ((x - COOR_REFE)·DIRECTION) / VITE_ONDE
  and dt the first step of the instants (zero when no such instant is stored);
- FONC_DX ... FONC_DRZ: each component becomes the formula of the node's
  DX ... DRZ (those of the formulas given, 0 for the others) and INST;

and the result is COEF times that. The field is stored as DEPL in a
dyna_trans (NOM_CHAM_INIT with FONC_*), as FORC_NODA in an evol_char.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.static_result import EvolChar
from asterlite.concepts.transient import DynaTrans
from asterlite.fem.loads import load_history, load_terms
from asterlite.fem.selection import as_tuple, node_group_members
from asterlite.modal.renumber import transfer

_COMPONENTS = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")


def _rows_at(times, t: float, precision: float, criterion: str) -> np.ndarray:
    tolerance = precision * abs(t) if criterion == "RELATIF" else precision
    return np.flatnonzero(np.abs(np.asarray(times) - t) <= tolerance)


def _formula_values(formula, parameters: dict) -> np.ndarray:
    """A deck formula or nappe of DX ... DRZ, INST on arrays (point by point
    when the formula does not take arrays)."""
    names = tuple(formula.nom_para)
    columns = [np.broadcast_to(parameters[name], parameters["DX"].shape) for name in names]
    try:
        return np.broadcast_to(formula.evaluate_many(*columns), columns[0].shape).astype(float)
    except Exception:  # noqa: BLE001 - deck functions may not take arrays
        return np.array(
            [float(formula(*(float(c[i]) for c in columns))) for i in range(columns[0].size)]
        )


def conv_resu(ctx, kw):
    occ = kw.factor("CONV_RESU")[0]
    if occ.get("MATR_RIGI") is not None:
        numbering = occ["MATR_RIGI"].numbering
    else:
        numbering = occ["NUME_DDL"]
    return convert(ctx, occ, kw["TYPE_RESU"], numbering)


def _instants(occ) -> np.ndarray:
    if occ.get("LIST_INST") is not None:
        return np.asarray(occ["LIST_INST"].values, dtype=float)
    return np.asarray(as_tuple(occ["INST"]), dtype=float)


def _source_rows(ctx, occ, source, instants, name) -> tuple[list[int], object]:
    """The rows of RESU_INIT at the instants (PRECISION / CRITERE), and the
    search ``t -> row or None`` for other instants."""
    precision, criterion = float(occ.get("PRECISION", 1.0e-6)), occ.get("CRITERE", "RELATIF")
    source_times = np.asarray(source.times, dtype=float)

    def source_row(t: float) -> int | None:
        rows = _rows_at(source_times, t, precision, criterion)
        return int(rows[0]) if rows.size else None

    rows = []
    for t in instants:
        row = source_row(float(t))
        if row is None:
            ctx.error(f"RESU_INIT has no {name} field at INST={t:g}", "RESU_INIT", occ)
        rows.append(row)
    return rows, source_row


def _result(type_resu, numbering, instants, values, stored="DEPL"):
    order = np.arange(1, instants.size + 1)
    if type_resu == "EVOL_CHAR":
        return EvolChar(
            numbering=numbering, times=instants, order=order, fields={"FORC_NODA": values}
        )
    return DynaTrans(
        numbering=numbering,
        times=instants,
        order=order,
        fields={stored: values},
        model=numbering.model,
    )


def convert(ctx, occ, type_resu: str, numbering):
    """CONV_RESU from the keywords of ``occ`` (CREA_RESU's CONV_RESU
    occurrence, or DEFI_CHAR_SOL's own keywords) onto ``numbering``."""
    source = occ["RESU_INIT"]
    name = occ.get("NOM_CHAM_INIT")
    if name is None:
        ctx.error("CONV_RESU needs NOM_CHAM_INIT", "NOM_CHAM_INIT", occ)
    fields = getattr(source, "fields", None)
    if not isinstance(fields, dict) or name not in fields:
        known = ", ".join(fields) if isinstance(fields, dict) else "none"
        ctx.error(f"RESU_INIT holds no {name} field (it has {known})", "NOM_CHAM_INIT", occ)
    if numbering.mesh is not source.numbering.mesh:
        ctx.error("RESU_INIT is on another mesh than the numbering", "RESU_INIT", occ)
    instants = _instants(occ)
    if instants.size < 2:
        # code_aster takes the first step of the list as dt
        ctx.error("CONV_RESU needs at least two instants", "LIST_INST", occ)
    stack = np.asarray(fields[name], dtype=float)
    rows, source_row = _source_rows(ctx, occ, source, instants, name)
    values = transfer(stack[rows].T, source.numbering, numbering).T.copy()

    excluded = occ.get("DDL_EXCLUS")
    if excluded is not None:
        values[:, [i for i, (_, c) in enumerate(numbering.dofs) if c == excluded]] = 0.0

    if occ.get("GROUP_NO_INTERF") is not None:
        values = _delayed(ctx, occ, numbering, source, stack, instants, values, source_row)

    functions = {c: occ.get(f"FONC_{c}") for c in _COMPONENTS if occ.get(f"FONC_{c}")}
    if functions:
        values = _of_functions(numbering, functions, instants, values)

    values *= float(occ.get("COEF", 1.0))
    ctx.log(f"CONV_RESU: {name} of {instants.size} instants, {numbering.n_dofs} DOFs")
    return _result(type_resu, numbering, instants, values, name if functions else "DEPL")


def kucv(ctx, occ, type_resu: str):
    """CREA_RESU KUCV (code_aster's crkucv): C v + K u of RESU_INIT at each
    instant (K u with MATR_RIGI only), on MATR_AMOR's numbering: the
    forces of a paraxial boundary driven by a free-field motion."""
    source, damping = occ["RESU_INIT"], occ["MATR_AMOR"]
    stiffness = occ.get("MATR_RIGI")
    numbering = damping.numbering
    if stiffness is not None and stiffness.numbering is not numbering:
        ctx.error("MATR_RIGI and MATR_AMOR are on different numberings", "MATR_RIGI", occ)
    instants = _instants(occ)
    needed = ("VITE", "DEPL") if stiffness is not None else ("VITE",)
    for name in needed:
        if name not in source.fields:
            ctx.error(f"RESU_INIT holds no {name} field", "RESU_INIT", occ)
    rows, _ = _source_rows(ctx, occ, source, instants, "VITE")

    def on_numbering(name):
        stack = np.asarray(source.fields[name], dtype=float)[rows]
        return transfer(stack.T, source.numbering, numbering).T

    values = np.asarray(damping.matrix @ on_numbering("VITE").T).T
    if stiffness is not None:
        values = values + np.asarray(stiffness.matrix @ on_numbering("DEPL").T).T
    ctx.log(f"KUCV: {instants.size} instants, {numbering.n_dofs} DOFs")
    return _result(type_resu, numbering, instants, values)


def _delayed(ctx, occ, numbering, source, stack, instants, values, source_row):
    """GROUP_NO_INTERF: the group's nodes take the field at their delayed
    instant (zero where none is stored)."""
    nodes = np.asarray(node_group_members(ctx, occ, numbering.mesh, "GROUP_NO_INTERF"), dtype=int)
    direction = np.asarray(as_tuple(occ["DIRECTION"]), dtype=float)
    direction = direction / np.linalg.norm(direction)
    reference = np.asarray(as_tuple(occ["COOR_REFE"]), dtype=float)
    coords = np.asarray(numbering.mesh.coords, dtype=float)[nodes][:, :3]
    distances = (coords - reference) @ direction
    if np.any(distances < 0.0):
        ctx.log(
            "warning: CONV_RESU: nodes of GROUP_NO_INTERF behind COOR_REFE along "
            "DIRECTION (negative delays), as code_aster warns (SEISME_78)"
        )
    dt = float(instants[1] - instants[0])
    # whole steps of delay, truncated toward zero as code_aster's int()
    shifts = np.trunc(distances / float(occ["VITE_ONDE"]) / dt).astype(np.int64)
    node_of_dof = np.array([n for n, _ in numbering.dofs])
    out = values.copy()
    for shift in np.unique(shifts):
        group = nodes[shifts == shift]
        targets = np.flatnonzero(np.isin(node_of_dof, group))
        if not targets.size:
            continue
        sources = source.numbering.dof_indices(
            [numbering.dofs[i][0] for i in targets], [numbering.dofs[i][1] for i in targets]
        )
        found = sources >= 0
        for k, t in enumerate(instants):
            row = source_row(float(t) - dt * int(shift))
            out[k, targets] = 0.0
            if row is not None:
                out[k, targets[found]] = stack[row, sources[found]]
    return out


def _of_functions(numbering, functions, instants, values):
    """FONC_DX ...: each given component is its formula of the node's
    components (0 for those without a formula) and INST."""
    dofs = numbering.dofs
    nodes = np.unique([n for n, _ in dofs])
    columns = {c: numbering.dof_indices(nodes, [c] * nodes.size) for c in _COMPONENTS}
    out = values.copy()
    for k, t in enumerate(instants):
        parameters = {
            c: (
                np.where(columns[c] >= 0, values[k, np.maximum(columns[c], 0)], 0.0)
                if c in functions
                else np.zeros(nodes.size)
            )
            for c in _COMPONENTS
        }
        parameters["INST"] = np.full(nodes.size, float(t))
        for component, formula in functions.items():
            present = columns[component] >= 0
            result = _formula_values(formula, parameters)
            out[k, columns[component][present]] = result[present]
    return out


def conv_char(ctx, kw):
    """CREA_RESU CONV_CHAR (code_aster's crcoch): at each instant the nodal
    forces of the loads CHARGE (their Neumann terms and the plane waves of
    AFFE_CHAR_MECA_F/ONDE_PLANE at that instant; imposed displacements are
    no force) assembled on MATR_RIGI's numbering, stored as DEPL in a
    dyna_trans or FORC_NODA in an evol_char."""
    from asterlite.commands.dyna_vibra_phys import history_rows

    from asterlite.fem.assemble import assemble_terms

    occ = kw.factor("CONV_CHAR")[0]
    if ctx.reuse is not None:
        ctx.unsupported("CREA_RESU CONV_CHAR with reuse", "reuse", kw)
    # PRECISION / CRITERE find the instants already stored in the result: a
    # new result has none
    occ.mark_used("PRECISION", "CRITERE")
    stiffness = occ["MATR_RIGI"]
    numbering = stiffness.numbering
    materials = occ["CHAM_MATER"]
    characteristics = occ.get("CARA_ELEM")
    instants = _instants(occ)
    if instants.size == 0 or np.any(np.diff(instants) <= 0.0):
        ctx.error("the instants must be strictly increasing", "LIST_INST", occ)
    values = np.zeros((instants.size, numbering.n_dofs))
    for load in as_tuple(occ["CHARGE"]):
        if load.model.mesh is not numbering.mesh:
            ctx.error(f"the load {load.name or ''} is on another mesh", "CHARGE", occ)
        try:
            terms = load_terms(load, characteristics, materials, history_apart=True)
            values += assemble_terms(terms, numbering)[None, :]
        except KeyError as exc:
            ctx.error(f"load on DOFs the numbering does not have: {exc}", "CHARGE", occ)
        history = load_history(load, materials)
        if history is None:
            continue
        nodes, components, forces = history(instants)
        rows = history_rows(ctx, numbering, nodes, components, occ)
        for k in range(instants.size):
            np.add.at(values[k], rows, forces[k])
    count = len(as_tuple(occ["CHARGE"]))
    ctx.log(f"CONV_CHAR: forces of {count} loads at {instants.size} instants")
    return _result(kw["TYPE_RESU"], numbering, instants, values)
