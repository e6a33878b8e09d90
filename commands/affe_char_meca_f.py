"""AFFE_CHAR_MECA_F: DDL_IMPO, FORCE_NODALE and FORCE_POUTRE whose values are
functions (DEFI_FONCTION, FORMULE, DEFI_CONSTANTE) of the geometry, and
ONDE_PLANE (a seismic plane wave on paraxial boundaries, kept as a wave: its
nodal forces are a history, asterlite.fem.plane_wave).

code_aster evaluates such a function where the load acts: at the node for
DDL_IMPO and FORCE_NODALE, at both nodes of each beam cell for FORCE_POUTRE
(the load then varies linearly along the cell, ptforp/ptfop1), with the
parameters X, Y, Z of the point (and INST, the current time, in time
stepping, or FREQ, in a harmonic response). asterlite evaluates them once,
when the load is built, except DDL_IMPO values of INST (evaluated in time by
a physical-basis transient) or FREQ (evaluated at each frequency by
DYNA_VIBRA HARM) and FORCE_NODALE values of INST (a history of nodal forces,
evaluated at its instants by a physical-basis transient, refused by the
commands that take a fixed load vector); forces of FREQ are refused, as are
the other keywords of the catalogue (not read, hence refused by name).
"""

from __future__ import annotations

import numpy as np
from asterlite.commands import affe_char_meca

from asterlite.concepts.assembly import MechanicalLoad, ValueInFrequency, ValueInTime
from asterlite.errors import CommandError
from asterlite.fem.plane_wave import PlaneWave
from asterlite.fem.selection import select_cells

# the parameters code_aster gives these functions, and their value at a node
_GEOMETRY = ("X", "Y", "Z")
_CONSTANT = "TOUTPARA"  # DEFI_CONSTANTE's parameter: any value


def _parameters(function) -> tuple[str, ...]:
    names = getattr(function, "nom_para", None)
    if names is None:
        return ()
    return tuple(names)


def _evaluator(ctx, model, occ, in_time=None, in_frequency=None):
    """value_at(function, node, key): the function at the node's coordinates.
    ``in_time`` (a dict): a function of INST is accepted, its value at
    INST=0 returned and its ``ValueInTime`` kept in ``in_time[(node, key)]``;
    ``in_frequency`` likewise for a function of FREQ (evaluated at each
    frequency of a harmonic response: 0 is returned); without them, such
    functions are refused."""

    coords = model.mesh.coords

    def value_at(function, node: int, key: str) -> float:
        if isinstance(function, (int, float)):
            return float(function)
        names = _parameters(function)
        if "FREQ" in names and in_frequency is not None:
            # code_aster evaluates it at each frequency of a harmonic response
            unknown = [p for p in names if p not in _GEOMETRY and p not in ("FREQ", _CONSTANT)]
            if unknown:
                ctx.error(
                    f"{key}: the function {function.name or ''} depends on "
                    f"{', '.join(unknown)}; an imposed value takes X, Y, Z and FREQ",
                    key,
                    occ,
                )
            point = tuple(float(x) for x in np.pad(coords[node], (0, 3 - len(coords[node]))))
            in_frequency[(node, key)] = ValueInFrequency(function, point)
            return 0.0
        if "FREQ" in names:
            ctx.unsupported(
                f"{ctx.command} {key}={function.name or 'function'} depends on FREQ (a value "
                "varying with the frequency of a harmonic response)",
                key,
                occ,
            )
        if "INST" in names and in_time is not None:
            unknown = [p for p in names if p not in _GEOMETRY and p not in ("INST", _CONSTANT)]
            if unknown:
                ctx.error(
                    f"{key}: the function {function.name or ''} depends on "
                    f"{', '.join(unknown)}; a load function takes X, Y, Z and INST",
                    key,
                    occ,
                )
            point = tuple(float(x) for x in np.pad(coords[node], (0, 3 - len(coords[node]))))
            value = ValueInTime(function, point)
            try:
                initial = float(value.evaluate([0.0])[0])
            except CommandError as exc:
                ctx.error(str(exc), key, occ)
            in_time[(node, key)] = value
            return initial
        if "INST" in names:
            ctx.unsupported(
                f"AFFE_CHAR_MECA_F {key}={function.name or 'function'} depends on INST (a load "
                "varying in time)",
                key,
                occ,
            )
        unknown = [p for p in names if p not in _GEOMETRY and p != _CONSTANT]
        if unknown:
            ctx.error(
                f"{key}: the function {function.name or ''} depends on {', '.join(unknown)}; "
                f"a load function takes X, Y, Z (and INST)",
                key,
                occ,
            )
        point = dict(zip(_GEOMETRY, coords[node], strict=True))
        args = [point.get(p, 0.0) for p in names]
        try:
            value = function(*args)
        except CommandError as exc:
            ctx.error(str(exc), key, occ)
        return float(np.real(value))

    return value_at


def _forces_in_time(load, first: int, in_time: dict) -> None:
    """The nodal forces of one FORCE_NODALE occurrence that are functions of
    INST leave the constant terms for the load's history
    (``extra['FORCE_NODALE_INST']``: node, component, ValueInTime), which a
    physical-basis transient evaluates at its instants
    (asterlite.fem.loads.load_history)."""
    if not in_time:
        return
    timed = {
        (node, affe_char_meca._FORCE_COMPONENTS[key]): value
        for (node, key), value in in_time.items()
    }
    added = load.nodal_forces[first:]
    del load.nodal_forces[first:]
    history = load.extra.setdefault("FORCE_NODALE_INST", [])
    for node, component, value in added:
        if (node, component) in timed:
            history.append((node, component, timed[(node, component)]))
        else:
            load.nodal_forces.append((node, component, value))


def _force_poutre(ctx, model, load, occ) -> None:
    """Values at the first and the second node of each cell (linear along it)."""
    keys, local = affe_char_meca.beam_load_keys(ctx, occ)
    cells = affe_char_meca.beam_load_cells(ctx, model, occ)
    value_at = _evaluator(ctx, model, occ)
    ends = np.array([model.mesh.cell_nodes[c][:2] for c in cells], dtype=int).reshape(-1, 2)
    first = np.zeros((len(cells), 6))
    second = np.zeros((len(cells), 6))
    for k, key in enumerate(keys):
        function = occ.get(key)
        if function is None:
            continue
        first[:, k] = [value_at(function, int(n), key) for n in ends[:, 0]]
        second[:, k] = [value_at(function, int(n), key) for n in ends[:, 1]]
    load.extra.setdefault("FORCE_POUTRE", []).append(
        {"CELLS": cells, "VALUES": first, "VALUES_2": second, "LOCAL": local}
    )


def _onde_plane(ctx, model, load, occ) -> None:
    """The wave and the absorbing cells it loads (3D_ABSO faces, D_PLAN_ABSO
    edges); the forces at each instant come from plane_wave_history."""

    def point(key):
        given = occ.get(key)
        if given is None:
            return None
        values = np.asarray(given, dtype=float).ravel()
        return np.pad(values, (0, 3 - values.size))

    cells = select_cells(ctx, occ, model.mesh) if occ.get("GROUP_MA") else None
    if cells is None:
        cells = [c for c, m in model.cell_modelisation.items() if m in ("3D_ABSO", "D_PLAN_ABSO")]
    wrong = [
        c for c in cells if model.cell_modelisation.get(int(c)) not in ("3D_ABSO", "D_PLAN_ABSO")
    ]
    if wrong:
        ctx.error(
            f"ONDE_PLANE on cell {model.mesh.cell_names[wrong[0]]}, which is not an absorbing "
            "boundary (3D_ABSO, D_PLAN_ABSO)",
            "GROUP_MA",
            occ,
        )
    wave = PlaneWave(
        kind=occ["TYPE_ONDE"],
        direction=np.asarray(occ["DIRECTION"], dtype=float),
        signal=occ["FONC_SIGNAL"],
        source=point("COOR_SOURCE"),
        reflection=point("COOR_REFLECHI"),
        displacement=occ.get("DEPL_IMPO"),
    )
    load.extra.setdefault("ONDE_PLANE", []).append(
        {"CELLS": np.asarray(cells, dtype=int), "WAVE": wave}
    )


def run(ctx, kw):
    model = kw["MODELE"]
    components = model.node_components()
    load = MechanicalLoad(model=model)
    if not any(kw.factor(k) for k in ("FACE_IMPO", "PRES_REP", "FORCE_COQUE", "EFFE_FOND")):
        # code_aster's VERI_NORM checks the faces of these keywords only
        kw.mark_used("VERI_NORM")
    for occ in kw.factor("DDL_IMPO"):
        in_time, in_frequency = {}, {}
        first = len(load.relations)
        value_at = _evaluator(ctx, model, occ, in_time, in_frequency)
        affe_char_meca._ddl_impo(ctx, model, components, load, occ, value_at=value_at)
        for relation in load.relations[first:]:
            if len(relation.terms) == 1:
                node, component, _ = relation.terms[0]
                relation.rhs_in_time = in_time.get((node, component))
                relation.rhs_in_frequency = in_frequency.get((node, component))
    for occ in kw.factor("FORCE_NODALE"):
        in_time = {}
        first = len(load.nodal_forces)
        value_at = _evaluator(ctx, model, occ, in_time)
        affe_char_meca._force_nodale(ctx, model, components, load, occ, value_at=value_at)
        _forces_in_time(load, first, in_time)
    for occ in kw.factor("FORCE_POUTRE"):
        _force_poutre(ctx, model, load, occ)
    for occ in kw.factor("ONDE_PLANE"):
        _onde_plane(ctx, model, load, occ)
    ctx.log(f"load: {len(load.relations)} relations, {len(load.nodal_forces)} nodal forces")
    return load
