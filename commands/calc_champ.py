"""CALC_CHAMP: beam internal forces and stresses of a result (EFGE_ELNO,
SIEF_ELNO, SIPO_ELNO, EFGE_ELGA, SIEF_ELGA and the _NOEU smoothing), the
stresses, strains and energies of 3D and plane solids (SIEF_ELGA, SIGM_ELNO,
EPSI_ELGA/ELNO, ENEL_ELGA/ELNO, EPOT_ELEM, ECIN_ELEM, _NOEU;
:mod:`asterlite.fem.solid_fields`), user fields (CHAM_UTIL) and the nodal
forces FORC_NODA / REAC_NODA of a dyna_trans or a dyna_harmo
(:mod:`asterlite.post.nodal_forces`, stored in ``result.fields``).

The fields are computed at every order of the result from its DEPL field
(mode shapes for a mode_meca), plus the element inertia forces M_e a_e from
the ACCE field of a dyna_trans (code_aster's beam elements take the result's
acceleration for transient results), and stored on the result as
``result.element_fields[NAME]`` (:class:`~asterlite.concepts.assembly.ElementField`)
and ``result.node_fields[NAME]`` (:class:`~asterlite.concepts.assembly.NodalComponentField`).
MODELE / CARA_ELEM / CHAM_MATER default to those the result's DOF numbering
was built with (as code_aster takes them from the result).
"""

from __future__ import annotations

import copy

import numpy as np
from asterlite.commands.dyna_vibra_harm import harmonic_load

from asterlite.concepts.assembly import ElementField
from asterlite.fem.assemble import assemble_terms
from asterlite.fem.beam_elements import section_forces
from asterlite.fem.element_fields import (
    BAR_OPTIONS,
    ELGA_OPTIONS,
    ELNO_OPTIONS,
    NOEU_OPTIONS,
    bar_element_fields,
    beam_element_fields,
    discrete_element_fields,
    nodal_average,
)
from asterlite.fem.elements import ElementError
from asterlite.fem.fibre_fields import multifibre_stresses
from asterlite.fem.loads import beam_element_loads, load_terms
from asterlite.fem.pipe_elements import PIPE_MODELISATIONS, pipe_element_fields
from asterlite.fem.plate_elements import PLATE_MODELISATIONS
from asterlite.fem.plate_fields import plate_element_fields
from asterlite.fem.selection import as_tuple, select_cells
from asterlite.fem.solid_fields import SOLID_FIELDS, solid_cells_of, solid_element_fields
from asterlite.harmonic.loads import load_matrix
from asterlite.post.nodal_forces import (
    FORCE_OPTIONS,
    NodalForceError,
    load_forces,
    nodal_forces,
)
from asterlite.post.restitution import selection_from_keywords

_BEAMS = ("POU_D_E", "POU_D_T", "POU_D_TG")
#: what CALC_CHAMP computes on multifibre beams (POU_D_EM)
_MULTIFIBRE_OPTIONS = ("SIEF_ELGA", "EFGE_ELNO", "EFGE_NOEU")
_BARS = ("BARRE", "2D_BARRE")
_PIPES = PIPE_MODELISATIONS


_DISCRETE = ("DIS_T", "DIS_TR", "2D_DIS_T", "2D_DIS_TR")
_ACCESS = ("NUME_ORDRE", "LIST_ORDRE", "INST", "LIST_INST", "FREQ", "LIST_FREQ")


def _keep_selected_orders(ctx, kw, result, fields) -> None:
    """Fields exist at the orders NUME_ORDRE / INST / FREQ... choose (every
    order by default): the others are NaN, as code_aster stores no field there,
    unless an earlier CALC_CHAMP on the result computed them (they are kept)."""
    if all(kw.peek(k) is None for k in _ACCESS):
        # every order, the default; CRITERE / PRECISION only tune an INST or FREQ search
        kw.mark_used("TOUT_ORDRE", "CRITERE", "PRECISION")
        return
    if hasattr(result, "frequencies"):  # a dyna_harmo
        from asterlite.post.harmonic import selection_from_keywords

        rows = selection_from_keywords(ctx, kw, result.frequencies, result.order).lower
    else:
        rows = _selected_orders(ctx, kw, result)
    for name, field in fields.items():
        dropped = np.ones(field.values.shape[0], dtype=bool)
        dropped[rows] = False
        field.values[dropped] = np.nan
        # orders computed by an earlier call on the same result keep their values
        earlier = getattr(result, "element_fields", {}).get(name)
        if (
            earlier is not None
            and earlier.values.shape == field.values.shape
            and np.array_equal(np.asarray(earlier.cells), np.asarray(field.cells))
        ):
            field.values[dropped] = earlier.values[dropped]


def _discrete_fields(ctx, kw, result, model, characteristics, cells, names) -> None:
    """EFGE_ELNO / SIEF_ELNO of a model of discrete elements (code_aster's
    ef0042: the stiffness forces in the element frame, real or complex)."""

    other = [n for n in names if n not in BAR_OPTIONS]
    if other:
        ctx.unsupported(f"CALC_CHAMP {other[0]} of discrete elements", "CONTRAINTE", kw)
    if kw.factor("CHAM_UTIL"):
        ctx.unsupported("CHAM_UTIL on a model of discrete elements", "CHAM_UTIL", kw)
    values = _nodal_values(ctx, result, kw)
    try:
        fields = discrete_element_fields(
            model, characteristics, result.numbering, cells, values, names
        )
    except (ElementError, ValueError, KeyError) as exc:
        ctx.error(str(exc), "CONTRAINTE", kw)
    _keep_selected_orders(ctx, kw, result, fields)
    result.element_fields.update(fields)
    ctx.log(
        f"CALC_CHAMP {', '.join(names)} on {cells.size} discrete cells, {values.shape[0]} orders"
    )


def _bar_fields(ctx, kw, result, model, characteristics, materials, bars, names) -> None:
    """EFGE_ELNO / SIEF_ELNO (N) of a model of bars (code_aster's te0185:
    from the displacements, real or complex)."""

    other = [n for n in names if n not in BAR_OPTIONS]
    if other:
        keyword = "CONTRAINTE" if other[0] in as_tuple(kw.get("CONTRAINTE")) else None
        ctx.unsupported(f"CALC_CHAMP {other[0]} of bars (EFGE_ELNO, SIEF_ELNO)", keyword, kw)
    if kw.factor("CHAM_UTIL"):
        ctx.unsupported("CHAM_UTIL on a model of bars", "CHAM_UTIL", kw)
    values = _nodal_values(ctx, result, kw)
    try:
        fields = bar_element_fields(
            model, characteristics, materials, result.numbering, bars, values, names
        )
    except (ElementError, ValueError, KeyError) as exc:
        ctx.error(str(exc), "CONTRAINTE", kw)
    _keep_selected_orders(ctx, kw, result, fields)
    result.element_fields.update(fields)
    ctx.log(f"CALC_CHAMP {', '.join(names)} on {bars.size} bar cells, {values.shape[0]} orders")


def _multifibre_fields(ctx, kw, result, model, characteristics, materials, cells) -> None:
    """SIEF_ELGA (fibre stresses SIXX) of POU_D_EM cells; a model where they
    are mixed with other element families is refused."""
    mixed = sorted({m for c, m in model.cell_modelisation.items() if m != "POU_D_EM"})
    if mixed:
        ctx.unsupported(
            f"CALC_CHAMP on POU_D_EM cells mixed with {', '.join(mixed)} cells", "CONTRAINTE", kw
        )
    values = _nodal_values(ctx, result, kw)
    try:
        field = multifibre_stresses(
            model, characteristics, materials, result.numbering, cells, values
        )
    except (ElementError, ValueError, KeyError) as exc:
        ctx.error(str(exc), "CONTRAINTE", kw)
    fields = {"SIEF_ELGA": field}
    _keep_selected_orders(ctx, kw, result, fields)
    result.element_fields.update(fields)
    ctx.log(
        f"CALC_CHAMP SIEF_ELGA on {cells.size} multifibre cells "
        f"({field.sub_points} fibres at most), {values.shape[0]} orders"
    )


def _refuse_other_options(ctx, kw, names, known, message: str) -> None:
    """Refuse by name the first requested option not in ``known``
    (``message`` formats it), located at the keyword that asked for it."""
    other = [n for n in names if n not in known]
    if other:
        keyword = next(
            (
                k
                for k in ("CONTRAINTE", "DEFORMATION", "ENERGIE")
                if other[0] in as_tuple(kw.get(k))
            ),
            None,
        )
        ctx.unsupported(message.format(other[0]), keyword, kw)


def _store_fields(ctx, kw, result, model, fields, names) -> None:
    """Store element ``fields`` at the selected orders, and the nodal
    averages of their ELNO fields for the _NOEU ``names``."""
    _keep_selected_orders(ctx, kw, result, fields)
    result.element_fields.update(fields)
    for name in names:
        if name.endswith("_NOEU"):
            source = result.element_fields[name.replace("_NOEU", "_ELNO")]
            result.node_fields[name] = nodal_average(source, model.mesh, name)


def _pipe_fields(ctx, kw, result, model, characteristics, materials, pipes, names) -> None:
    """EFGE_ELNO (and EFGE_NOEU) of a model of pipes (code_aster's te0185:
    from the displacements' stresses, real or complex; no inertia)."""

    _refuse_other_options(
        ctx, kw, names, ("EFGE_ELNO", "EFGE_NOEU"), "CALC_CHAMP {} of pipe elements (EFGE_ELNO)"
    )
    if kw.factor("CHAM_UTIL"):
        ctx.unsupported("CHAM_UTIL on a model of pipes", "CHAM_UTIL", kw)
    if kw.factor("EXCIT"):
        ctx.unsupported("CALC_CHAMP EXCIT on pipe elements", "EXCIT", kw)
    values = _nodal_values(ctx, result, kw)
    try:
        fields = pipe_element_fields(
            model, characteristics, materials, result.numbering, pipes, values, ["EFGE_ELNO"]
        )
    except (ElementError, ValueError, KeyError) as exc:
        ctx.error(str(exc), "CONTRAINTE", kw)
    _store_fields(ctx, kw, result, model, fields, names)
    ctx.log(f"CALC_CHAMP {', '.join(names)} on {pipes.size} pipe cells, {values.shape[0]} orders")


def _plate_fields(ctx, kw, result, model, characteristics, materials, plates, names) -> None:
    """EFGE_ELNO (and EFGE_NOEU), EFGE_ELGA, SIEF_ELGA and SIGM_ELNO of DKT plates
    (code_aster's ef0033 / te0033: from the displacements, real or complex;
    no inertia)."""

    known = ("EFGE_ELNO", "EFGE_NOEU", "EFGE_ELGA", "SIEF_ELGA", "SIGM_ELNO")
    _refuse_other_options(
        ctx, kw, names, known, f"CALC_CHAMP {{}} of DKT plates ({', '.join(known)})"
    )
    if kw.factor("CHAM_UTIL"):
        ctx.unsupported("CHAM_UTIL on a model of DKT plates", "CHAM_UTIL", kw)
    if kw.factor("EXCIT"):
        ctx.unsupported("CALC_CHAMP EXCIT on DKT plates", "EXCIT", kw)
    values = _nodal_values(ctx, result, kw)
    try:
        computed = sorted({n.replace("EFGE_NOEU", "EFGE_ELNO") for n in names})
        fields = plate_element_fields(
            model, characteristics, materials, result.numbering, plates, values, computed
        )
    except (ElementError, ValueError, KeyError) as exc:
        ctx.error(str(exc), "CONTRAINTE", kw)
    _store_fields(ctx, kw, result, model, fields, names)
    ctx.log(f"CALC_CHAMP {', '.join(names)} on {plates.size} DKT cells, {values.shape[0]} orders")


def _solid_fields(ctx, kw, result, model, materials, solids, names) -> None:
    """Stresses, strains and energies of 3D and plane solid cells
    (:mod:`asterlite.fem.solid_fields`), their nodal averages for _NOEU."""

    _refuse_other_options(ctx, kw, names, SOLID_FIELDS, "CALC_CHAMP {} of solid elements")
    # the loads asterlite builds hold no initial strain or stress (EPSI_INIT,
    # SIGM_INTERNE are refused by AFFE_CHAR_MECA): the elastic stresses,
    # strains and energies of solids then depend on the displacements only
    kw.mark_used("EXCIT")
    for occ in kw.factor("EXCIT"):
        occ.mark_used(*(k for k, v in dict.items(occ) if v is not None))
    values = _nodal_values(ctx, result, kw)
    velocities = omega2 = None
    if "ECIN_ELEM" in names:
        fields = getattr(result, "fields", None)
        if isinstance(fields, dict) and fields.get("VITE") is not None:
            velocities = np.asarray(fields["VITE"])
        elif getattr(result, "frequencies", None) is not None and hasattr(result, "shapes"):
            omega2 = (2.0 * np.pi * np.asarray(result.frequencies, dtype=float)) ** 2
        else:
            ctx.error("ECIN_ELEM needs the VITE field of the result", "ENERGIE", kw)
    element_names = sorted({n.replace("_NOEU", "_ELNO") for n in names})
    try:
        fields = solid_element_fields(
            model, materials, result.numbering, solids, values, element_names, velocities, omega2
        )
    except (ElementError, ValueError, KeyError) as exc:
        ctx.error(str(exc), "CONTRAINTE", kw)
    _store_fields(ctx, kw, result, model, fields, names)
    ctx.log(f"CALC_CHAMP {', '.join(names)} on {solids.size} solid cells, {values.shape[0]} orders")


def _nodal_values(ctx, result, kw) -> np.ndarray:
    """(n_orders, n_dofs) displacements of the result."""
    fields = getattr(result, "fields", None)
    if isinstance(fields, dict) and "DEPL" in fields:
        depl = np.asarray(fields["DEPL"])
        return depl if np.iscomplexobj(depl) else depl.astype(float)  # dyna_harmo: complex
    shapes = getattr(result, "shapes", None)
    if shapes is not None:
        return np.asarray(shapes, dtype=float).T
    ctx.error(f"the result {result.name or ''} has no DEPL field", "RESULTAT", kw)


def _accelerations(ctx, result, values: np.ndarray) -> np.ndarray | None:
    """(n_orders, n_dofs) ACCE of a dyna_trans or a dyna_harmo (their beam
    forces include the inertia M_e a_e, as code_aster's); None for static and
    modal results. A result without ACCE gets zero accelerations, as in
    code_aster."""
    kind = next(
        (t for t in ("dyna_trans", "dyna_harmo") if t in getattr(result, "aster_types", ())), None
    )
    if kind is None:
        return None
    acce = result.fields.get("ACCE")
    if acce is None:
        ctx.log(f"CALC_CHAMP: the {kind} has no ACCE field, inertia forces taken as 0")
        return None
    acce = np.asarray(acce)
    acce = acce if np.iscomplexobj(acce) else acce.astype(float)
    if acce.shape != values.shape:
        ctx.error(f"ACCE has shape {acce.shape}, DEPL {values.shape}", "RESULTAT", None)
    return acce


def _excitation_forces(ctx, kw, result, model, characteristics, beams, n_orders):
    """(n_orders, n_beams, 2, 6) the distributed loads of EXCIT on the beams,
    times FONC_MULT at each instant of the result (or COEF_MULT), in the
    convention of the internal forces; None without EXCIT."""

    occurrences = kw.factor("EXCIT")
    if not occurrences and "evol_elas" in getattr(result, "aster_types", ()):
        return _static_result_loads(ctx, kw, result, model, characteristics, beams, n_orders)
    if not occurrences:
        return None
    times = getattr(result, "times", None)
    total = np.zeros((n_orders, len(beams), 2, 6))
    for occ in occurrences:
        for key in ("FONC_MULT_C", "COEF_MULT_C", "TYPE_CHARGE", "PHAS_DEG", "PUIS_PULS"):
            if key == "TYPE_CHARGE" and occ.get(key, "FIXE_CSTE") == "FIXE_CSTE":
                continue
            if key in ("PHAS_DEG", "PUIS_PULS") and not occ.get(key):
                continue
            if occ.get(key) is not None:
                ctx.unsupported(f"CALC_CHAMP EXCIT {key} on beams", key, occ)
        function = occ.get("FONC_MULT")
        if function is not None:
            if times is None or len(times) != n_orders:
                ctx.unsupported(
                    "CALC_CHAMP EXCIT FONC_MULT on a result without instants", "FONC_MULT", occ
                )
            coefficients = np.array([float(function(float(t))) for t in times])
        else:
            coefficients = np.full(n_orders, float(occ.get("COEF_MULT", 1.0)))
        try:
            local = beam_element_loads(model, characteristics, beams, occ["CHARGE"])
        except ElementError as exc:
            ctx.unsupported(str(exc), "CHARGE", occ)
        total += coefficients[:, None, None, None] * section_forces(local)[None]
    return total


def _static_result_loads(ctx, kw, result, model, characteristics, beams, n_orders):
    """Without EXCIT, code_aster takes the loads of a MECA_STATIQUE result off
    the beams' internal forces: its FORCE_POUTRE loads here (None if none)."""
    total = None
    for load, mult in getattr(result, "loads", ()):
        if not load.extra.get("FORCE_POUTRE"):
            continue
        if callable(mult):
            coefficients = np.array([float(mult(float(t))) for t in result.times])
        else:
            coefficients = np.full(n_orders, float(mult))
        try:
            local = beam_element_loads(model, characteristics, beams, load)
        except ElementError as exc:
            ctx.unsupported(f"{exc} (the loads of the static result)", "RESULTAT", kw)
        term = coefficients[:, None, None, None] * section_forces(local)[None]
        total = term if total is None else total + term
    return total


def _beam_fields(model, characteristics, materials, numbering, beams, values, elno, acce, loads):
    """beam_element_fields; complex states (a dyna_harmo) give complex fields,
    computed from their real and imaginary parts (the fields are linear in
    the displacements and accelerations)."""
    if not np.iscomplexobj(values) and not np.iscomplexobj(acce):
        return beam_element_fields(
            model,
            characteristics,
            materials,
            numbering,
            beams,
            values,
            elno,
            accelerations=acce,
            load_forces=loads,
        )
    if loads is not None:
        raise ValueError("CALC_CHAMP EXCIT on a complex (harmonic) result")
    parts = [
        beam_element_fields(
            model,
            characteristics,
            materials,
            numbering,
            beams,
            np.ascontiguousarray(part(values)),
            elno,
            accelerations=None if acce is None else np.ascontiguousarray(part(acce)),
        )
        for part in (np.real, np.imag)
    ]
    return {
        name: ElementField(
            field.name, field.cells, field.components, field.values + 1j * parts[1][name].values
        )
        for name, field in parts[0].items()
    }


def _context(ctx, kw, result):
    numbering = result.numbering
    model = kw.get("MODELE") or getattr(result, "model", None) or numbering.model
    characteristics = (
        kw.get("CARA_ELEM")
        or getattr(result, "characteristics", None)
        or getattr(numbering, "characteristics", None)
    )
    materials = (
        kw.get("CHAM_MATER")
        or getattr(result, "materials", None)
        or getattr(numbering, "materials", None)
    )
    if model is None:
        ctx.error("give MODELE: the result does not know its model", "MODELE", kw)
    if model.mesh is not numbering.mesh:
        ctx.error("MODELE is built on another mesh than the result", "MODELE", kw)
    return model, characteristics, materials


_ORDER_KEYWORDS = ("NUME_ORDRE", "LIST_ORDRE", "INST", "LIST_INST")


def _selected_orders(ctx, kw, result) -> np.ndarray | None:
    """Row indices of the orders named by NUME_ORDRE / INST... of a transient
    result, None for all of them."""
    times, order = getattr(result, "times", None), getattr(result, "order", None)
    if times is None or order is None or all(kw.get(k) is None for k in _ORDER_KEYWORDS):
        return None
    return selection_from_keywords(ctx, kw, times, order).lower


def _evaluate(formula, columns: list[np.ndarray]) -> np.ndarray:
    """A deck formula on arrays, point by point when it does not take arrays."""
    try:
        return np.broadcast_to(formula.evaluate(*columns), columns[0].shape)
    except Exception:  # noqa: BLE001 - deck functions may not take arrays
        flat = [c.ravel() for c in columns]
        return np.array(
            [formula(*(float(c[i]) for c in flat)) for i in range(flat[0].size)]
        ).reshape(columns[0].shape)


def _cham_util(ctx, result, occ, rows=None, cells=None) -> None:
    """UTnn_ELNO from a formula of an ELNO field's components; with ``rows``
    (selected orders) the other orders are NaN (code_aster has no field there);
    with ``cells`` (GROUP_MA of the call) the field lives on those cells only."""
    source = occ["NOM_CHAM"]
    field = result.element_fields.get(source)
    if field is None:
        ctx.error(f"{source} must be computed first (CONTRAINTE)", "NOM_CHAM", occ)
    if occ.get("FORMULE") is None:
        ctx.unsupported("CHAM_UTIL CRITERE / NORME", "CRITERE", occ)
    formulas = as_tuple(occ["FORMULE"])
    on_cells = np.ones(len(field.cells), dtype=bool)
    if cells is not None:
        on_cells = np.isin(np.asarray(field.cells), np.asarray(cells))
        if not on_cells.any():
            ctx.error(f"{source} is on none of the cells of GROUP_MA", "NOM_CHAM", occ)
    source_values = (field.values if rows is None else field.values[rows])[:, on_cells]
    n_orders, _, n_points = field.values.shape[:3]
    values = np.full((n_orders, int(on_cells.sum()), n_points, len(formulas)), np.nan)
    for k, formula in enumerate(formulas):
        params = formula.nom_para
        missing = [p for p in params if p not in field.components]
        if missing:
            ctx.error(f"{source} has no component {', '.join(missing)}", "FORMULE", occ)
        columns = [source_values[..., field.components.index(p)] for p in params]
        target = slice(None) if rows is None else rows
        # real fields: the real part of a VALE_C formula
        values[target, ..., k] = np.real(_evaluate(formula, columns))
    name = f"UT{int(occ['NUME_CHAM_RESU']):02d}_" + source.split("_")[-1]
    components = tuple(f"X{k + 1}" for k in range(len(formulas)))
    kept = np.asarray(field.cells)[on_cells]
    result.element_fields[name] = ElementField(name, kept, components, values)
    ctx.log(f"CALC_CHAMP {name}: {len(formulas)} components on {len(kept)} cells")


def run(ctx, kw):
    source = kw["RESULTAT"]
    if ctx.reuse is not None:
        result = source
    else:
        # a new result holding the source's fields and the new ones
        result = copy.copy(source)
        result.name = None
    result.element_fields = dict(getattr(source, "element_fields", {}) or {})
    result.node_fields = dict(getattr(source, "node_fields", {}) or {})
    requested = []
    for keyword in ("CONTRAINTE", "DEFORMATION", "ENERGIE", "CRITERES", "VARI_INTERNE"):
        requested.extend((keyword, name) for name in as_tuple(kw.get(keyword)))
    if kw.get("PROPRIETES"):
        ctx.unsupported(f"CALC_CHAMP PROPRIETES={as_tuple(kw['PROPRIETES'])}", "PROPRIETES", kw)
    if kw.get("FORCE"):
        _force_fields(ctx, kw, result)
    names = [name for _, name in requested]
    known = ELNO_OPTIONS + ELGA_OPTIONS + NOEU_OPTIONS + SOLID_FIELDS
    other = [n for n in names if n not in known]
    if other:
        keyword = next(k for k, n in requested if n == other[0])
        ctx.unsupported(f"CALC_CHAMP {keyword}={other[0]!r}", keyword, kw)
    if names:
        model, characteristics, materials = _context(ctx, kw, result)
        # TOUT='OUI' (its only value) is every cell of the model, as without GROUP_MA
        kw.mark_used("TOUT")
        cells = select_cells(ctx, kw, model.mesh) if kw.get("GROUP_MA") else None
        candidates = sorted(model.cell_modelisation) if cells is None else cells
        beams = np.array(
            [c for c in candidates if model.cell_modelisation.get(int(c)) in _BEAMS], dtype=int
        )
        bars = np.array(
            [c for c in candidates if model.cell_modelisation.get(int(c)) in _BARS], dtype=int
        )
        multifibre = np.array(
            [c for c in candidates if model.cell_modelisation.get(int(c)) == "POU_D_EM"],
            dtype=int,
        )
        if multifibre.size:
            other = [n for n in names if n not in _MULTIFIBRE_OPTIONS]
            if other:
                keyword = next(k for k, n in requested if n == other[0])
                ctx.unsupported(
                    f"CALC_CHAMP {other[0]} of multifibre beams ({', '.join(_MULTIFIBRE_OPTIONS)})",
                    keyword,
                    kw,
                )
            if "SIEF_ELGA" in names:
                _multifibre_fields(ctx, kw, result, model, characteristics, materials, multifibre)
            names = [n for n in names if n != "SIEF_ELGA"]
            if not names:
                return _cham_utils(ctx, kw, result)
            # their generalised forces: K u (+ M a) of the fibre-integrated element
            beams = np.union1d(beams, multifibre).astype(int)
        solids = solid_cells_of(model, candidates)
        pipes = np.array(
            [c for c in candidates if model.cell_modelisation.get(int(c)) in _PIPES], dtype=int
        )
        on_plates = [
            c for c in candidates if model.cell_modelisation.get(int(c)) in PLATE_MODELISATIONS
        ]
        # the edges (SEG2) a DKT modelisation also covers carry no plate field
        plates = np.array(
            [c for c in on_plates if model.mesh.cell_types[int(c)] in ("TRIA3", "QUAD4")],
            dtype=int,
        )
        if plates.size:
            if len(on_plates) != len(candidates):
                ctx.unsupported(
                    "CALC_CHAMP on DKT plates and other elements at once", "GROUP_MA", kw
                )
            _plate_fields(ctx, kw, result, model, characteristics, materials, plates, names)
            return result
        if pipes.size:
            if pipes.size != len(candidates):
                ctx.unsupported(
                    "CALC_CHAMP on pipe elements and other elements at once", "GROUP_MA", kw
                )
            _pipe_fields(ctx, kw, result, model, characteristics, materials, pipes, names)
            return result
        if solids.size and not beams.size and not bars.size:
            _solid_fields(ctx, kw, result, model, materials, solids, names)
            return _cham_utils(ctx, kw, result)
        if bars.size and not beams.size:
            _bar_fields(ctx, kw, result, model, characteristics, materials, bars, names)
            return result
        discrete = np.array(
            [c for c in candidates if model.cell_modelisation.get(int(c)) in _DISCRETE], dtype=int
        )
        if discrete.size and not beams.size:
            _discrete_fields(ctx, kw, result, model, characteristics, discrete, names)
            return result
        if not beams.size:
            ctx.unsupported(
                "CALC_CHAMP on a model without POU_D_E / POU_D_T / POU_D_TG cells", None, kw
            )
        if characteristics is None:
            ctx.error("beam fields need CARA_ELEM", "CARA_ELEM", kw)
        elno = sorted({n.replace("_NOEU", "_ELNO") for n in names})
        values = _nodal_values(ctx, result, kw)
        accelerations = _accelerations(ctx, result, values)
        loads = _excitation_forces(ctx, kw, result, model, characteristics, beams, len(values))
        try:
            fields = _beam_fields(
                model,
                characteristics,
                materials,
                result.numbering,
                beams,
                values,
                elno,
                accelerations,
                loads,
            )
        except (ElementError, ValueError, KeyError) as exc:
            ctx.error(str(exc), "CONTRAINTE", kw)
        if discrete.size:
            fields = _with_discrete_cells(
                ctx, kw, model, characteristics, result, discrete, values, fields
            )
        _store_fields(ctx, kw, result, model, fields, names)
        ctx.log(
            f"CALC_CHAMP {', '.join(names)} on {beams.size} beam cells"
            + (f" and {discrete.size} discrete cells" if discrete.size else "")
            + f", {values.shape[0]} orders"
        )
    return _cham_utils(ctx, kw, result)


def _force_fields(ctx, kw, result) -> None:
    """FORCE=FORC_NODA / REAC_NODA of a dyna_trans or a dyna_harmo, stored
    as nodal fields of the result (NaN at the orders not selected, as
    code_aster stores none there)."""
    options = as_tuple(kw["FORCE"])
    other = [name for name in options if name not in FORCE_OPTIONS]
    if other:
        ctx.unsupported(f"CALC_CHAMP FORCE={other[0]!r}", "FORCE", kw)
    kinds = getattr(result, "aster_types", ())
    if "dyna_trans" not in kinds and "dyna_harmo" not in kinds:
        ctx.unsupported(
            f"CALC_CHAMP FORCE on a {getattr(result, 'aster_type', type(result).__name__)} "
            "(asterlite computes it on a dyna_trans or a dyna_harmo)",
            "FORCE",
            kw,
        )
    model, characteristics, materials = _context(ctx, kw, result)
    cells = None
    if kw.get("GROUP_MA"):
        if "REAC_NODA" in options:
            ctx.unsupported(
                "CALC_CHAMP REAC_NODA on a part of the model (GROUP_MA)", "GROUP_MA", kw
            )
        # FORC_NODA of those cells' elements only, as code_aster's restricted ligrel
        cells = select_cells(ctx, kw, model.mesh)
    kw.mark_used("TOUT")
    load_values = None
    if "REAC_NODA" in options:
        if "dyna_harmo" in kinds:
            load_values = _harmonic_load_values(ctx, kw, result, characteristics, materials)
        else:
            load_values = _transient_load_values(ctx, kw, result, characteristics, materials)
    rows = _selected_orders(ctx, kw, result)
    if rows is None:
        kw.mark_used("TOUT_ORDRE")  # every order, the default
    result.fields = dict(result.fields)
    for option in options:
        try:
            values = nodal_forces(
                result, option, model, characteristics, materials, load_values, ctx.log, cells
            )
        except (NodalForceError, ElementError, KeyError) as exc:
            ctx.error(str(exc), "FORCE", kw)
        except NotImplementedError as exc:
            ctx.unsupported(str(exc), "FORCE", kw)
        if rows is not None:
            kept = np.full(values.shape, np.nan, dtype=values.dtype)
            kept[rows] = values[rows]
            previous = result.fields.get(option)
            if previous is not None and previous.shape == values.shape:
                # what an earlier CALC_CHAMP computed at the other orders stays
                kept = np.where(np.isnan(kept), previous, kept)
            values = kept
        result.fields[option] = values
        ctx.log(f"CALC_CHAMP {option}: {values.shape[0]} orders, {values.shape[1]} DOFs")


def _transient_load_values(ctx, kw, result, characteristics, materials):
    """F(t) of REAC_NODA on a dyna_trans: the CALC_CHAMP EXCIT loads, else the
    result's own (each times its FONC_MULT or COEF_MULT)."""
    occurrences = kw.factor("EXCIT")
    loads = result.loads
    if occurrences:
        for occ in occurrences:
            for key in ("FONC_MULT_C", "COEF_MULT_C", "PHAS_DEG", "PUIS_PULS"):
                if occ.get(key):
                    ctx.unsupported(f"CALC_CHAMP EXCIT {key} on a dyna_trans", key, occ)
            if occ.get("TYPE_CHARGE", "FIXE_CSTE") != "FIXE_CSTE":
                ctx.unsupported("CALC_CHAMP EXCIT TYPE_CHARGE with FORCE", "TYPE_CHARGE", occ)
        loads = tuple(
            (occ["CHARGE"], occ.get("FONC_MULT") or float(occ.get("COEF_MULT", 1.0)))
            for occ in occurrences
        )
    try:
        return load_forces(loads, characteristics, materials, result.numbering, result.times)
    except KeyError as exc:
        ctx.error(f"load on DOFs the result's numbering does not have: {exc}", "EXCIT", kw)


def _harmonic_load_values(ctx, kw, result, characteristics, materials):
    """F(f) of REAC_NODA on a dyna_harmo: Σ c(f) F of CALC_CHAMP's EXCIT
    (code_aster reads the harmonic loads from the command's EXCIT)."""

    occurrences = kw.factor("EXCIT")
    if not occurrences:
        ctx.unsupported("REAC_NODA of a dyna_harmo without CALC_CHAMP EXCIT", "FORCE", kw)
    loads = []
    for occ in occurrences:
        if occ.get("TYPE_CHARGE", "FIXE_CSTE") != "FIXE_CSTE":
            ctx.unsupported("CALC_CHAMP EXCIT TYPE_CHARGE with FORCE", "TYPE_CHARGE", occ)
        load = occ["CHARGE"]
        try:
            terms = load_terms(load, characteristics, materials, complex_values=True)
            vector = assemble_terms(terms, result.numbering)
        except KeyError as exc:
            ctx.error(f"load on DOFs the result's numbering does not have: {exc}", "CHARGE", occ)
        loads.append(harmonic_load(ctx, occ, vector, load.name or ""))
    return load_matrix(loads, result.frequencies, result.numbering.n_dofs)


def _with_discrete_cells(ctx, kw, model, characteristics, result, cells, values, fields):
    """The beam fields extended to the discrete cells of the model, as code_aster
    computes EFGE_ELNO / SIEF_ELNO on every cell that has the option: the
    discrete elements' stiffness forces (ef0042), one modelisation at a time."""
    names = [name for name in fields if name in BAR_OPTIONS]
    if not names:
        return fields
    merged = dict(fields)
    by_kind: dict[str, list[int]] = {}
    for cell in cells:
        by_kind.setdefault(model.cell_modelisation[int(cell)], []).append(int(cell))
    for kind, members in sorted(by_kind.items()):
        try:
            extra = discrete_element_fields(
                model, characteristics, result.numbering, members, values, names
            )
        except (ElementError, ValueError, KeyError) as exc:
            ctx.error(str(exc), "CONTRAINTE", kw)
        for name in names:
            field, added = merged[name], extra[name]
            if added.components != field.components:
                ctx.unsupported(
                    f"CALC_CHAMP {name} on beams and {kind} cells at once (components "
                    f"{', '.join(field.components)} and {', '.join(added.components)}): "
                    "give GROUP_MA",
                    "CONTRAINTE",
                    kw,
                )
            merged[name] = ElementField(
                name,
                np.concatenate([np.asarray(field.cells), np.asarray(added.cells)]),
                field.components,
                np.concatenate([field.values, added.values.astype(field.values.dtype)], axis=1),
            )
    return merged


def _cham_utils(ctx, kw, result):
    """The CHAM_UTIL occurrences of the call, then the result."""
    rows = _selected_orders(ctx, kw, result) if kw.factor("CHAM_UTIL") else None
    mesh = result.numbering.mesh if kw.factor("CHAM_UTIL") else None
    restricted = select_cells(ctx, kw, mesh) if mesh is not None and kw.get("GROUP_MA") else None
    for occ in kw.factor("CHAM_UTIL"):
        _cham_util(ctx, result, occ, rows, restricted)
    return result
