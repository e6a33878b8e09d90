"""TEST_RESU: check values of results, generalized results and nodal fields.

RESU (RESULTAT + NOM_CHAM + node + NOM_CMP at NUME_ORDRE / INST, or PARA of a
state, or TYPE_TEST over a field), GENE (RESU_GENE + NUME_CMP_GENE, or
VECT_GENE), CHAM_NO (CHAM_GD + node + NOM_CMP, or TYPE_TEST), CHAM_ELEM
(a cham_elem at a cell node or Gauss point, or TYPE_TEST), CARTE (a
carte's component on the one cell of GROUP_MA). Verdicts:
``asterlite.post.checks``.
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import ElementField, NodalField
from asterlite.concepts.harmonic import DynaHarmo, HarmGene
from asterlite.concepts.mesh import CellConstantField
from asterlite.concepts.modes import (
    FieldOnElements,
    GeneralizedModes,
    GeneralizedVector,
    ModeResult,
    MultElasResult,
)
from asterlite.concepts.transient import DynaTrans, TranGene
from asterlite.errors import missing_name
from asterlite.legacy.v15 import computes
from asterlite.post.checks import record_check, reduce_values
from asterlite.post.harmonic import frequency_indices
from asterlite.post.restitution import (
    as_tuple,
    computed_fields,
    dof_rows,
    element_value_history,
    nearest_archived,
    node_indices,
)


def run(ctx, kw):
    checks = (
        ("RESU", check_result),
        ("GENE", check_gene),
        ("CHAM_NO", check_field),
        ("CHAM_ELEM", check_element_field),
        ("CARTE", check_carte),
        ("OBJET", check_object),
    )
    for key, check in checks:
        for i, occ in enumerate(kw.factor(key), start=1):
            check(ctx, occ, f"{key}[{i}]")
    return None


def _state_index(ctx, occ, times, order) -> tuple[int, str]:
    """Index of the tested state (NUME_ORDRE or INST) and its description."""
    if occ.get("NUME_ORDRE") is not None:
        number = int(occ["NUME_ORDRE"])
        matches = np.flatnonzero(np.asarray(order) == number)
        if matches.size == 0:
            ctx.error(f"NUME_ORDRE {number} is not in the result", "NUME_ORDRE", occ)
        return int(matches[0]), f"ordre {number}"
    if occ.get("INST") is not None:
        t = float(occ["INST"])
        # code_aster searches the instant with the occurrence's own PRECISION and
        # CRITERE (the first ones when pairs are given), keeping the nearest
        precision = as_tuple(occ.get("PRECISION") or 1e-6)[0]
        criterion = as_tuple(occ.get("CRITERE") or "RELATIF")[0]
        try:
            index = nearest_archived(times, [t], float(precision), str(criterion))[0]
            return int(index), f"inst {t:g}"
        except Exception as exc:
            ctx.error(getattr(exc, "message", str(exc)), "INST", occ)
    ctx.error("NUME_ORDRE or INST is required", "NUME_ORDRE", occ)


def _field_value(ctx, occ, numbering, values, label):
    """Value at a node component, or TYPE_TEST over the (component) field."""
    components = as_tuple(occ.get("NOM_CMP"))
    nodes = node_indices(ctx, occ, numbering.mesh)
    type_test = occ.get("TYPE_TEST")
    if type_test is None:
        if nodes is None or not components:
            ctx.error("give a node (GROUP_NO / NOEUD) and NOM_CMP, or TYPE_TEST", None, occ)
        node = int(nodes[0])
        try:
            row = numbering.dof_index(node, components[0])
        except KeyError:
            name = numbering.mesh.node_names[node]
            present = [c for n, c in numbering.dofs if n == node]
            ctx.error(missing_name("DOF", components[0], present, f"node {name}"), "NOM_CMP", occ)
        return values[row], f"{label} {numbering.mesh.node_names[node]} {components[0]}"
    rows = dof_rows(numbering, nodes, components)
    if rows.size == 0:
        ctx.error("no DOF matches for TYPE_TEST", "NOM_CMP", occ)
    return reduce_values(values[rows], type_test), f"{label} {type_test}"


def _check_mult_elas(ctx, occ, where, result) -> None:
    """A DEPL value of one load case, by NOM_CAS or NUME_ORDRE."""
    name = result.name or "?"
    if occ.get("NOM_CAS") is not None:
        case = str(occ["NOM_CAS"])
        if case not in result.case_names:
            ctx.error(f"{name} has no case {case!r}", "NOM_CAS", occ)
        index, state = result.case_names.index(case), f"cas {case}"
    else:
        order = np.arange(1, result.n_cases + 1)
        index, state = _state_index(ctx, occ, order.astype(float), order)
    if occ.get("PARA") is not None:
        ctx.unsupported(f"PARA={occ['PARA']!r} of a mult_elas", "PARA", occ)
    if occ.get("NOM_CHAM") != "DEPL":
        ctx.unsupported(f"NOM_CHAM={occ.get('NOM_CHAM')!r} of a mult_elas", "NOM_CHAM", occ)
    values = np.asarray(result.fields)[:, index]
    value, what = _field_value(ctx, occ, result.numbering, values, f"{name} DEPL")
    record_check(ctx, f"{where} {what} {state}", value, occ)


def check_result(ctx, occ, where):
    result = occ["RESULTAT"]
    name = result.name or "?"
    if isinstance(result, MultElasResult):
        _check_mult_elas(ctx, occ, where, result)
        return
    if isinstance(result, DynaHarmo):
        _check_harmonic(ctx, occ, where, result)
        return
    if isinstance(result, GeneralizedModes) and occ.get("PARA") is None:
        # code_aster tests a mode_gene's vectors through GENE (RESU_GENE)
        ctx.unsupported("TEST_RESU/RESU of a mode_gene's field (use GENE)", "NOM_CHAM", occ)
    if isinstance(result, (ModeResult, GeneralizedModes)):
        times = np.arange(1, result.n_modes + 1, dtype=float)
        order = np.arange(1, result.n_modes + 1)
    elif isinstance(result, DynaTrans):
        times, order = result.times, result.order
    else:
        ctx.unsupported(f"TEST_RESU of a {result.aster_type}", "RESULTAT", occ)
    if isinstance(result, (ModeResult, GeneralizedModes)) and occ.get("NUME_MODE") is not None:
        index, state = _mode_index(ctx, occ, result)
    else:
        index, state = _state_index(ctx, occ, times, order)
    if occ.get("PARA") is not None:
        value = result_parameter(ctx, occ, result, index)
        label = f"{where} {name} {occ['PARA']} {state}"
    else:
        field = occ.get("NOM_CHAM")
        if field not in getattr(result, "fields", {}) and field in computed_fields(result):
            if occ.get("TYPE_TEST") is not None:
                ctx.unsupported(f"TYPE_TEST on {field}", "TYPE_TEST", occ)
            value = element_value_history(ctx, occ, result, field)[index]
            label = f"{where} {name} {field} {cell_point_label(occ)} {state}"
            record_check(ctx, label, value, occ)
            return
        if isinstance(result, ModeResult):
            if field != "DEPL":
                ctx.unsupported(f"NOM_CHAM={field!r} of a mode_meca", "NOM_CHAM", occ)
            values = result.shapes[:, index]
        else:
            if field not in result.fields:
                known = ", ".join(result.fields)
                ctx.error(f"result has no field {field!r} (it has {known})", "NOM_CHAM", occ)
            values = result.fields[field][index]
        value, what = _field_value(ctx, occ, result.numbering, values, f"{name} {field}")
        label = f"{where} {what} {state}"
    record_check(ctx, label, value, occ)


def _mode_index(ctx, occ, result) -> tuple[int, str]:
    """The order whose mode number (the NUME_MODE parameter) is the one asked."""
    number = int(occ["NUME_MODE"])
    matches = np.flatnonzero(np.asarray(result.mode_numbers) == number)
    if matches.size == 0:
        ctx.error(f"the result has no mode number {number}", "NUME_MODE", occ)
    return int(matches[0]), f"mode {number}"


def _frequency_index(ctx, occ, result) -> tuple[int, str]:
    """Index of the tested state of a harmonic result (NUME_ORDRE or FREQ,
    the frequency searched with the occurrence's PRECISION and CRITERE as
    for INST)."""

    if occ.get("FREQ") is None:
        return _state_index(ctx, occ, result.frequencies, result.order)
    f = float(occ["FREQ"])
    precision = float(as_tuple(occ.get("PRECISION") or 1e-6)[0])
    criterion = str(as_tuple(occ.get("CRITERE") or "RELATIF")[0])
    try:
        return int(frequency_indices(result.frequencies, [f], precision, criterion)[0]), (
            f"freq {f:g}"
        )
    except Exception as exc:
        ctx.error(getattr(exc, "message", str(exc)), "FREQ", occ)


def _check_harmonic(ctx, occ, where, result) -> None:
    """A dyna_harmo: PARA='FREQ', a nodal field component, or a component of
    an element field CALC_CHAMP computed (complex values)."""
    name = result.name or "?"
    index, state = _frequency_index(ctx, occ, result)
    if occ.get("PARA") is not None:
        if occ["PARA"] != "FREQ":
            ctx.unsupported(f"PARA={occ['PARA']!r} of a dyna_harmo", "PARA", occ)
        value = float(result.frequencies[index])
        record_check(ctx, f"{where} {name} FREQ {state}", value, occ)
        return
    field = occ.get("NOM_CHAM")
    if field not in result.fields and field in computed_fields(result):
        if occ.get("TYPE_TEST") is not None:
            ctx.unsupported(f"TYPE_TEST on {field}", "TYPE_TEST", occ)
        value = element_value_history(ctx, occ, result, field)[index]
        record_check(ctx, f"{where} {name} {field} {cell_point_label(occ)} {state}", value, occ)
        return
    if field not in result.fields:
        known = ", ".join([*result.fields, *computed_fields(result)])
        ctx.error(f"result has no field {field!r} (it has {known})", "NOM_CHAM", occ)
    values = result.fields[field][index]
    value, what = _field_value(ctx, occ, result.numbering, values, f"{name} {field}")
    record_check(ctx, f"{where} {what} {state}", value, occ)


def result_parameter(ctx, occ, result, index):
    para = occ["PARA"]
    if isinstance(result, DynaTrans):
        if para == "INST":
            return float(result.times[index])
    else:
        known = {
            "FREQ": result.frequencies,
            "MASS_GENE": result.generalized_mass,
            "RIGI_GENE": result.generalized_stiffness,
            "OMEGA2": (2 * np.pi * np.asarray(result.frequencies)) ** 2,
            **result.parameters,
        }
        if para in known:
            return float(np.asarray(known[para])[index])
    ctx.unsupported(f"PARA={para!r} of a {result.aster_type}", "PARA", occ)


def check_gene(ctx, occ, where):
    mode = occ.get("NUME_CMP_GENE")
    if mode is None:
        ctx.error("NUME_CMP_GENE is required", "NUME_CMP_GENE", occ)
    mode = int(mode)
    vector = occ.get("VECT_GENE")
    if vector is None and isinstance(occ.get("RESU_GENE"), GeneralizedVector):
        vector = occ["RESU_GENE"]  # RECU_GENE output tested through RESU_GENE
    if vector is not None:
        values, label = np.asarray(vector.values), f"{where} {vector.name or '?'}"
    elif isinstance(occ.get("RESU_GENE"), HarmGene):
        result = occ["RESU_GENE"]
        field = occ.get("NOM_CHAM", "DEPL")
        if field not in result.fields:
            ctx.error(f"the harm_gene holds no {field!r} field", "NOM_CHAM", occ)
        index, state = _frequency_index(ctx, occ, result)
        values = result.fields[field][index]
        label = f"{where} {result.name or '?'} {field} {state}"
    else:
        result = occ.get("RESU_GENE")
        if not isinstance(result, TranGene):
            ctx.unsupported(f"TEST_RESU/GENE of a {getattr(result, 'aster_type', '?')}", None, occ)
        field = occ.get("NOM_CHAM", "DEPL")
        if field not in ("DEPL", "VITE", "ACCE"):
            ctx.unsupported(f"NOM_CHAM={field!r}", "NOM_CHAM", occ)
        index, state = _gene_state_index(ctx, occ, result)
        values = getattr(result, field.lower())[index]
        label = f"{where} {result.name or '?'} {field} {state}"
    if not 1 <= mode <= values.size:
        ctx.error(f"NUME_CMP_GENE={mode}: {values.size} generalized DOFs", "NUME_CMP_GENE", occ)
    record_check(ctx, f"{label} cmp {mode}", values[mode - 1], occ)


_GENERALIZED_FIELDS = (".DEPL", ".VITE", ".ACCE")


def check_object(ctx, occ, where):
    """OBJET: code_aster's check sum of a stored array (its tstvec without
    weights: the sum of the finite values, real and imaginary parts alike).
    The arrays asterlite keeps under code_aster's names: the generalized
    DEPL/VITE/ACCE of a harm_gene or a tran_gene ('<name> .DEPL')."""
    text = str(occ["NOM"])
    name, suffix = text[:-5].strip(), text[-5:]
    concept = next(
        (
            value
            for value in ctx.session.namespace.values()
            if getattr(value, "name", None) == name and isinstance(value, (HarmGene, TranGene))
        ),
        None,
    )
    if concept is None or suffix not in _GENERALIZED_FIELDS:
        ctx.unsupported(
            f"OBJET {text.strip()!r}: asterlite keeps only the generalized "
            f"{'/'.join(_GENERALIZED_FIELDS)} arrays of harm_gene and tran_gene results",
            "NOM",
            occ,
        )
    field = suffix[1:]
    if isinstance(concept, HarmGene):
        if field not in concept.fields:
            ctx.error(f"the harm_gene {name} holds no {field} field", "NOM", occ)
        values = np.asarray(concept.fields[field])
    else:
        values = np.asarray(getattr(concept, field.lower()))
    parts = (
        np.concatenate([values.real.ravel(), values.imag.ravel()])
        if np.iscomplexobj(values)
        else values.ravel()
    )
    kept = parts[np.isfinite(parts) & (np.abs(parts) < 1e300)]
    record_check(ctx, f"{where} {name}{suffix} sum", float(kept.sum()), occ)


def _gene_state_index(ctx, occ, result) -> tuple[int, str]:
    """_state_index, except that code_aster 15 and older read NUME_ORDRE on a
    tran_gene as the position of the archived instant (asterlite.legacy.v15)."""
    number = occ.get("NUME_ORDRE")
    if number is None or not computes(ctx.session, "TEST_RESU_GENE_NUME_ORDRE_AS_POSITION"):
        return _state_index(ctx, occ, result.times, result.order)
    count = len(result.times)
    if not 1 <= int(number) <= count:
        ctx.error(f"NUME_ORDRE {number}: the result archives {count} instants", "NUME_ORDRE", occ)
    index = int(number) - 1
    ctx.log(
        f"note: code_aster 15 deck: NUME_ORDRE={number} read as the {number}th archived "
        f"instant (t={result.times[index]:g}, order {int(result.order[index])})"
    )
    return index, f"ordre {number}"


def check_field(ctx, occ, where):
    field = occ.get("CHAM_GD")
    if not isinstance(field, NodalField):
        ctx.unsupported(f"TEST_RESU/CHAM_NO of a {getattr(field, 'aster_type', '?')}", None, occ)
    value, what = _field_value(
        ctx, occ, field.numbering, np.asarray(field.values), field.name or "?"
    )
    record_check(ctx, f"{where} {what}", value, occ)


def check_carte(ctx, occ, where):
    """CARTE: the value of NOM_CMP a carte holds on the cell of GROUP_MA
    (a group of exactly one cell, as code_aster requires)."""
    carte = occ.get("CHAM_GD")
    if not isinstance(carte, CellConstantField):
        kind = getattr(carte, "aster_type", type(carte).__name__)
        ctx.unsupported(f"TEST_RESU/CARTE of a {kind}", "CHAM_GD", occ)
    mesh, group = carte.mesh, occ.get("GROUP_MA")
    if group is None:
        ctx.error("GROUP_MA names the cell to test", "GROUP_MA", occ)
    if group not in mesh.cell_groups:
        ctx.error(missing_name("cell group", group, mesh.cell_groups), "GROUP_MA", occ)
    cells = mesh.cell_groups[group]
    if len(cells) != 1:
        ctx.error(
            f"group {group} has {len(cells)} cells, TEST_RESU/CARTE needs one", "GROUP_MA", occ
        )
    component = occ["NOM_CMP"]
    given = dict(zip(carte.components, carte.values.get(int(cells[0]), ()), strict=False))
    if component not in given:
        ctx.error(f"the carte has no {component} on the cell of {group}", "NOM_CMP", occ)
    record_check(ctx, f"{where} {carte.name or '?'} {group} {component}", given[component], occ)


def cell_point_label(occ) -> str:
    where = [str(occ[k]) for k in ("GROUP_MA", "MAILLE", "GROUP_NO", "NOEUD") if occ.get(k)]
    if occ.get("POINT") is not None:
        where.append(f"PT {occ['POINT']}")
    return " ".join([*where, str(occ.get("NOM_CMP") or "")]).strip()


class _FieldHolder:
    def __init__(self, field):
        self.element_fields = {field.name: field}


def check_element_field(ctx, occ, where):
    """CHAM_ELEM: one component of an element field at a cell node (GROUP_MA
    + GROUP_NO / NOEUD) or point (POINT), or TYPE_TEST over its values (of
    NOM_CMP when given). The field is a ``cham_elem`` from CREA_CHAMP
    (:class:`FieldOnElements`) or a concept holding ``element_field`` (an
    ElementField with one order) and ``mesh``."""
    concept = occ.get("CHAM_GD")
    field, mesh = element_field_of(concept)
    if field is None or mesh is None:
        kind = getattr(concept, "aster_type", type(concept).__name__)
        ctx.unsupported(f"TEST_RESU/CHAM_ELEM of a {kind}", "CHAM_GD", occ)
    if occ.get("TYPE_TEST") is not None:
        values = np.asarray(field.values)[0]
        if occ.get("NOM_CMP"):
            component = as_tuple(occ["NOM_CMP"])[0]
            if component not in field.components:
                ctx.error(f"{field.name} has no component {component!r}", "NOM_CMP", occ)
            values = values[..., field.components.index(component)]
        value = reduce_values(values, occ["TYPE_TEST"])
        label = f"{where} {concept.name or '?'} {occ['TYPE_TEST']} {occ.get('NOM_CMP') or ''}"
        record_check(ctx, label.strip(), value, occ)
        return
    value = element_value_history(ctx, occ, _FieldHolder(field), field.name, mesh)[0]
    label = f"{where} {concept.name or '?'} {cell_point_label(occ)}"
    record_check(ctx, label, value, occ)


def element_field_of(concept):
    """(ElementField with one order, mesh) of a cham_elem concept."""
    if isinstance(concept, FieldOnElements):
        name = concept.field_name or concept.name or "CHAM_ELEM"
        values = np.asarray(concept.values)[None]
        field = ElementField(name, np.asarray(concept.cells), tuple(concept.components), values)
        return field, concept.mesh
    return getattr(concept, "element_field", None), getattr(concept, "mesh", None)
