"""CREA_CHAMP on nodal fields (TYPE_CHAM 'NOEU_*_R', and 'NOEU_*_C' for EXTR,
ASSE, R2C and C2R): AFFE (values by node and component), EXTR (one field of
a result, or its extreme over the stored fields with TYPE_MAXI; also on the
ELNO/ELGA fields CALC_CHAMP stored on a result, giving a ``cham_elem``, and
on the curvilinear abscissa carte MODI_MAILLAGE ABSC_CURV stored on a mesh,
TYPE_CHAM='CART_ABSC_R'), ASSE (pieces of fields, later ones overriding
earlier ones unless CUMUL='OUI') and COMB (linear combination). A field of
functions (TYPE_CHAM='NOEU_NEUT_F', AFFE with VALE_F) is evaluated by EVAL:
at each of its nodes, each function takes its parameters from the
components of the CHAM_PARA fields there (X, Y, Z of the geometry, X1...)."""

from __future__ import annotations

import re

import numpy as np

from asterlite.concepts.assembly import DofNumbering, NodalField, NodalFunctionField
from asterlite.concepts.mesh import CellConstantField
from asterlite.concepts.modes import FieldOnElements
from asterlite.fem.abscissa import ABSCISSA_COMPONENTS
from asterlite.fem.dofs import COMPONENT_RANK, sort_components
from asterlite.fem.selection import as_tuple, select_nodes
from asterlite.modal.fields import (
    FieldError,
    element_extreme,
    element_field_stack,
    extreme_over,
    field_stack,
    interpolate,
    match_real,
    norm_tran_extreme,
)
from asterlite.modal.renumber import transfer

#: the components of NEUT_R and NEUT_F fields
_NEUTRAL = r"X([1-9]|[12]\d|30)"


def _template_numbering(ctx, kw):
    for key in ("CHAM_NO", "NUME_DDL"):
        value = kw.get(key)
        if value is not None:
            return value if key == "NUME_DDL" else value.numbering
    model = kw.get("MODELE")
    neutral = kw.get("TYPE_CHAM") in ("NOEU_NEUT_R", "NOEU_NEUT_F")
    if model is not None and not neutral:
        from asterlite.fem.assemble import build_numbering_dofs

        return DofNumbering(mesh=model.mesh, dofs=build_numbering_dofs(model.node_components()))
    # MAILLAGE only, or a NEUT field (its components X1... are no DOFs of the
    # model): a field on exactly the (node, component) pairs affected
    mesh = kw["MAILLAGE"] if model is None else model.mesh
    pairs: dict[int, set[str]] = {}
    for occ in kw.factor("AFFE"):
        for node in select_nodes(ctx, occ, mesh):
            pairs.setdefault(int(node), set()).update(as_tuple(occ.get("NOM_CMP")))
    dofs = [(n, c) for n in sorted(pairs) for c in sort_components(pairs[n])]
    return DofNumbering(mesh=mesh, dofs=dofs)


def _check_meshes(ctx, kw, mesh) -> None:
    """MAILLAGE and MODELE, when given, must be on the field's mesh."""
    for key in ("MAILLAGE", "MODELE"):
        given = kw.get(key)
        given_mesh = given.mesh if key == "MODELE" and given is not None else given
        if given_mesh is not None and given_mesh is not mesh:
            ctx.error(f"{key} is not the mesh of the field's numbering", key, kw)


def _prolonged(kw, numbering, values, assigned):
    """The field on its whole numbering (PROL_ZERO='OUI': unassigned DOFs are
    zero) or, as code_aster builds it otherwise, on the assigned DOFs only."""

    if kw.get("PROL_ZERO", "NON") == "OUI" or assigned.all():
        return NodalField(numbering=numbering, values=values)
    dofs = [dof for dof, kept in zip(numbering.dofs, assigned, strict=True) if kept]
    return NodalField(
        numbering=DofNumbering(mesh=numbering.mesh, dofs=dofs), values=values[assigned]
    )


def _affe(ctx, kw):
    type_cham = kw.get("TYPE_CHAM")
    if type_cham not in ("NOEU_DEPL_R", "NOEU_NEUT_R", "NOEU_NEUT_F"):
        ctx.unsupported(f"CREA_CHAMP TYPE_CHAM={type_cham!r}", "TYPE_CHAM", kw)
    if type_cham == "NOEU_NEUT_F":
        return _affe_functions(ctx, kw)
    if type_cham == "NOEU_NEUT_R":
        for occ in kw.factor("AFFE"):
            for comp in as_tuple(occ.get("NOM_CMP")):
                if not re.fullmatch(_NEUTRAL, str(comp)):
                    ctx.error(f"{comp} is no component of NEUT_R (X1 ... X30)", "NOM_CMP", occ)
    numbering = _template_numbering(ctx, kw)
    _check_meshes(ctx, kw, numbering.mesh)
    mesh = numbering.mesh
    prolong = kw.get("PROL_ZERO", "NON") == "OUI"
    values = np.zeros(numbering.n_dofs)
    assigned = np.zeros(numbering.n_dofs, dtype=bool)
    by_node: dict[int, list[str]] = {}
    for node, comp in numbering.dofs:
        by_node.setdefault(node, []).append(comp)
    for occ in kw.factor("AFFE"):
        nodes = select_nodes(ctx, occ, mesh, all_nodes=sorted(by_node))
        comps = as_tuple(occ.get("NOM_CMP"))
        vals = as_tuple(occ.get("VALE"))
        if len(comps) != len(vals):
            ctx.error(f"NOM_CMP has {len(comps)} names but VALE {len(vals)} values", "VALE", occ)
        for comp, val in zip(comps, vals, strict=True):
            rows = numbering.dof_indices(nodes, comp)
            if np.all(rows < 0):
                ctx.error(f"no selected node carries {comp} in the numbering", "NOM_CMP", occ)
            if np.any(rows < 0) and not prolong and occ.get("TOUT") != "OUI":
                missing = mesh.node_names[int(np.asarray(nodes)[rows < 0][0])]
                ctx.error(f"node {missing} has no {comp} in the numbering", "NOM_CMP", occ)
            values[rows[rows >= 0]] = float(val)
            assigned[rows[rows >= 0]] = True
    return _prolonged(kw, numbering, values, assigned)


def _affe_functions(ctx, kw) -> NodalFunctionField:
    """NOEU_NEUT_F: functions (VALE_F) on the X1 ... X30 of the selected
    nodes, on those (node, component) pairs only."""
    for occ in kw.factor("AFFE"):
        if occ.get("VALE_F") is None:
            ctx.error("a NOEU_NEUT_F field takes functions (VALE_F)", "VALE_F", occ)
        for comp in as_tuple(occ.get("NOM_CMP")):
            if not re.fullmatch(_NEUTRAL, str(comp)):
                ctx.error(f"{comp} is no component of NEUT_F (X1 ... X30)", "NOM_CMP", occ)
    numbering = _template_numbering(ctx, kw)
    _check_meshes(ctx, kw, numbering.mesh)
    functions: list = [None] * numbering.n_dofs
    for occ in kw.factor("AFFE"):
        nodes = select_nodes(ctx, occ, numbering.mesh)
        comps = as_tuple(occ.get("NOM_CMP"))
        given = as_tuple(occ.get("VALE_F"))
        if len(comps) != len(given):
            ctx.error(
                f"NOM_CMP has {len(comps)} names but VALE_F {len(given)} functions", "VALE_F", occ
            )
        for comp, function in zip(comps, given, strict=True):
            for row in numbering.dof_indices(nodes, comp):
                functions[int(row)] = function
    return NodalFunctionField(numbering=numbering, functions=functions)


def _eval(ctx, kw) -> NodalField:
    """EVAL: the NOEU_NEUT_F field CHAM_F evaluated at each of its nodes, the
    parameters read at that node from the components of the CHAM_PARA
    fields (a NOEU_NEUT_R field on CHAM_F's nodes and components)."""
    if kw.get("TYPE_CHAM") != "NOEU_NEUT_R":
        ctx.error("EVAL of a NOEU_NEUT_F field gives a NOEU_NEUT_R field", "TYPE_CHAM", kw)
    source = kw["CHAM_F"]
    if not isinstance(source, NodalFunctionField):
        ctx.unsupported("CREA_CHAMP EVAL of a field other than NOEU_NEUT_F", "CHAM_F", kw)
    parameters: dict[tuple[int, str], float] = {}
    for field in as_tuple(kw["CHAM_PARA"]):
        if not isinstance(field, NodalField) or field.numbering.mesh is not source.numbering.mesh:
            ctx.error("CHAM_PARA must be nodal fields on CHAM_F's mesh", "CHAM_PARA", kw)
        for (node, comp), value in zip(field.numbering.dofs, np.real(field.values), strict=True):
            parameters[(int(node), str(comp))] = float(value)
    values = np.empty(source.numbering.n_dofs)
    for row, ((node, _comp), function) in enumerate(
        zip(source.numbering.dofs, source.functions, strict=True)
    ):
        values[row] = _evaluated(ctx, kw, function, node, parameters, source.numbering.mesh)
    return NodalField(numbering=source.numbering, values=values)


def _evaluated(ctx, kw, function, node: int, parameters, mesh) -> float:
    names = [p for p in getattr(function, "nom_para", ()) if p != "TOUTPARA"]
    missing = [p for p in names if (node, p) not in parameters]
    if missing:
        ctx.error(
            f"no CHAM_PARA field gives {', '.join(missing)} at node {mesh.node_names[node]} "
            f"(the parameters of {function.name or 'a function'} of CHAM_F)",
            "CHAM_PARA",
            kw,
        )
    if len(names) > 1 and not hasattr(function, "VALE"):
        ctx.unsupported(
            f"CREA_CHAMP EVAL of {function.name or 'a function'} of several parameters "
            "other than a FORMULE",
            "CHAM_F",
            kw,
        )
    args = [parameters[(node, p)] for p in names] or [0.0]
    return float(np.asarray(function.evaluate(*args), dtype=float))


def _nodal_only(ctx, kw):
    type_cham = str(kw.get("TYPE_CHAM") or "")
    if kw.get("OPERATION") == "EXTR" and kw.get("TABLE") is not None:
        return  # _table_field says which types it reads
    if kw.get("OPERATION") == "EXTR" and kw.get("MAILLAGE") is not None:
        return  # the mesh's own fields (_mesh_field)
    if kw.get("OPERATION") == "EXTR" and _is_element_type(type_cham) and type_cham.endswith("_R"):
        return  # element fields a result stores (CALC_CHAMP)
    if kw.get("OPERATION") in ("EXTR", "ASSE") and type_cham.startswith("NOEU_"):
        if type_cham.endswith("_C"):
            return  # complex nodal fields (a dyna_harmo's, a mode_meca_c's, R2C's)
    if not (type_cham.startswith("NOEU_") and type_cham.endswith("_R")):
        ctx.unsupported(
            f"CREA_CHAMP {kw.get('OPERATION')} on TYPE_CHAM={type_cham!r} (nodal real fields only)",
            "TYPE_CHAM",
            kw,
        )


def _extr(ctx, kw):
    """One stored field, chosen by order / instant / mode, or its extreme over
    the stored fields (TYPE_MAXI), nodal or by element (ELNO/ELGA fields
    CALC_CHAMP stored on the result)."""

    if kw.get("TABLE") is not None:
        return _table_field(ctx, kw)
    if kw.get("MAILLAGE") is not None:
        return _mesh_field(ctx, kw)
    if kw.get("RESULTAT") is None:
        ctx.unsupported("CREA_CHAMP EXTR from something else than RESULTAT", "OPERATION", kw)
    result = kw["RESULTAT"]
    element = _is_element_type(kw.get("TYPE_CHAM"))
    try:
        if element:
            field, access = element_field_stack(result, kw["NOM_CHAM"])
            values = field.values
        else:
            numbering, values, access = field_stack(result, kw["NOM_CHAM"])
        if kw.get("TYPE_MAXI") == "NORM_TRAN":
            selected = _norm_tran(ctx, kw, access, values, None if element else numbering)
        else:
            selected = _selected_state(ctx, kw, access, values)
    except FieldError as exc:
        ctx.error(str(exc), "RESULTAT", kw)
    complex_type = str(kw.get("TYPE_CHAM")).endswith("_C")
    if np.iscomplexobj(selected) != complex_type:
        # code_aster checks the field's scalar type against TYPE_CHAM
        kind = "complex" if np.iscomplexobj(selected) else "real"
        ctx.error(
            f"the {kw['NOM_CHAM']} field is {kind}: TYPE_CHAM does not match", "TYPE_CHAM", kw
        )
    if not element:
        target = kw.get("NUME_DDL")
        if target is not None and target is not numbering:
            # code_aster copies the field onto the given numbering (vtcopy):
            # DOFs it lacks are dropped, DOFs the result lacks are zero
            from asterlite.modal.renumber import transfer

            selected = transfer(selected, numbering, target)
            numbering = target
        return NodalField(numbering=numbering, values=selected)

    return FieldOnElements(
        mesh=_result_mesh(ctx, kw, result),
        field_type=kw["TYPE_CHAM"],
        field_name=kw["NOM_CHAM"],
        cells=np.asarray(field.cells, dtype=int),
        components=tuple(field.components),
        values=selected,
    )


# a table's columns that locate a value; the others are components (tabchs)
TABLE_PLACES = ("NOEUD", "MAILLE", "POINT", "SOUS_POINT")


def _table_field(ctx, kw):
    """EXTR of a table (code_aster's tabchs): a nodal field whose rows give a
    node by name (NOEUD) and components by column; a cell a row leaves empty
    is a component the field lacks at that node."""
    table, type_cham = kw["TABLE"], str(kw.get("TYPE_CHAM") or "")
    if not type_cham.startswith("NOEU_") or type_cham.endswith("_C"):
        ctx.unsupported(
            f"CREA_CHAMP EXTR of a TABLE as {type_cham} (real nodal fields only)", "TYPE_CHAM", kw
        )
    model = kw.get("MODELE")
    mesh = kw.get("MAILLAGE") or (model.mesh if model is not None else None)
    if mesh is None:
        ctx.error("a field read from a TABLE needs MAILLAGE or MODELE", "TABLE", kw)
    if "NOEUD" not in table.columns:
        ctx.error("a nodal field's TABLE needs a NOEUD column", "TABLE", kw)
    components = [c for c in table.columns if c not in TABLE_PLACES]
    if type_cham.startswith("NOEU_DEPL"):
        foreign = [c for c in components if c not in COMPONENT_RANK]
        if foreign:
            ctx.error(f"components of no DEPL_R field: {', '.join(foreign)}", "TABLE", kw)
    values: dict[tuple[int, str], float] = {}
    for row in table.rows:
        name = row.get("NOEUD")
        node = None if name is None else mesh.find_node(str(name).strip())
        if node is None:
            ctx.error(f"the TABLE's node {name!r} is not in the mesh", "TABLE", kw)
        for component in components:
            if row.get(component) is not None:
                values[(int(node), component)] = float(row[component])
    by_node: dict[int, set] = {}
    for node, component in values:
        by_node.setdefault(node, set()).add(component)
    dofs = [(n, c) for n in sorted(by_node) for c in sort_components(by_node[n])]
    return NodalField(
        numbering=DofNumbering(mesh=mesh, dofs=dofs),
        values=np.array([values[dof] for dof in dofs], dtype=float),
    )


def _mesh_field(ctx, kw):
    """EXTR of a mesh's field: its curvilinear abscissa (NOM_CHAM='ABSC_CURV')
    or its node coordinates (NOM_CHAM='GEOMETRIE')."""
    mesh, name = kw["MAILLAGE"], kw["NOM_CHAM"]
    if name == "GEOMETRIE":
        return _geometry(ctx, kw, mesh)
    if kw.get("TYPE_CHAM") != "CART_ABSC_R":
        ctx.error(
            f"the mesh's ABSC_CURV is a CART_ABSC_R field, not {kw.get('TYPE_CHAM')}",
            "TYPE_CHAM",
            kw,
        )
    if mesh.curvilinear_abscissa is None:
        ctx.error(
            "the mesh has no curvilinear abscissa (MODI_MAILLAGE ABSC_CURV first)", "NOM_CHAM", kw
        )
    return CellConstantField(
        mesh=mesh,
        field_type="CART_ABSC_R",
        components=ABSCISSA_COMPONENTS,
        values=dict(mesh.curvilinear_abscissa),
    )


def _geometry(ctx, kw, mesh):
    """The coordinates X, Y, Z of every node (code_aster keeps three, also
    for a plane mesh), as a NOEU_GEOM_R field."""
    if kw.get("TYPE_CHAM") != "NOEU_GEOM_R":
        ctx.error(
            f"the mesh's GEOMETRIE is a NOEU_GEOM_R field, not {kw.get('TYPE_CHAM')}",
            "TYPE_CHAM",
            kw,
        )
    dofs = [(node, axis) for node in range(mesh.n_nodes) for axis in ("X", "Y", "Z")]
    values = np.asarray(mesh.coords, dtype=float)[:, :3].reshape(-1).copy()
    return NodalField(numbering=DofNumbering(mesh=mesh, dofs=dofs), values=values)


def _is_element_type(type_cham) -> bool:
    return str(type_cham or "").startswith(("ELNO_", "ELGA_"))


def _result_mesh(ctx, kw, result):
    numbering = getattr(result, "numbering", None)
    if numbering is not None:
        return numbering.mesh
    if kw.get("MODELE") is not None:
        return kw["MODELE"].mesh
    ctx.error("cannot tell the mesh of the result", "RESULTAT", kw)


def _extreme_params(kw, access, rows) -> np.ndarray:
    """What TYPE_RESU puts in an extreme field: the order numbers for
    'NUME_ORDRE', the instants otherwise (orders when there are none)."""
    if kw.get("TYPE_RESU") == "NUME_ORDRE" or "INST" not in access:
        return np.asarray(access["NUME_ORDRE"], dtype=float)[rows]
    return np.asarray(access["INST"], dtype=float)[rows]


def _norm_tran(ctx, kw, access, values, numbering) -> np.ndarray:
    """TYPE_MAXI='NORM_TRAN': by node, the field of largest translation norm."""

    if numbering is None:
        ctx.error("TYPE_MAXI='NORM_TRAN' applies to nodal fields", "TYPE_MAXI", kw)
    rows = _extr_rows(ctx, kw, access, values.shape[0])
    if rows.size == 0:
        ctx.error("no stored field is selected", "RESULTAT", kw)
    what = kw.get("TYPE_RESU", "VALE")
    return norm_tran_extreme(numbering, values[rows], what, _extreme_params(kw, access, rows))


def _selected_state(ctx, kw, access, values) -> np.ndarray:
    """The field (values[k]) the keywords select in a stack (first axis: the
    stored states), or the entry-wise extreme for TYPE_MAXI."""

    if kw.get("TYPE_MAXI") is not None:
        if np.iscomplexobj(values):
            ctx.unsupported("TYPE_MAXI over complex fields", "TYPE_MAXI", kw)
        rows = _extr_rows(ctx, kw, access, values.shape[0])
        params = _extreme_params(kw, access, rows)
        reduce = element_extreme if values.ndim > 2 else extreme_over
        return reduce(values[rows], kw["TYPE_MAXI"], kw.get("TYPE_RESU", "VALE"), params)
    precision = float(kw.get("PRECISION", 1.0e-6))
    criterion = kw.get("CRITERE", "RELATIF")
    if kw.get("INST") is not None and "INST" in access:
        if kw.get("INTERPOL", "NON") == "LIN":
            return interpolate(access["INST"], values, float(kw["INST"]))
        k = match_real(access["INST"], float(kw["INST"]), precision, criterion)
    elif kw.get("FREQ") is not None and "FREQ" in access:
        k = match_real(access["FREQ"], float(kw["FREQ"]), precision, criterion)
    else:
        k = _extr_index(ctx, kw, access)
    return np.array(values[k], dtype=np.result_type(values, float))


def _extr_index(ctx, kw, access) -> int:
    for key in ("NUME_ORDRE", "NUME_MODE", "NOM_CAS", "NOEUD_CMP", "INST", "FREQ"):
        wanted = kw.get(key)
        if wanted is None:
            continue
        if key not in access:
            ctx.error(f"this result has no {key} access", key, kw)
        if key == "NOEUD_CMP":
            wanted = " ".join(str(w).strip() for w in as_tuple(wanted))
        hits = np.flatnonzero(np.asarray(access[key]) == wanted)
        if hits.size == 0:
            ctx.error(f"no field with {key}={wanted!r} in the result", key, kw)
        return int(hits[0])
    ctx.error("give NUME_ORDRE, INST, NUME_MODE, FREQ, NOM_CAS or NOEUD_CMP", None, kw)


def _extr_rows(ctx, kw, access, count) -> np.ndarray:
    if kw.get("NUME_ORDRE") is not None:
        wanted = np.asarray(as_tuple(kw["NUME_ORDRE"]))
        return np.flatnonzero(np.isin(access["NUME_ORDRE"], wanted))
    instants = None
    if kw.get("LIST_INST") is not None:
        instants = np.asarray(kw["LIST_INST"].values, dtype=float)
    elif kw.get("INST") is not None:
        instants = np.asarray(as_tuple(kw["INST"]), dtype=float)
    if instants is not None and "INST" in access:
        from asterlite.modal.fields import match_real

        precision = float(kw.get("PRECISION", 1.0e-6))
        criterion = kw.get("CRITERE", "RELATIF")
        return np.array(
            [match_real(access["INST"], t, precision, criterion) for t in instants], dtype=int
        )
    return np.arange(count)


def _union_numbering(mesh, fields):
    from asterlite.fem.assemble import build_numbering_dofs

    pairs: dict[int, set[str]] = {}
    for f in fields:
        for node, comp in f.numbering.dofs:
            pairs.setdefault(node, set()).add(comp)
    return DofNumbering(
        mesh=mesh, dofs=build_numbering_dofs({n: sort_components(c) for n, c in pairs.items()})
    )


def _output_numbering(ctx, kw, fields):
    """The numbering of an assembled field: the NUME_DDL / CHAM_NO template's
    when one is given (as code_aster), else the union of the pieces' DOFs."""
    if kw.get("NUME_DDL") is not None or kw.get("CHAM_NO") is not None:
        numbering = _template_numbering(ctx, kw)
        _check_meshes(ctx, kw, numbering.mesh)
        return numbering
    mesh = kw.get("MAILLAGE") or kw["MODELE"].mesh
    _check_meshes(ctx, kw, mesh)
    return _union_numbering(mesh, fields)


def _asse(ctx, kw):
    """Pieces of nodal fields on one numbering. As code_aster's chpass, each
    piece has the scalar type TYPE_CHAM names; COEF_C needs a complex piece;
    a later piece overrides earlier ones on the DOFs it covers unless
    CUMUL='OUI'."""
    occs = kw.factor("ASSE")
    numbering = _output_numbering(ctx, kw, [occ["CHAM_GD"] for occ in occs])
    mesh = numbering.mesh
    complex_type = str(kw.get("TYPE_CHAM")).endswith("_C")
    for occ in occs:
        source = occ["CHAM_GD"]
        if not isinstance(source, NodalField):
            ctx.unsupported("CREA_CHAMP ASSE of a field by element", "CHAM_GD", occ)
        if source.numbering.mesh is not mesh:
            ctx.error("CHAM_GD is on another mesh", "CHAM_GD", occ)
        if np.iscomplexobj(source.values) != complex_type:
            kind = "complex" if np.iscomplexobj(source.values) else "real"
            ctx.error(f"CHAM_GD is a {kind} field: TYPE_CHAM does not match", "CHAM_GD", occ)
        if occ.get("COEF_C") is not None and not complex_type:
            ctx.error("COEF_C needs complex fields (TYPE_CHAM NOEU_*_C)", "COEF_C", occ)
    values = np.zeros(numbering.n_dofs, dtype=complex if complex_type else float)
    assigned = np.zeros(numbering.n_dofs, dtype=bool)
    for occ in occs:
        source = occ["CHAM_GD"]
        nodes = set(select_nodes(ctx, occ, mesh).tolist())
        comps = as_tuple(occ.get("NOM_CMP"))
        renamed = as_tuple(occ.get("NOM_CMP_RESU")) or comps
        if len(renamed) != len(comps):
            ctx.error("NOM_CMP and NOM_CMP_RESU differ in length", "NOM_CMP_RESU", occ)
        rename = dict(zip(comps, renamed, strict=True))
        coef = occ.get("COEF_C")
        coef = complex(coef) if coef is not None else float(occ.get("COEF_R", 1.0))
        for (node, comp), value in zip(source.numbering.dofs, source.values, strict=True):
            if node not in nodes or (comps and comp not in rename):
                continue
            row = numbering.index.get((node, rename.get(comp, comp)))
            if row is None:
                continue
            if occ.get("CUMUL", "NON") == "OUI":
                values[row] += coef * value
            else:
                values[row] = coef * value
            assigned[row] = True
    return _prolonged(kw, numbering, values, assigned)


def _comb(ctx, kw):
    occs = kw.factor("COMB")
    numbering = occs[0]["CHAM_GD"].numbering
    values = np.zeros(numbering.n_dofs)
    for occ in occs:
        field = occ["CHAM_GD"]
        if field.numbering.mesh is not numbering.mesh:
            ctx.error("the fields are on different meshes", "CHAM_GD", occ)
        values += float(occ["COEF_R"]) * transfer(field.values, field.numbering, numbering)
    return NodalField(numbering=numbering, values=values)


def _c2r(ctx, kw):
    """C2R (code_aster's chreco): the real part, imaginary part, modulus or
    phase (degrees, atan2) of a complex nodal field."""
    field = kw["CHAM_GD"]
    if not isinstance(field, NodalField):
        ctx.unsupported("CREA_CHAMP C2R of a field by element", "CHAM_GD", kw)
    values = np.asarray(field.values)
    if not np.iscomplexobj(values):
        ctx.error("C2R needs a complex field: CHAM_GD is real", "CHAM_GD", kw)
    part = kw["PARTIE"]
    if part == "REEL":
        out = values.real
    elif part == "IMAG":
        out = values.imag
    elif part == "MODULE":
        out = np.abs(values)
    else:
        out = np.degrees(np.arctan2(values.imag, values.real))
    return NodalField(numbering=field.numbering, values=np.array(out, dtype=float))


def _r2c(ctx, kw):
    """R2C: a real nodal field as a complex one (zero imaginary part)."""
    field = kw["CHAM_GD"]
    if not isinstance(field, NodalField):
        ctx.unsupported("CREA_CHAMP R2C of a field by element", "CHAM_GD", kw)
    if np.iscomplexobj(field.values):
        ctx.error("R2C needs a real field: CHAM_GD is complex", "CHAM_GD", kw)
    return NodalField(numbering=field.numbering, values=np.asarray(field.values).astype(complex))


def run(ctx, kw):
    operation = kw.get("OPERATION")
    if operation == "AFFE":
        return _affe(ctx, kw)
    if operation in ("C2R", "R2C"):
        # code_aster derives the output quantity from CHAM_GD's (DEPL_R <-> DEPL_C);
        # a TYPE_CHAM of the other scalar type is a deck error
        wanted = "_C" if operation == "R2C" else "_R"
        if not str(kw.get("TYPE_CHAM")).endswith(wanted):
            ctx.error(f"{operation} gives a NOEU_*{wanted} field", "TYPE_CHAM", kw)
        return _c2r(ctx, kw) if operation == "C2R" else _r2c(ctx, kw)
    if operation == "EVAL":
        return _eval(ctx, kw)
    handlers = {"EXTR": _extr, "ASSE": _asse, "COMB": _comb}
    if operation in handlers:
        _nodal_only(ctx, kw)
        return handlers[operation](ctx, kw)
    ctx.unsupported(f"CREA_CHAMP OPERATION={operation!r}", "OPERATION", kw)
