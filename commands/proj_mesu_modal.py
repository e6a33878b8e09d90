"""PROJ_MESU_MODAL: the generalized coordinates on MODELE_CALCUL's BASE that
best explain MODELE_MESURE's MESURE (code_aster's op0193).

Sensors are the measured translations of the measurement mesh: for
identified modes (mode_meca) the DX, DY, DZ some mode moves (above 100
machine precisions), for a transient or harmonic measurement every DX, DY,
DZ its field carries and every D1, D2, D3 along the direction its D1X..D3Z
give (LIRE_RESU FORMAT='IDEAS_DS58'); or gauges, every measured component
of SIEF_NOEU / EPSI_NOEU, compared with the basis' SIGM_NOEU / EPSI_NOEU
(CALC_CHAMP). Measurement nodes are paired with the nearest calculation
node when the calculation model has discrete elements, bars or pipes but
no beams, plates or shells, else placed in its cells by collocation (as
PROJ_CHAMP does); CORR_MANU pairs a node by hand. Each measured state is solved as
asterlite.modal.measured_projection describes. The result is a mode_gene
(measured modes: FREQ and the NOM_PARA parameters copied), a tran_gene
(instants; velocities and accelerations by finite differences, or
displacements integrated from measured VITE / ACCE as code_aster does) or
a harm_gene (frequencies; VITE = iω DEPL, ACCE = -ω² DEPL; measured VITE or
ACCE give DEPL = VITE / iω or -ACCE / ω²: code_aster's mpinvc multiplies by
-iω there, with ω taken past the last frequency, which is not kept).

Two more departures from op0193, both where its result is not the least-
squares solution it means: with fewer sensors than modes and no weight the
minimum-norm coordinates Hᵀ(HHᵀ)⁺y are taken whole (mpinvr keeps only the
last sensor's term); complex measured modes (mode_meca_c) are refused.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.harmonic import DynaHarmo, HarmGene
from asterlite.concepts.modes import (
    ComplexModeResult,
    GeneralizedModes,
    GeneralizedNumbering,
    ModeResult,
)
from asterlite.concepts.transient import DynaTrans, TranGene
from asterlite.modal import measured_projection as mp
from asterlite.post import field_projection as fp

_TRANSLATIONS = ("DX", "DY", "DZ")
# gauges: the measured field, the basis field they are compared with, its components
_GAUGES = {
    "SIEF_NOEU": ("SIGM_NOEU", ("SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ")),
    "EPSI_NOEU": ("EPSI_NOEU", ("EPXX", "EPYY", "EPZZ", "EPXY", "EPXZ", "EPYZ")),
}
_PLATES = ("DKT", "DST", "Q4G", "COQUE", "GRILLE", "MEMBRANE")
_STRUCTURAL = ("DIS_", "2D_DIS_", "BARRE", "2D_BARRE", "CABLE", "TUYAU") + _PLATES


def run(ctx, kw):
    calc = kw.factor("MODELE_CALCUL")[0]
    mesu = kw.factor("MODELE_MESURE")[0]
    basis, measured = calc["BASE"], mesu["MESURE"]
    names = _field_name(ctx, mesu)
    if isinstance(measured, ComplexModeResult):
        ctx.unsupported("PROJ_MESU_MODAL of complex modes (mode_meca_c)", "MESURE", mesu)
    if not hasattr(basis, "shapes"):
        ctx.unsupported(f"PROJ_MESU_MODAL on a {basis.aster_type} basis", "BASE", calc)
    calc_mesh, mesu_mesh = calc["MODELE"].mesh, mesu["MODELE"].mesh
    if basis.numbering.mesh is not calc_mesh:
        ctx.error("the basis does not lie on MODELE_CALCUL's mesh", "BASE", calc)
    if measured.numbering.mesh is not mesu_mesh:
        ctx.error("the measured result does not lie on MODELE_MESURE's mesh", "MESURE", mesu)

    abscissas, values = _measured_states(ctx, mesu, measured, names)
    sensors, data = _sensors(ctx, mesu, measured, values, names[0])
    observation = _observation(ctx, kw, calc, mesu, basis, sensors, names[0])
    resolution = _resolution(ctx, kw, basis.n_modes, abscissas)
    try:
        eta = mp.identify(observation, data, resolution)
    except mp.MeasuredProjectionError as exc:
        ctx.error(str(exc), "RESOLUTION")
    ctx.log(
        f"PROJ_MESU_MODAL: {len(sensors)} sensors, {basis.n_modes} modes, "
        f"{len(abscissas)} measured states, {resolution.method} "
        f"(REGUL={resolution.regul})"
    )
    if isinstance(measured, DynaTrans):
        return _transient(basis, abscissas, eta, names[0])
    if isinstance(measured, DynaHarmo):
        return _harmonic(basis, abscissas, eta, names[0])
    return _modes(ctx, kw, basis, measured, eta)


def _field_name(ctx, mesu) -> list[str]:
    names = list(np.atleast_1d(mesu["NOM_CHAM"]))
    if len(names) > 1:
        ctx.unsupported("PROJ_MESU_MODAL with several NOM_CHAM", "NOM_CHAM", mesu)
    return names


def _measured_states(ctx, mesu, measured, names):
    """Abscissas (instants, frequencies) and the (n_states, n_dofs) values."""
    name = names[0]
    if isinstance(measured, ModeResult):
        if name in _GAUGES:
            ctx.unsupported(f"PROJ_MESU_MODAL of measured modes' {name}", "NOM_CHAM", mesu)
        if name != "DEPL":
            ctx.error(f"measured modes have no field {name}", "NOM_CHAM", mesu)
        return np.asarray(measured.frequencies, dtype=float), measured.shapes.T
    if name not in measured.fields:
        ctx.error(f"the measured result has no field {name}", "NOM_CHAM", mesu)
    if isinstance(measured, DynaTrans):
        abscissas = np.asarray(measured.times, dtype=float)
        if abscissas.size < 2:
            ctx.error("a measured transient needs at least two instants", "MESURE", mesu)
    else:
        abscissas = np.asarray(measured.frequencies, dtype=float)
    return abscissas, np.asarray(measured.fields[name])


def _sensors(ctx, mesu, measured, values, name):
    """The sensors, (node, unit direction) each, and their (n_states,
    n_sensors) data: translations DX, DY, DZ, and for a transient or harmonic
    measurement D1, D2, D3 along the direction their D1X..D3Z give."""
    dofs = measured.numbering.dofs
    index = measured.numbering.index
    if name in _GAUGES:
        # every measured component of the gauges' tensor is a sensor
        columns = [i for i, (_, c) in enumerate(dofs) if c in _GAUGES[name][1]]
        if not columns:
            ctx.error(f"the measurement has no {name} component", "MESURE", mesu)
        return [dofs[i] for i in columns], values[:, columns]
    modes = isinstance(measured, ModeResult)
    kinds = _TRANSLATIONS if modes else _TRANSLATIONS + ("D1", "D2", "D3")
    columns = [i for i, (_, c) in enumerate(dofs) if c in kinds]
    if modes:
        moved = np.abs(values[:, columns]).max(axis=0) > mp.SENSOR_THRESHOLD
        columns = [c for c, keep in zip(columns, moved, strict=True) if keep]
    if not columns:
        ctx.error("the measurement has no measured translation", "MESURE", mesu)
    sensors = []
    for i in columns:
        node, component = dofs[i]
        if component in _TRANSLATIONS:
            direction = np.eye(3)[_TRANSLATIONS.index(component)]
        else:
            # the sensor's orientation, read at the first measured state
            direction = np.array(
                [
                    np.real(values[0, index[(node, f"{component}{axis}")]])
                    if (node, f"{component}{axis}") in index
                    else 0.0
                    for axis in "XYZ"
                ]
            )
            norm = np.linalg.norm(direction)
            if norm <= np.finfo(float).eps:
                name = measured.numbering.mesh.node_names[node]
                ctx.error(f"the sensor {component} at node {name} has no direction", "MESURE", mesu)
            direction = direction / norm
        sensors.append((node, direction))
    return sensors, values[:, columns]


def _observation(ctx, kw, calc, mesu, basis, sensors, name) -> np.ndarray:
    """The basis at the sensors, (n_sensors, n_modes): each measurement node
    paired with a calculation node or placed in the calculation cells (then
    CORR_MANU's pairs); displacements projected on the sensor's direction,
    gauges compared with the basis' stress or strain component."""
    calc_mesh = calc["MODELE"].mesh
    mesu_mesh = mesu["MODELE"].mesh
    nodes = np.unique([n for n, _ in sensors])
    if _nearest_nodes(calc["MODELE"]):
        placement = _paired(ctx, mesu, calc_mesh, mesu_mesh, nodes)
    else:
        placement = _collocated(ctx, calc, mesu, calc_mesh, mesu_mesh, nodes)
    for occ in kw.factor("CORR_MANU"):
        measured_node = _one_node(ctx, occ, "NOEU_MESURE", mesu_mesh)
        placement.nodes[measured_node] = (
            np.array([_one_node(ctx, occ, "NOEU_CALCUL", calc_mesh)]),
            np.ones(1),
        )
    if name in _GAUGES:
        return _gauges_seen(ctx, calc, basis, placement, sensors, name)
    targets = [(n, c) for n, _ in sensors for c in _TRANSLATIONS]
    seen, _ = fp.project_values(
        placement, basis.numbering.index, basis.shapes.T, targets, default=np.nan
    )
    seen = seen.T.reshape(len(sensors), 3, basis.n_modes)
    out = np.zeros((len(sensors), basis.n_modes))
    for k, (node, direction) in enumerate(sensors):
        used = direction != 0.0
        if np.isnan(seen[k, used]).any():
            name = mesu_mesh.node_names[node]
            ctx.error(f"the basis has no translation at the sensor of node {name}", "BASE", calc)
        out[k] = direction[used] @ seen[k, used]
    return out


def _one_node(ctx, occ, keyword, mesh) -> int:
    node = mesh.find_node(str(occ[keyword]))
    if node is None:
        ctx.error(f"no node {occ[keyword]} in the mesh", keyword, occ)
    return int(node)


def _gauges_seen(ctx, calc, basis, placement, sensors, name) -> np.ndarray:
    """Each gauge's component of the basis' nodal stresses (SIGM_NOEU) or
    strains (EPSI_NOEU, CALC_CHAMP on the basis), at its placed nodes."""
    field_name, _ = _GAUGES[name]
    field = (getattr(basis, "node_fields", None) or {}).get(field_name)
    if field is None:
        ctx.error(f"the basis has no {field_name} field (CALC_CHAMP)", "BASE", calc)
    if field.values.shape[0] != basis.n_modes:
        ctx.error(f"the basis' {field_name} is not computed for every mode", "BASE", calc)
    rows = {int(n): k for k, n in enumerate(field.nodes)}
    out = np.zeros((len(sensors), basis.n_modes))
    for k, (node, component) in enumerate(sensors):
        calc_nodes, weights = placement.nodes[int(node)]
        if component not in field.components or any(int(n) not in rows for n in calc_nodes):
            calc_name = basis.numbering.mesh.node_names[int(calc_nodes[0])]
            ctx.error(
                f"the basis' {field_name} has no {component} at node {calc_name}", "BASE", calc
            )
        column = field.components.index(component)
        out[k] = sum(
            w * np.real(field.values[:, rows[int(n)], column])
            for n, w in zip(calc_nodes, weights, strict=True)
        )
    return out


def _nearest_nodes(model) -> bool:
    """code_aster pairs each measurement node with the nearest calculation node
    when the calculation model has structural elements (discrete elements,
    bars, pipes...) but neither beams (placed on their segments) nor plates
    or shells (op0193's mpjeft); otherwise the nodes are placed in its cells."""
    kinds = set(model.cell_modelisation.values()) | set(model.node_modelisation.values())
    beams = any(k.startswith("POU") for k in kinds)
    plates = any(k.startswith(_PLATES) for k in kinds)
    structural = any(k.startswith(_STRUCTURAL) for k in kinds)
    return structural and not beams and not plates


def _paired(ctx, mesu, calc_mesh, mesu_mesh, nodes) -> fp.Placement:
    coords = calc_mesh.coords
    placed = {}
    for node in nodes:
        distance = np.linalg.norm(coords - mesu_mesh.coords[node], axis=1)
        placed[int(node)] = (np.array([int(np.argmin(distance))]), np.ones(1))
    images = [int(v[0][0]) for v in placed.values()]
    if len(set(images)) != len(images):
        ctx.error("two measurement nodes have the same nearest calculation node", "MODELE", mesu)
    ctx.log("PROJ_MESU_MODAL: each measurement node takes its nearest calculation node")
    return fp.Placement(placed, [], 0.0)


def _collocated(ctx, calc, mesu, calc_mesh, mesu_mesh, nodes) -> fp.Placement:
    cells = fp.source_cells(calc_mesh, _model_cells(calc["MODELE"]))
    try:
        placement = fp.place_nodes(calc_mesh, cells, mesu_mesh, nodes)
    except fp.ProjectionUnsupported as exc:
        ctx.unsupported(f"PROJ_MESU_MODAL: {exc}", "MODELE", calc)
    if placement.unplaced:
        name = mesu_mesh.node_names[placement.unplaced[0]]
        ctx.error(
            f"the measurement node {name} lies in no cell of the calculation model", "MODELE", mesu
        )
    if placement.farthest > 0.0:
        ctx.log(
            f"PROJ_MESU_MODAL: measurement nodes up to {placement.farthest:g} "
            "from the calculation cells (nearest cell taken)"
        )
    return placement


def _model_cells(model):
    return np.asarray(sorted(model.cell_modelisation), dtype=int)


def _resolution(ctx, kw, n_modes, abscissas) -> mp.Resolution:
    occurrences = kw.factor("RESOLUTION")
    if not occurrences:
        return mp.Resolution()
    occ = occurrences[0]
    method, regul = occ["METHODE"], occ["REGUL"]
    eps = float(occ.get("EPS") or 0.0) if method == "SVD" else 0.0
    weights = None
    if regul != "NON":
        if occ.get("COEF_PONDER") is not None:
            weights = _constant_weights(ctx, occ, n_modes)
        elif occ.get("COEF_PONDER_F") is not None:
            weights = _function_weights(ctx, occ, n_modes, abscissas)
    return mp.Resolution(method=method, eps=eps, regul=regul, weights=weights)


def _constant_weights(ctx, occ, n_modes) -> np.ndarray:
    given = [float(v) for v in np.atleast_1d(occ["COEF_PONDER"])]
    if len(given) > n_modes:
        ctx.error(f"{len(given)} weights for {n_modes} modes", "COEF_PONDER", occ)
    # fewer weights than modes: the last one stands for the others
    return np.array(given + [given[-1]] * (n_modes - len(given)))


def _function_weights(ctx, occ, n_modes, abscissas) -> np.ndarray:
    """(n_states, n_modes) weights: one function per mode (the last one for
    the modes after it), tabulated on the measured abscissas."""
    functions = list(np.atleast_1d(occ["COEF_PONDER_F"]))
    if len(functions) > n_modes:
        ctx.error(f"{len(functions)} functions for {n_modes} modes", "COEF_PONDER_F", occ)
    functions += [functions[-1]] * (n_modes - len(functions))
    steps = np.diff(abscissas)
    steps = np.concatenate([steps[:1], steps]) if steps.size else np.ones(1)
    out = np.zeros((abscissas.size, n_modes))
    for k, function in enumerate(functions):
        x = np.asarray(getattr(function, "abscissas", []), dtype=float)
        if x.size != abscissas.size or np.any(np.abs(x - abscissas) > np.abs(steps) * 1e-4):
            ctx.error(
                "each COEF_PONDER_F function must be tabulated on the measured abscissas",
                "COEF_PONDER_F",
                occ,
            )
        out[:, k] = np.asarray(function.ordinates, dtype=float)
    return out


def _transient(basis, times, eta, name) -> TranGene:
    if name not in ("VITE", "ACCE"):  # displacements, or gauges
        depl = eta
        vite, acce = mp.time_derivatives(depl, times)
    elif name == "VITE":
        vite = eta
        acce, _ = mp.time_derivatives(vite, times)
        depl = mp.time_integral(vite, times)
    else:
        acce = eta
        vite = mp.time_integral(acce, times)
        depl = mp.time_integral(vite, times)
    return TranGene(
        basis=basis,
        times=times.copy(),
        order=np.arange(times.size),
        depl=depl,
        vite=vite,
        acce=acce,
        step=float((times[-1] - times[0]) / times.size),
    )


def _harmonic(basis, frequencies, eta, name) -> HarmGene:
    iw = (2j * np.pi * frequencies)[:, None]
    eta = eta.astype(complex)
    if name == "VITE":
        depl = np.divide(eta, iw, out=np.zeros_like(eta), where=iw != 0)
    elif name != "ACCE":
        depl = eta
    else:
        depl = np.divide(eta, iw**2, out=np.zeros_like(eta), where=iw != 0)
    return HarmGene(
        basis=basis,
        numbering=GeneralizedNumbering(basis=basis),
        frequencies=frequencies.copy(),
        order=np.arange(1, frequencies.size + 1),
        fields={"DEPL": depl, "VITE": iw * depl, "ACCE": iw**2 * depl},
    )


def _modes(ctx, kw, basis, measured, eta) -> GeneralizedModes:
    """One generalized mode per measured mode: FREQ kept, NOM_PARA copied."""
    n = eta.shape[0]
    parameters = {"NUME_MODE": np.arange(1, n + 1)}
    for name in np.atleast_1d(kw.get("NOM_PARA") or ()):
        value = _measured_parameter(measured, str(name))
        if value is None:
            ctx.error(f"the measured modes have no parameter {name}", "NOM_PARA", kw)
        parameters[str(name)] = value
    unknown = np.full(n, np.nan)  # code_aster leaves them unset
    return GeneralizedModes(
        numbering=GeneralizedNumbering(basis=basis),
        vectors=eta.T.copy(),
        frequencies=np.asarray(measured.frequencies, dtype=float).copy(),
        generalized_mass=parameters.get("MASS_GENE", unknown),
        generalized_stiffness=parameters.get("RIGI_GENE", unknown),
        parameters=parameters,
        norm=measured.norm,
    )


def _measured_parameter(measured, name):
    if name in measured.parameters:
        return np.asarray(measured.parameters[name]).copy()
    direct = {
        "FREQ": measured.frequencies,
        "MASS_GENE": measured.generalized_mass,
        "RIGI_GENE": measured.generalized_stiffness,
    }
    return None if name not in direct else np.asarray(direct[name], dtype=float).copy()
