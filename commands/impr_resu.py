"""IMPR_RESU: write meshes, nodal fields and results.

- ``FORMAT='MED'`` (logical unit 80 by default): a MED file for Salome /
  ParaVis (:mod:`asterlite.io.med_writer`). ``RESU=_F(MAILLAGE=...)`` writes
  the mesh; ``RESULTAT`` (dyna_trans, mode_meca, mult_elas) writes its
  nodal fields (NOM_CHAM, all by default) at the chosen steps (TOUT_ORDRE,
  NUME_ORDRE, NUME_MODE, INST, FREQ, LIST_*, NOM_CAS), on the nodes of
  GROUP_NO / GROUP_MA (a MED profile) and for the components NOM_CMP; the
  mesh comes with it. ``CHAM_GD`` writes a nodal field. Field names follow
  code_aster (result name on 8 characters padded with ``_`` + field name),
  or NOM_CHAM_MED / NOM_RESU_MED. Element fields (``*_ELNO`` by element
  node, ``*_ELGA`` at Gauss points, on the cells of GROUP_MA / MAILLE) of a
  result or a ``cham_elem`` (CREA_CHAMP) are written as code_aster does
  (MED ``MED_NOEUD_MAILLE`` / Gauss-point fields). Every IMPR_RESU of a run on the same unit
  adds to the same file (a MED file left by an earlier run is replaced).
- ``FORMAT='RESULTAT'`` (unit 8): a text listing of the same selections,
  one block per field and step, one line per node (FORMAT_R, IMPR_COOR,
  NOM_PARA / TOUT_PARA, VALE_MAX / VALE_MIN), or for element fields one
  block per cell with a line per node (ELNO) or Gauss point (ELGA); a mesh
  alone is listed in ASTER format.
- ``FORMAT='ASTER'`` (unit 26): a mesh in code_aster's text mesh format.
"""

from __future__ import annotations

import weakref
from pathlib import Path

import numpy as np

from asterlite.concepts.assembly import NodalField
from asterlite.concepts.harmonic import DynaHarmo
from asterlite.concepts.mesh import Mesh
from asterlite.concepts.modes import FieldOnElements, ModeResult
from asterlite.concepts.table import Table
from asterlite.concepts.transient import DynaTrans
from asterlite.errors import CommandError, missing_name
from asterlite.io.ideas_result import field_lines
from asterlite.io.med_writer import (
    ElementSeries,
    MedWriteError,
    NodalSeries,
    complex_part,
    dofs_to_nodal,
    med_field_name,
    write_med,
)
from asterlite.io.result_store import (
    element_field_names,
    is_physical_result,
    nodal_field_names,
    nodal_series,
    result_steps,
    select_steps,
)
from asterlite.io.tables import fortran_real, table_lines, write_lines
from asterlite.post.restitution import as_tuple, node_indices, values_of

# MED files each session has written (a later IMPR_RESU on the unit appends)
_WRITTEN: dict[int, tuple[weakref.ref, set[Path]]] = {}


def run(ctx, kw):
    fmt = kw.get("FORMAT", "MED")
    if fmt == "MED":
        return write_med_format(ctx, kw)
    if fmt == "RESULTAT":
        return write_text_format(ctx, kw)
    if fmt == "ASTER":
        return write_aster_format(ctx, kw)
    if fmt == "IDEAS":
        return write_ideas_format(ctx, kw)
    ctx.unsupported(f"FORMAT={fmt!r}", "FORMAT", kw)


def write_ideas_format(ctx, kw) -> None:
    """FORMAT='IDEAS' (unit 30): the nodal fields of results as I-DEAS
    datasets 55 (asterlite.io.ideas_result), every order (or those chosen)
    and field (or NOM_CHAM), on the nodes of GROUP_NO / GROUP_MA; PARTIE
    writes the real or imaginary part of a complex field."""

    # VERSION changes the mesh datasets only (2411/2412 or 781/780), not 55
    kw.mark_used("VERSION")
    path = ctx.session.output_path(int(kw.get("UNITE", 30)))
    lines: list[str] = []
    for occ in kw.factor("RESU"):
        result = occ.get("RESULTAT")
        if result is None:
            what = "MAILLAGE" if occ.get("MAILLAGE") is not None else "CHAM_GD"
            ctx.unsupported(f"IMPR_RESU FORMAT='IDEAS' of a {what}", what, occ)
        if not isinstance(result, DynaHarmo | DynaTrans | ModeResult):
            ctx.unsupported(f"IMPR_RESU FORMAT='IDEAS' of a {result.aster_type}", "RESULTAT", occ)
        if occ.get("NOM_CMP") is not None:
            ctx.unsupported("NOM_CMP in FORMAT='IDEAS'", "NOM_CMP", occ)
        occ.mark_used("TOUT_CMP")  # every component: the default
        lines.extend(_ideas_occurrence(ctx, occ, result))
    write_lines(path, lines, append=not first_time(ctx.session, path))
    ctx.log(f"IDEAS datasets written to {path.name} ({len(lines)} lines)")


def _ideas_occurrence(ctx, occ, result) -> list[str]:
    if isinstance(result, ModeResult):
        fields = {"DEPL": np.asarray(result.shapes).T}
    else:
        fields = dict(result.fields)
    names = list(as_tuple(occ.get("NOM_CHAM"))) or [
        n for n in ("DEPL", "VITE", "ACCE") if n in fields
    ]
    occ.mark_used("TOUT_CHAM")  # every field: the default
    for name in names:
        if name not in fields:
            ctx.error(f"the result has no field {name}", "NOM_CHAM", occ)
    if isinstance(result, DynaHarmo):
        from asterlite.post.harmonic import selection_from_keywords

        rows = selection_from_keywords(ctx, occ, result.frequencies, result.order).lower
    else:
        rows = chosen_steps(ctx, occ, result_steps(result))
    nodes = node_indices(ctx, occ, result.numbering.mesh)
    title = f"ASTERLITE CONCEPT {result.name or ''} DE TYPE {result.aster_type.upper()}"
    lines: list[str] = []
    for k in rows:
        if isinstance(result, ModeResult):
            analysis, order = 2, k + 1
            record_7 = (2, 4, order, int(result.mode_numbers[k]))
            damping = result.parameters.get("AMOR_REDUIT")
            record_8 = (
                float(result.frequencies[k]),
                float(np.asarray(result.generalized_mass)[k]),
                0.0 if damping is None else float(np.asarray(damping)[k]),
                0.0,
            )
        elif isinstance(result, DynaHarmo):
            analysis, order = 5, int(result.order[k])
            record_7, record_8 = (2, 1, 1, order), (float(result.frequencies[k]),)
        else:
            analysis, order = 4, int(result.order[k])
            record_7, record_8 = (2, 1, 1, order), (float(result.times[k]),)
        for name in names:
            values = np.asarray(fields[name][k])
            if np.iscomplexobj(values) and occ.get("PARTIE") is not None:
                values = values.real if occ["PARTIE"] == "REEL" else values.imag
            subtitle = occ.get("SOUS_TITRE") or f"CHAMP {name} NUME_ORDRE {order}"
            lines.extend(
                field_lines(
                    result.numbering,
                    values,
                    name,
                    analysis,
                    record_7,
                    record_8,
                    title,
                    subtitle,
                    nodes,
                )  # fmt: skip
            )
    return lines


# =============================================================================
# selections shared by the formats (and by POST_RELEVE_T)
# =============================================================================


def first_time(session, path: Path) -> bool:
    """True the first time this session writes ``path`` (then it is recorded)."""
    entry = _WRITTEN.get(id(session))
    if entry is None or entry[0]() is not session:
        entry = (weakref.ref(session), set())
        _WRITTEN[id(session)] = entry
    path = Path(path).resolve()
    if path in entry[1]:
        return False
    entry[1].add(path)
    return True


def chosen_steps(ctx, kw, steps) -> np.ndarray:
    """Indices of the stored steps selected by the access keywords of ``kw``."""
    access = {}
    kw.mark_used("TOUT_ORDRE", "TOUT_INST")  # every step: the default selection
    if kw.get("NUME_ORDRE") is not None:
        access["nume_ordre"], key = as_tuple(kw["NUME_ORDRE"]), "NUME_ORDRE"
    elif kw.get("LIST_ORDRE") is not None:
        access["nume_ordre"], key = values_of(kw["LIST_ORDRE"]).astype(int), "LIST_ORDRE"
    elif kw.get("NUME_MODE") is not None:
        access["nume_mode"], key = as_tuple(kw["NUME_MODE"]), "NUME_MODE"
    elif kw.get("LIST_MODE") is not None:
        access["nume_mode"], key = values_of(kw["LIST_MODE"]).astype(int), "LIST_MODE"
    elif kw.get("INST") is not None:
        access["inst"], key = values_of(kw["INST"]), "INST"
    elif kw.get("LIST_INST") is not None:
        access["inst"], key = values_of(kw["LIST_INST"]), "LIST_INST"
    elif kw.get("FREQ") is not None:
        access["freq"], key = values_of(kw["FREQ"]), "FREQ"
    elif kw.get("LIST_FREQ") is not None:
        access["freq"], key = values_of(kw["LIST_FREQ"]), "LIST_FREQ"
    elif kw.get("NOM_CAS") is not None:
        access["nom_cas"], key = as_tuple(kw["NOM_CAS"]), "NOM_CAS"
    else:
        key = None
    try:
        return select_steps(
            steps,
            precision=float(kw.get("PRECISION", 1e-6)),
            criterion=kw.get("CRITERE", "RELATIF"),
            **access,
        )
    except CommandError as exc:
        ctx.error(exc.message, key, kw)


def chosen_nodes(ctx, kw, mesh) -> np.ndarray | None:
    """Mesh nodes of GROUP_NO / NOEUD / GROUP_MA / MAILLE (None: all)."""
    if kw.get("TOUT") == "OUI":
        return None
    return node_indices(ctx, kw, mesh)


def result_mesh(result) -> Mesh:
    return result.numbering.mesh


def field_names(ctx, kw, result) -> list[str]:
    """Fields to write: NOM_CHAM, or every field the result holds (nodal
    fields first, then element fields)."""
    nodal = nodal_field_names(result)
    available = nodal + [n for n in element_field_names(result) if n not in nodal]
    if kw.get("NOM_CHAM") is not None and kw.get("TOUT_CHAM") != "OUI":
        names = list(dict.fromkeys(as_tuple(kw["NOM_CHAM"])))
        for name in names:
            if name not in available:
                ctx.error(
                    f"the result {result.name or ''} has no field {name} "
                    f"(it has {', '.join(available) or 'none'})",
                    "NOM_CHAM",
                    kw,
                )
        return names
    return available


def is_element_field(result, name: str) -> bool:
    return name not in nodal_field_names(result) and name in element_field_names(result)


def element_location(name: str) -> str:
    return "ELGA" if name.endswith("_ELGA") else "ELNO"


def chosen_cells(ctx, kw, mesh, carried) -> np.ndarray:
    """Rows of ``carried`` (the cells a field is on) named by GROUP_MA /
    MAILLE (all rows when neither is given)."""
    carried = np.asarray(carried, dtype=int)
    names = as_tuple(kw.get("GROUP_MA")) + as_tuple(kw.get("MAILLE"))
    if not names or kw.get("TOUT") == "OUI":
        return np.arange(carried.size)
    wanted: list[int] = []
    for group in as_tuple(kw.get("GROUP_MA")):
        if group not in mesh.cell_groups:
            ctx.error(missing_name("cell group", group, mesh.cell_groups), "GROUP_MA", kw)
        wanted.extend(int(c) for c in mesh.cell_groups[group])
    for cell_name in as_tuple(kw.get("MAILLE")):
        found = mesh.find_cell(str(cell_name))
        if found is None:
            ctx.error(f"mesh has no cell {cell_name!r}", "MAILLE", kw)
        wanted.append(int(found))
    wanted_set = set(wanted)
    rows = np.array([k for k, c in enumerate(carried) if int(c) in wanted_set], dtype=int)
    if rows.size == 0:
        ctx.error("the field has no value on the requested cells", "GROUP_MA", kw)
    return rows


def element_components(ctx, kw, name: str, components) -> list[int]:
    """Indices of NOM_CMP in ``components`` (all when NOM_CMP is absent)."""
    asked = components_of(kw)
    if not asked:
        return list(range(len(components)))
    absent = [c for c in asked if c not in components]
    if absent:
        ctx.error(
            f"field {name} has no component {absent[0]} (it has {', '.join(components)})",
            "NOM_CMP",
            kw,
        )
    return [list(components).index(c) for c in asked]


def element_block(ctx, kw, result, name: str):
    """(cells, components, values (n_selected_steps, n_cells, n_points,
    n_comp), step indices) of an element field of a result."""
    field = result.element_fields[name]
    if field.sub_points > 1:
        ctx.unsupported(f"IMPR_RESU of {name} on sub-points (multifibre beams)", "NOM_CHAM", kw)
    indices = chosen_steps(ctx, kw, result_steps(result))
    rows = chosen_cells(ctx, kw, result_mesh(result), field.cells)
    cmp_idx = element_components(ctx, kw, name, field.components)
    values = np.asarray(field.values)[indices][:, rows][..., cmp_idx]
    comps = tuple(field.components[k] for k in cmp_idx)
    return np.asarray(field.cells, dtype=int)[rows], comps, values, indices


def cham_elem_block(ctx, kw, field: FieldOnElements):
    """(cells, components, values (1, n_cells, n_points, n_comp)) of a cham_elem."""
    rows = chosen_cells(ctx, kw, field.mesh, field.cells)
    cmp_idx = element_components(ctx, kw, field.field_name, field.components)
    values = np.asarray(field.values)[rows][..., cmp_idx][None]
    comps = tuple(field.components[k] for k in cmp_idx)
    return np.asarray(field.cells, dtype=int)[rows], comps, values


def cham_elem_location(field: FieldOnElements) -> str:
    kind = str(field.field_type or field.field_name or "")
    return "ELGA" if "ELGA" in kind else "ELNO"


def components_of(kw) -> tuple[str, ...]:
    return tuple(as_tuple(kw.get("NOM_CMP")))


def result_block(ctx, kw, result, name: str):
    """(nodes, components, values (n_selected_steps, n_nodes, n_comp), step
    indices) of one field of a result, for the keywords of one occurrence."""
    mesh = result_mesh(result)
    steps = result_steps(result)
    indices = chosen_steps(ctx, kw, steps)
    nodes = chosen_nodes(ctx, kw, mesh)
    comps = components_of(kw)
    nodes, comps, values = nodal_series(result, name, nodes, comps)
    check_components(ctx, kw, result, name, comps)
    if nodes.size == 0:
        ctx.error(f"field {name}: no value on the requested nodes", "GROUP_NO", kw)
    return nodes, comps, values[indices], indices


def check_components(ctx, kw, result, name, comps) -> None:
    asked = components_of(kw)
    if not asked:
        return
    _, present, _ = nodal_series(result, name)
    absent = [c for c in asked if c not in present]
    if absent:
        ctx.error(
            f"field {name} has no component {absent[0]} (it has {', '.join(present)})",
            "NOM_CMP",
            kw,
        )


def nodal_field_block(ctx, kw, field: NodalField):
    """(nodes, components, values (1, n_nodes, n_comp)) of a CHAM_GD."""
    numbering = field.numbering
    nodes = chosen_nodes(ctx, kw, numbering.mesh)
    return dofs_to_nodal(numbering, field.values[None, :], nodes, components_of(kw))


# =============================================================================
# MED
# =============================================================================


def write_med_format(ctx, kw) -> None:
    path = ctx.session.output_path(int(kw.get("UNITE", 80)))
    version = kw.get("VERSION_MED", "4.0.0")
    for occ in kw.factor("RESU"):
        mesh, mesh_name, series = med_occurrence(ctx, occ)
        append = not first_time(ctx.session, path)
        try:
            write_med(path, mesh, mesh_name, series, version=version, append=append)
        except MedWriteError as exc:
            ctx.error(str(exc), None, occ)
        written = ", ".join(s.name for s in series) or "mesh only"
        ctx.log(f"MED {path.name}: mesh {mesh_name}; {written}")
        if occ.get("INFO_MAILLAGE") == "OUI":
            ctx.log(mesh_summary(mesh, mesh_name))


def med_occurrence(ctx, occ):
    """(mesh, mesh name, [NodalSeries]) of one RESU occurrence; PARTIE
    writes a part of the values (asterlite.io.med_writer.complex_part)."""
    mesh, name, series = _med_series(ctx, occ)
    part = occ.get("PARTIE")
    if part is not None:
        for one in series:
            one.values = complex_part(one.values, part)
    return mesh, name, series


def _med_series(ctx, occ):
    if occ.get("NOM_PARA") is not None:
        ctx.unsupported("NOM_PARA (MED scalar variables)", "NOM_PARA", occ)
    result, field = occ.get("RESULTAT"), occ.get("CHAM_GD")
    mesh = occ.get("MAILLAGE")
    if result is not None:
        if isinstance(result, DynaHarmo) and occ.get("PARTIE") is None:
            # MED holds real values: code_aster stops too (ircmva, RESULT3_69)
            ctx.error("a complex field is written to MED one PARTIE at a time", "PARTIE", occ)
        if not (is_physical_result(result) or isinstance(result, DynaHarmo)):
            ctx.unsupported(f"IMPR_RESU of a {result.aster_type}", "RESULTAT", occ)
        mesh = mesh or result_mesh(result)
        return mesh, mesh_label(mesh), result_series(ctx, occ, result)
    if isinstance(field, FieldOnElements):
        mesh = mesh or field.mesh
        return mesh, mesh_label(mesh), [cham_elem_series(ctx, occ, field)]
    if field is not None:
        if not isinstance(field, NodalField):
            ctx.unsupported(f"CHAM_GD of type {field.aster_type}", "CHAM_GD", occ)
        mesh = mesh or field.numbering.mesh
        return mesh, mesh_label(mesh), [cham_gd_series(ctx, occ, field)]
    return mesh, mesh_label(mesh), []


def mesh_label(mesh: Mesh) -> str:
    return (mesh.name or "MAILLAGE").strip()


def med_names(ctx, occ, default_prefix: str, fields: list[str]) -> list[str]:
    """MED field names: NOM_CHAM_MED (one per field), else NOM_RESU_MED or
    the concept name, padded to 8 with ``_``, followed by the field name."""
    given = as_tuple(occ.get("NOM_CHAM_MED"))
    if given:
        if len(given) != len(fields):
            ctx.error(
                f"NOM_CHAM_MED gives {len(given)} names for {len(fields)} fields",
                "NOM_CHAM_MED",
                occ,
            )
        return [str(g) for g in given]
    prefix = occ.get("NOM_RESU_MED") or default_prefix
    return [med_field_name(prefix, f) for f in fields]


def result_series(ctx, occ, result) -> list[NodalSeries]:
    fields = field_names(ctx, occ, result)
    names = med_names(ctx, occ, result.name or "RESU", fields)
    steps = result_steps(result)
    times = steps.time_values()
    out = []
    chosen = occ.get("NOM_CHAM") is not None and occ.get("TOUT_CHAM") != "OUI"
    for field, med_name in zip(fields, names, strict=True):
        if is_element_field(result, field):
            if not chosen and not med_writable(result, field):
                ctx.log(f"element field {field} not written (Gauss points of its cells)")
                continue
            cells, comps, values, indices = element_block(ctx, occ, result, field)
            out.append(
                ElementSeries(
                    med_name,
                    element_location(field),
                    cells,
                    comps,
                    values,
                    times[indices],
                    steps.orders[indices],
                )
            )
            continue
        nodes, comps, values, indices = result_block(ctx, occ, result, field)
        out.append(
            NodalSeries(med_name, comps, values, times[indices], steps.orders[indices], nodes)
        )
    return out


def med_writable(result, name: str) -> bool:
    """False for Gauss-point fields on cells whose Gauss points MED cannot
    locate here (only segments are known)."""
    if element_location(name) != "ELGA":
        return True
    mesh = result_mesh(result)
    cells = result.element_fields[name].cells
    return all(mesh.cell_types[int(c)].startswith("SEG") for c in cells)


def cham_elem_series(ctx, occ, field: FieldOnElements) -> ElementSeries:
    cells, comps, values = cham_elem_block(ctx, occ, field)
    given = as_tuple(occ.get("NOM_CHAM_MED"))
    name = str(given[0]) if given else (occ.get("NOM_RESU_MED") or field.name or "CHAMP")
    location = cham_elem_location(field)
    return ElementSeries(name, location, cells, comps, values, np.zeros(1), np.array([-1]))


def cham_gd_series(ctx, occ, field: NodalField) -> NodalSeries:
    nodes, comps, values = nodal_field_block(ctx, occ, field)
    given = as_tuple(occ.get("NOM_CHAM_MED"))
    name = str(given[0]) if given else (occ.get("NOM_RESU_MED") or field.name or "CHAMP")
    return NodalSeries(name, comps, values, np.zeros(1), np.array([-1]), nodes)


def mesh_summary(mesh: Mesh, name: str) -> str:
    counts = {t: mesh.cell_types.count(t) for t in dict.fromkeys(mesh.cell_types)}
    cells = ", ".join(f"{n} {t}" for t, n in counts.items()) or "no cell"
    return (
        f"mesh {name}: {mesh.n_nodes} nodes, {cells}; "
        f"{len(mesh.node_groups)} node groups, {len(mesh.cell_groups)} cell groups"
    )


# =============================================================================
# RESULTAT (text)
# =============================================================================

RULE = " " + "=" * 78


def write_text_format(ctx, kw) -> None:
    path = ctx.session.output_path(int(kw.get("UNITE", 8)))
    lines: list[str] = []
    for occ in kw.factor("RESU"):
        lines.extend(text_occurrence(ctx, occ))
    write_lines(path, lines)  # text units accumulate, as for IMPR_TABLE
    ctx.log(f"RESULTAT listing written to {path.name} ({len(lines)} lines)")


def text_occurrence(ctx, occ) -> list[str]:
    if occ.get("BORNE_SUP") is not None or occ.get("BORNE_INF") is not None:
        key = "BORNE_SUP" if occ.get("BORNE_SUP") is not None else "BORNE_INF"
        ctx.unsupported("BORNE_SUP / BORNE_INF", key, occ)
    if occ.get("FORM_TABL", "NON") != "NON" and occ.get("RESULTAT") is None:
        ctx.unsupported("FORM_TABL without RESULTAT", "FORM_TABL", occ)
    real_format = fortran_format(occ.get("FORMAT_R", "1PE21.14"))
    lines = [RULE]
    if occ.get("SOUS_TITRE"):
        lines.append(f" {occ['SOUS_TITRE']}")
    result, field = occ.get("RESULTAT"), occ.get("CHAM_GD")
    if result is not None:
        if not (is_physical_result(result) or isinstance(result, DynaHarmo)):
            ctx.unsupported(f"IMPR_RESU of a {result.aster_type}", "RESULTAT", occ)
        return lines + result_text(ctx, occ, result, real_format)
    if isinstance(field, FieldOnElements):
        cells, comps, values = cham_elem_block(ctx, occ, field)
        location = cham_elem_location(field)
        lines.append(f" {ELEMENT_TITLES[location]} {field.name or ''}".rstrip())
        return lines + element_lines(field.mesh, cells, location, comps, values[0], real_format)
    if field is not None:
        if not isinstance(field, NodalField):
            ctx.unsupported(f"CHAM_GD of type {field.aster_type}", "CHAM_GD", occ)
        nodes, comps, values = nodal_field_block(ctx, occ, field)
        lines.append(f" CHAMP AUX NOEUDS {field.name or ''}")
        mesh = field.numbering.mesh
        carried = carried_components(field.numbering, nodes, comps)
        return lines + node_lines(occ, mesh, nodes, comps, values[0], real_format, carried)
    mesh = occ["MAILLAGE"]
    return lines + aster_mesh_lines(mesh)


def fortran_format(spec: str) -> str:
    """``1PE21.14`` -> ``E21.14`` (the scale factor is implied by E formats here)."""
    spec = spec.strip().upper()
    if "P" in spec:
        spec = spec.split("P", 1)[1]
    return spec if spec[:1] in ("E", "D", "F") else "E21.14"


def result_text(ctx, occ, result, real_format: str) -> list[str]:
    steps = result_steps(result)
    fields = field_names(ctx, occ, result)
    lines = [f" RESULTAT {result.name or ''} ({result.aster_type})"]
    blocks = {
        f: element_block(ctx, occ, result, f)
        if is_element_field(result, f)
        else result_block(ctx, occ, result, f)
        for f in fields
    }
    indices = chosen_steps(ctx, occ, steps)
    params = parameter_names(ctx, occ, result, steps)
    if params and occ.get("FORM_TABL", "NON") != "NON":
        lines.extend(parameter_table(result, steps, indices, params))
        params = []
    part = occ.get("PARTIE")
    for field, (nodes, comps, values, chosen) in list(blocks.items()):
        if part is not None:
            blocks[field] = (nodes, comps, complex_part(values, part), chosen)
        elif np.iscomplexobj(values) and "OUI" in (occ.get("VALE_MAX"), occ.get("VALE_MIN")):
            key = "VALE_MAX" if occ.get("VALE_MAX") == "OUI" else "VALE_MIN"
            ctx.unsupported(f"{key} of a complex field (give PARTIE)", key, occ)
    mesh = result_mesh(result)
    for k, step in enumerate(indices):
        for field, (nodes, comps, values, _) in blocks.items():
            element = is_element_field(result, field)
            location = element_location(field)
            lines.append(" " + "-" * 78)
            title = ELEMENT_TITLES[location] if element else "CHAMP AUX NOEUDS"
            lines.append(f" {title} DE NOM SYMBOLIQUE  {field}")
            lines.append(step_header(steps, step))
            shown = steps.parameters(step)
            lines.extend(
                f" {p}: {format_parameter(v)}"
                for p, v in step_parameters(result, steps, step, params).items()
                if p not in shown
            )
            lines.append("")
            if element:
                lines.extend(element_lines(mesh, nodes, location, comps, values[k], real_format))
            else:
                carried = carried_components(result.numbering, nodes, comps, field, result)
                lines.extend(node_lines(occ, mesh, nodes, comps, values[k], real_format, carried))
    return lines


def carried_components(numbering, nodes, comps, field=None, result=None) -> np.ndarray | None:
    """(n_nodes, n_comp) mask of the components each node carries in the
    numbering of a DOF field (code_aster lists only those, ircnrl); None for
    a field not on the numbering's DOFs (a smoothed ``*_NOEU`` field)."""
    if field is not None and field not in getattr(result, "fields", {}):
        return None
    present = set(numbering.dofs)
    return np.array([[(int(n), c) in present for c in comps] for n in nodes], dtype=bool)


ELEMENT_TITLES = {
    "ELNO": "CHAMP PAR ELEMENT AUX NOEUDS",
    "ELGA": "CHAMP PAR ELEMENT AUX POINTS DE GAUSS",
}


def element_lines(mesh: Mesh, cells, location: str, comps, values, real_format: str) -> list:
    """One block per cell (``MAILLE name``), then one line per element node
    (ELNO: the node's name) or Gauss point (ELGA: its number) with the
    component values; ``values`` is (n_cells, n_points, n_comp), padded with
    NaN past a cell's own points (a point cell among segments, fewer Gauss
    points): only the cell's own points are listed, as code_aster does."""
    width = len(fortran_real(0.0, real_format))
    first = "NOEUD" if location == "ELNO" else "POINT"
    header = f"  {first:<8}" + "".join(f" {c:>{width}}" for c in comps)
    lines: list[str] = []
    for k, cell in enumerate(cells):
        lines.append(f" MAILLE {mesh.cell_names[int(cell)]}")
        lines.append(header)
        connectivity = mesh.cell_nodes[int(cell)]
        for point in range(_own_points(values[k], location, len(connectivity))):
            name = mesh.node_names[int(connectivity[point])] if location == "ELNO" else point + 1
            for label, row in _value_rows(str(name), values[k, point]):
                numbers = "".join(f" {fortran_real(float(v) + 0.0, real_format)}" for v in row)
                lines.append(f"  {label!s:<8}" + numbers)
    return lines


def _own_points(values, location: str, n_nodes: int) -> int:
    """How many of the (n_points, n_comp) rows of one cell are its own: its
    nodes for ELNO; for ELGA the rows up to the last one holding a value
    (the padding of cells with fewer Gauss points is NaN throughout)."""
    if location == "ELNO":
        return min(values.shape[0], n_nodes)
    held = np.flatnonzero(~np.all(np.isnan(np.asarray(values)), axis=1))
    return int(held[-1]) + 1 if held.size else 0


def _value_rows(label: str, values) -> list:
    """The printed rows of one point: its values, or for complex values the
    real parts then, on an unlabelled row, the imaginary parts (ircnc8)."""
    values = np.asarray(values)
    if np.iscomplexobj(values):
        return [(label, values.real), ("", values.imag)]
    return [(label, values)]


def step_header(steps, step: int) -> str:
    text = f" NUMERO D'ORDRE: {int(steps.orders[step]):8d}"
    for name, value in steps.parameters(step).items():
        text += f" {name}: {format_parameter(value)}"
    return text


def format_parameter(value) -> str:
    if isinstance(value, float | np.floating):
        return fortran_real(float(value), "E12.5").strip()
    return str(value)


def all_parameters(result, steps, step: int) -> dict:
    out = steps.parameters(step)
    if isinstance(result, ModeResult):
        for name, values in result.parameters.items():
            values = np.asarray(values)
            if values.shape[:1] == (result.n_modes,) and values.ndim == 1:
                value = values[step]
                out[name] = value.item() if isinstance(value, np.generic) else value
    return out


def parameter_names(ctx, occ, result, steps) -> list[str]:
    if occ.get("TOUT_PARA") == "OUI":
        return list(all_parameters(result, steps, 0)) if steps.count else []
    names = list(as_tuple(occ.get("NOM_PARA")))
    known = all_parameters(result, steps, 0) if steps.count else {}
    for name in names:
        if name not in known:
            ctx.error(
                f"the result has no parameter {name} (it has {', '.join(known)})", "NOM_PARA", occ
            )
    return names


def step_parameters(result, steps, step: int, names) -> dict:
    values = all_parameters(result, steps, step)
    return {n: values[n] for n in names}


def parameter_table(result, steps, indices, params) -> list[str]:
    table = Table()
    for step in indices:
        row = {"NUME_ORDRE": int(steps.orders[step])}
        row.update(step_parameters(result, steps, step, params))
        table.add_row(row)
    return table_lines(table)


def node_lines(occ, mesh: Mesh, nodes, comps, values, real_format: str, carried=None) -> list:
    """One line per node: name, coordinates (IMPR_COOR), component values;
    then the extrema of each component (VALE_MAX / VALE_MIN). With
    ``carried`` (n_nodes, n_comp) a node lists only the components it
    carries, under a header repeated whenever that set changes (ircnrl)."""
    width = len(fortran_real(0.0, real_format))
    coords = occ.get("IMPR_COOR") == "OUI"
    axes = ("COOR_X", "COOR_Y", "COOR_Z")[: max(1, min(mesh.dim, 3))]
    if carried is None:
        carried = np.ones((len(nodes), len(comps)), dtype=bool)
    lines: list[str] = []
    shown = None
    for k, node in enumerate(nodes):
        own = tuple(np.flatnonzero(carried[k]))
        if not own:
            continue
        if own != shown:
            names = (*(axes if coords else ()), *(comps[j] for j in own))
            lines.append(" NOEUD   " + "".join(f" {c:>{width}}" for c in names))
            shown = own
        place = [fortran_real(float(x), real_format) for x in mesh.coords[node, : len(axes)]]
        for label, row in _value_rows(mesh.node_names[node], np.asarray(values[k])[list(own)]):
            cells = place if coords else []
            cells = cells + [fortran_real(float(v) + 0.0, real_format) for v in row]
            lines.append(f" {label:<8}" + "".join(f" {c}" for c in cells))
    if not lines:
        lines.append(" NOEUD   " + "".join(f" {c:>{width}}" for c in comps))
    for key, pick in (("VALE_MAX", np.argmax), ("VALE_MIN", np.argmin)):
        if occ.get(key) == "OUI" and len(nodes):
            lines.append("")
            for j, comp in enumerate(comps):
                held = np.flatnonzero(carried[:, j])
                if held.size == 0:
                    continue
                k = int(held[pick(values[held, j])])
                lines.append(
                    f" {key} {comp:<8} {fortran_real(float(values[k, j]), real_format)} "
                    f"NOEUD {mesh.node_names[nodes[k]]}"
                )
    return lines


# =============================================================================
# ASTER mesh format
# =============================================================================


def write_aster_format(ctx, kw) -> None:
    path = ctx.session.output_path(int(kw.get("UNITE", 26)))
    lines: list[str] = []
    for occ in kw.factor("RESU"):
        if occ.get("RESULTAT") is not None or occ.get("CHAM_GD") is not None:
            ctx.unsupported("fields in FORMAT='ASTER' (meshes only)", "RESULTAT", occ)
        lines.extend(aster_mesh_lines(occ["MAILLAGE"]))
    write_lines(path, lines)
    ctx.log(f"ASTER mesh written to {path.name}")


def aster_mesh_lines(mesh: Mesh) -> list[str]:
    """The mesh in code_aster's text format (TITRE, COOR_nD, one section per
    cell type in mesh order, GROUP_NO, GROUP_MA, FIN)."""
    dim = max(1, min(int(mesh.dim), 3))
    lines = ["TITRE", f" {mesh.name or 'MAILLAGE'} {mesh.title}".rstrip(), "FINSF", "%"]
    lines.append(f"COOR_{dim}D")
    for name, xyz in zip(mesh.node_names, mesh.coords, strict=True):
        lines.append(f" {name:<8}" + "".join(f" {x:23.15E}" for x in xyz[:dim]))
    lines += ["FINSF", "%"]
    start = 0
    while start < mesh.n_cells:
        kind = mesh.cell_types[start]
        stop = start
        while stop < mesh.n_cells and mesh.cell_types[stop] == kind:
            stop += 1
        lines.append(kind)
        for c in range(start, stop):
            nodes = " ".join(mesh.node_names[n] for n in mesh.cell_nodes[c])
            lines.append(f" {mesh.cell_names[c]:<8} {nodes}")
        lines += ["FINSF", "%"]
        start = stop
    for section, groups, names in (
        ("GROUP_NO", mesh.node_groups, mesh.node_names),
        ("GROUP_MA", mesh.cell_groups, mesh.cell_names),
    ):
        for group, members in groups.items():
            lines += [section, f" {group}"]
            lines += [f" {names[int(i)]}" for i in members]
            lines += ["FINSF", "%"]
    lines.append("FIN")
    return lines
