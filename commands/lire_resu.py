"""LIRE_RESU: a result built from fields of a MED file (universal files:
datasets 55 below, datasets 58 in lire_resu_ds58).

FORMAT='MED', TYPE_RESU 'MODE_MECA' or 'DYNA_TRANS', nodal fields (DEPL,
VITE, ACCE) named by NOM_CHAM_MED or by the prefix NOM_RESU (code_aster's
naming: the result name on 8 characters padded with '_', then the field),
components renamed by NOM_CMP / NOM_CMP_MED. As code_aster's lrfmed:

- TOUT_ORDRE / NUME_ORDRE / LIST_ORDRE pick steps by order number (the
  file's order, else its iteration); INST / FREQ (and their lists) pick the
  step whose time matches within CRITERE / PRECISION, and the steps read are
  then numbered 1, 2, ...;
- the time of each step becomes the result's INST (DYNA_TRANS) or FREQ
  (MODE_MECA);
- values lay on the DOFs of MATR_RIGI's (or MATR_MASS's) numbering, or of the
  MODELE's, or else on the nodes and components the file gives;
  PROL_ZERO='OUI' puts zero where the file has no value.

A MODE_MECA read this way keeps the matrices it is given; its generalized
masses and stiffnesses are computed from them (zero without them).
"""

from __future__ import annotations

import numpy as np
from asterlite.commands import lire_resu_ds58

from asterlite.concepts.assembly import DofNumbering
from asterlite.concepts.harmonic import DynaHarmo
from asterlite.concepts.modes import ModeResult
from asterlite.concepts.transient import DynaTrans
from asterlite.fem.dofs import sort_components
from asterlite.io.ideas_result import IdeasReadError, read_datasets_55, record_field
from asterlite.io.med_result import MedResultError, read_nodal_field
from asterlite.io.med_writer import med_field_name
from asterlite.post.restitution import as_tuple

_NODAL = ("DEPL", "VITE", "ACCE")


def run(ctx, kw):
    if kw["FORMAT"] == "IDEAS":
        return _read_ideas(ctx, kw)
    if kw["FORMAT"] == "IDEAS_DS58":
        return lire_resu_ds58.read(ctx, kw, _input(ctx, kw))
    if kw["FORMAT"] != "MED":
        ctx.unsupported(f"LIRE_RESU FORMAT={kw['FORMAT']!r}", "FORMAT", kw)
    kind = kw["TYPE_RESU"]
    if kind not in ("MODE_MECA", "DYNA_TRANS"):
        ctx.unsupported(f"LIRE_RESU TYPE_RESU={kind!r}", "TYPE_RESU", kw)
    if kw.get("RESULTAT") is not None:
        ctx.unsupported("LIRE_RESU into an existing result (reuse)", "RESULTAT", kw)
    kw.mark_used("INFO", "TITRE", "CHAM_MATER", "CARA_ELEM")  # recorded by code_aster only
    path = _input(ctx, kw)
    fields = {}
    for occ in kw.factor("FORMAT_MED"):
        name = occ["NOM_CHAM"]
        if name not in _NODAL:
            ctx.unsupported(
                f"LIRE_RESU of field {name} (nodal DEPL, VITE, ACCE only)", "NOM_CHAM", occ
            )
        med_name = occ.get("NOM_CHAM_MED") or med_field_name(occ["NOM_RESU"], name)
        try:
            field = read_nodal_field(path, med_name)
        except MedResultError as exc:
            ctx.error(str(exc), "NOM_CHAM_MED" if occ.get("NOM_CHAM_MED") else "NOM_RESU", occ)
        fields[name] = (field, _component_names(ctx, occ, field))
    mesh = kw["MAILLAGE"] if kw.get("MAILLAGE") is not None else kw["MODELE"].mesh
    for field, _ in fields.values():
        if field.n_mesh_nodes != mesh.n_nodes:
            ctx.error(
                f"field {field.name} lies on {field.n_mesh_nodes} nodes, "
                f"the mesh has {mesh.n_nodes}",
                "MAILLAGE" if kw.get("MAILLAGE") is not None else "MODELE",
                kw,
            )
    first = next(iter(fields.values()))[0]
    picked, orders, times = _select_steps(ctx, kw, first)
    numbering = _numbering(ctx, kw, mesh, fields)
    arrays = {
        name: _values(ctx, kw, numbering, field, comps, picked)
        for name, (field, comps) in fields.items()
    }
    if kind == "MODE_MECA":
        return _modes(ctx, kw, numbering, arrays, orders, times)
    return DynaTrans(numbering=numbering, times=times, order=orders, fields=arrays)


def _input(ctx, kw):
    try:
        return ctx.session.input_path(kw["UNITE"])
    except (KeyError, FileNotFoundError, LookupError) as exc:
        ctx.error(f"no file is mapped to logical unit {kw['UNITE']} ({exc})", "UNITE", kw)


def _component_names(ctx, occ, field) -> dict[str, str]:
    """MED component name -> code_aster component name."""
    aster = as_tuple(occ.get("NOM_CMP"))
    med = as_tuple(occ.get("NOM_CMP_MED"))
    if len(aster) != len(med):
        ctx.error("NOM_CMP and NOM_CMP_MED must have as many names", "NOM_CMP", occ)
    renamed = dict(zip(med, aster, strict=True))
    missing = [c for c in med if c not in field.components]
    if missing:
        ctx.error(f"field {field.name} has no component {missing[0]}", "NOM_CMP_MED", occ)
    if renamed:
        return renamed
    return {c: c for c in field.components}


def _store_number(step) -> int:
    return step.order if step.order != -1 else step.iteration


def _select_steps(ctx, kw, field):
    """Indices of the file's steps to read, their order numbers and times."""
    steps = field.steps
    numbers = [_store_number(s) for s in steps]
    wanted_orders = kw.get("NUME_ORDRE") or kw.get("LIST_ORDRE")
    if wanted_orders is not None:
        wanted = [int(n) for n in _values_of(wanted_orders)]
        picked = []
        for number in wanted:
            if number not in numbers:
                ctx.log(f"<A> order {number} is not in field {field.name}: skipped")
                continue
            picked.append(numbers.index(number))
        return picked, np.array([numbers[i] for i in picked]), _times(steps, picked)
    wanted_times = next(
        (kw.get(k) for k in ("INST", "LIST_INST", "FREQ", "LIST_FREQ") if kw.get(k) is not None),
        None,
    )
    if wanted_times is None:
        kw.mark_used("TOUT_ORDRE")  # every step: what the selection rule leaves
        picked = list(range(len(steps)))
        return picked, np.array(numbers), _times(steps, picked)
    precision, relative = kw["PRECISION"], kw["CRITERE"] == "RELATIF"
    picked, times = [], []
    for value in _values_of(wanted_times):
        tolerance = abs(precision * value) if relative else abs(precision)
        match = next((i for i, s in enumerate(steps) if abs(s.time - value) <= tolerance), None)
        if match is None:
            ctx.error(f"no step of field {field.name} at {value:g}", None, kw)
        picked.append(match)
        times.append(float(value))  # code_aster stores the asked value
    return picked, np.arange(1, len(picked) + 1), np.array(times)


def _values_of(value):
    values = getattr(value, "values", value)
    return [v for v in np.atleast_1d(np.asarray(values)).ravel()]


def _times(steps, picked) -> np.ndarray:
    return np.array([steps[i].time for i in picked], dtype=float)


def _numbering(ctx, kw, mesh, fields) -> DofNumbering:
    matrix = kw.get("MATR_RIGI") or kw.get("MATR_MASS")
    if matrix is not None:
        return matrix.numbering
    if kw.get("MODELE") is not None:
        from asterlite.commands.nume_ddl import numbering_for

        return numbering_for(kw["MODELE"], [])
    per_node: dict[int, set] = {}
    for field, comps in fields.values():
        for step in field.steps:
            for node in step.nodes:
                per_node.setdefault(int(node), set()).update(comps.values())
    dofs = [(n, c) for n in sorted(per_node) for c in sort_components(per_node[n])]
    return DofNumbering(mesh=mesh, dofs=dofs)


def _values(ctx, kw, numbering, field, comps, picked) -> np.ndarray:
    """(n_steps, n_dofs) values on the numbering; zero where the file has none
    (PROL_ZERO='OUI'), refused otherwise."""
    out = np.zeros((len(picked), numbering.n_dofs))
    filled = np.zeros((len(picked), numbering.n_dofs), dtype=bool)
    med_index = {aster: field.components.index(med) for med, aster in comps.items()}
    for row, i in enumerate(picked):
        step = field.steps[i]
        for k, node in enumerate(step.nodes):
            for aster, column in med_index.items():
                dof = numbering.index.get((int(node), aster))
                if dof is not None:
                    out[row, dof] = step.values[k, column]
                    filled[row, dof] = True
    if not np.all(np.isfinite(out)):
        ctx.error(f"field {field.name} holds a non-finite value", "UNITE", kw)
    if kw.get("PROL_ZERO", "OUI") == "NON" and not filled.all():
        dof = numbering.dofs[int(np.argmax(~filled.any(axis=0)))]
        ctx.unsupported(
            f"PROL_ZERO='NON' with DOFs the file does not give (node "
            f"{numbering.mesh.node_names[dof[0]]} {dof[1]}): code_aster leaves them undefined",
            "PROL_ZERO",
            kw,
        )
    return out


def _modes(ctx, kw, numbering, arrays, orders, times) -> ModeResult:
    if "DEPL" not in arrays:
        ctx.error("a MODE_MECA needs the DEPL field", "FORMAT_MED", kw)
    shapes = arrays["DEPL"].T.copy()
    stiffness, mass = kw.get("MATR_RIGI"), kw.get("MATR_MASS")
    if mass is not None and stiffness is not None and mass.numbering is not stiffness.numbering:
        ctx.error("MATR_MASS and MATR_RIGI must share their numbering", "MATR_MASS", kw)
    gen_mass = _quadratic(mass, shapes)
    gen_stiff = _quadratic(stiffness, shapes)
    modes = ModeResult(
        numbering=numbering,
        shapes=shapes,
        frequencies=np.asarray(times, dtype=float),
        generalized_mass=gen_mass,
        generalized_stiffness=gen_stiff,
        mass=mass,
        stiffness=stiffness,
    )
    modes.parameters["NUME_MODE"] = np.asarray(orders, dtype=int)
    ctx.log(f"{shapes.shape[1]} modes read on {numbering.n_dofs} DOFs")
    return modes


def _quadratic(matrix, shapes) -> np.ndarray:
    if matrix is None:
        return np.zeros(shapes.shape[1])
    return np.einsum("im,im->m", shapes, matrix.matrix @ shapes)


# ----------------------------------------------------------------------------- IDEAS

# record 6's data type of each field (code_aster's lridea, when RECORD_6 is not given)
_IDEAS_TYPES = {8: "DEPL", 11: "VITE", 12: "ACCE", 5: "TEMP", 15: "PRES"}


def _read_ideas(ctx, kw):
    """FORMAT='IDEAS' (code_aster's lridea), nodal datasets 55 into a
    DYNA_HARMO or a DYNA_TRANS: each FORMAT_IDEAS occurrence names the field
    its datasets hold (RECORD_3 / RECORD_6 / RECORD_9 values to match, else
    record 6's data type), where the order number (POSI_ORDRE: record,
    field) and the frequency or instant (POSI_FREQ / POSI_INST) are, and the
    components of the value slots (NOM_CMP); nodes are found by the name
    N<label>, else by number. The orders stored are the file's."""

    kind = kw["TYPE_RESU"]
    if kind not in ("DYNA_HARMO", "DYNA_TRANS", "MODE_MECA"):
        ctx.unsupported(f"LIRE_RESU FORMAT='IDEAS' TYPE_RESU={kind!r}", "TYPE_RESU", kw)
    if kw.get("RESULTAT") is not None:
        ctx.unsupported("LIRE_RESU into an existing result (reuse)", "RESULTAT", kw)
    kw.mark_used("INFO", "TITRE", "CHAM_MATER", "CARA_ELEM")  # recorded by code_aster only
    access = "INST" if kind == "DYNA_TRANS" else "FREQ"
    mesh = kw["MAILLAGE"] if kw.get("MAILLAGE") is not None else kw["MODELE"].mesh
    wanted = list(as_tuple(kw["NOM_CHAM"]))
    occurrences = {occ["NOM_CHAM"]: occ for occ in kw.factor("FORMAT_IDEAS")}
    for name in wanted:
        if name not in occurrences:
            occurrences[name] = _ideas_default_format(ctx, kw, name)
    try:
        datasets = read_datasets_55(_input(ctx, kw))
    except (IdeasReadError, ValueError, IndexError) as exc:
        ctx.error(f"the file is not a readable universal file: {exc}", "UNITE", kw)
    read: dict[str, dict[int, tuple[float, dict]]] = {}
    mode_parameters: dict[int, dict[str, float]] = {}
    for name in wanted:
        occ = occurrences[name]
        if occ.get("NUME_DATASET", 55) != 55:
            ctx.unsupported(f"NUME_DATASET={occ['NUME_DATASET']}", "NUME_DATASET", occ)
        position = occ.get(f"POSI_{access}")
        if position is None:
            ctx.error(f"a {kind} needs POSI_{access}", f"POSI_{access}", occ)
        components = as_tuple(occ["NOM_CMP"])
        read[name] = {}
        for dataset in datasets:
            if not _ideas_matches(occ, dataset, name):
                continue
            try:
                order = int(record_field(dataset["records"], *occ["POSI_ORDRE"]))
                value = float(record_field(dataset["records"], *position).replace("D", "E"))
                if kind == "MODE_MECA":
                    mode_parameters[order] = _ideas_mode_parameters(occ, dataset["records"])
            except (IdeasReadError, ValueError) as exc:
                ctx.error(str(exc), "POSI_ORDRE", occ)
            by_node = {}
            for label, file_name, row in zip(
                dataset["labels"], dataset["names"], dataset["values"], strict=True
            ):
                node = _ideas_node(ctx, occ, mesh, int(label), file_name)
                by_node[node] = {c: row[k] for k, c in enumerate(components) if k < row.size}
            read[name][order] = (value, by_node)
    orders = sorted(set().union(*(set(v) for v in read.values())))
    if not orders:
        ctx.error("no dataset of the file matches FORMAT_IDEAS", "FORMAT_IDEAS", kw)
    picked = _ideas_selection(ctx, kw, orders, read)
    numbering = _ideas_numbering(kw, mesh, read)
    complex_values = kind == "DYNA_HARMO"
    fields = {}
    for name, steps in read.items():
        values = np.zeros(
            (len(picked), numbering.n_dofs), dtype=complex if complex_values else float
        )
        for row, order in enumerate(picked):
            if order not in steps:
                ctx.error(f"field {name} has no dataset of order {order}", "FORMAT_IDEAS", kw)
            for node, comps in steps[order][1].items():
                for component, value in comps.items():
                    dof = numbering.index.get((node, component))
                    if dof is not None:
                        values[row, dof] = value if complex_values else np.real(value)
        fields[name] = values
    parameters = np.array([next(iter(read.values()))[o][0] for o in picked], dtype=float)
    orders = np.asarray(picked, dtype=int)
    if kind == "MODE_MECA":
        return _ideas_modes(
            ctx, kw, numbering, fields, parameters, [mode_parameters[o] for o in picked]
        )
    ctx.log(f"{len(fields)} fields at {len(picked)} orders read on {numbering.n_dofs} DOFs")
    if complex_values:
        return DynaHarmo(numbering=numbering, frequencies=parameters, order=orders, fields=fields)
    return DynaTrans(numbering=numbering, times=parameters, order=orders, fields=fields)


def _ideas_mode_parameters(occ, records) -> dict[str, float]:
    """NUME_MODE, MASS_GENE and the damping of a mode's dataset (POSI_*),
    zero where the occurrence does not place them, as code_aster's lridea;
    code_aster stores the damping read at POSI_AMOR_GENE as AMOR_REDUIT."""
    out = {}
    for key, name in (
        ("POSI_NUME_MODE", "NUME_MODE"),
        ("POSI_MASS_GENE", "MASS_GENE"),
        ("POSI_AMOR_GENE", "AMOR_REDUIT"),
    ):
        position = occ.get(key)
        text = record_field(records, *position).replace("D", "E") if position else "0"
        out[name] = int(float(text)) if name == "NUME_MODE" else float(text)
    return out


def _ideas_modes(ctx, kw, numbering, fields, frequencies, parameters) -> ModeResult:
    """A MODE_MECA read from datasets 55: the DEPL shapes, FREQ, and the
    file's NUME_MODE, MASS_GENE and AMOR_REDUIT; MATR_RIGI / MATR_MASS are
    the matrices the modes refer to (RIGI_GENE from them, as for MED)."""
    if "DEPL" not in fields:
        ctx.error("a MODE_MECA needs the DEPL field", "NOM_CHAM", kw)
    modes = _modes(ctx, kw, numbering, fields, np.zeros(len(parameters), dtype=int), frequencies)
    modes.generalized_mass = np.array([p["MASS_GENE"] for p in parameters], dtype=float)
    modes.parameters["NUME_MODE"] = np.array([p["NUME_MODE"] for p in parameters], dtype=int)
    modes.parameters["AMOR_REDUIT"] = np.array([p["AMOR_REDUIT"] for p in parameters], dtype=float)
    return modes


def _ideas_default_format(ctx, kw, name: str) -> dict:
    """code_aster's format of a field that FORMAT_IDEAS does not describe
    (its crsdfi): nodal datasets 55 for the fields asterlite reads."""
    for prefix, (record_6, components) in _IDEAS_DEFAULT_FORMATS.items():
        if name.startswith(prefix):
            return {
                "NOM_CHAM": name,
                "NUME_DATASET": 55,
                "RECORD_6": record_6,
                "POSI_ORDRE": (7, 4),
                "POSI_INST": (8, 1),
                "POSI_FREQ": (8, 1),
                "NOM_CMP": components,
            }
    ctx.unsupported(
        f"LIRE_RESU IDEAS of {name} without FORMAT_IDEAS: code_aster's default format of "
        "this field is an element dataset (57), which asterlite does not read",
        "FORMAT_IDEAS",
        kw,
    )


# code_aster's default record 6 (None: any value) and components per field
_TRANSLATIONS = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")
_IDEAS_DEFAULT_FORMATS = {
    "DEPL": ((1, None, 3, 8, 2, 6), _TRANSLATIONS),
    "VITE": ((1, None, 3, 11, 2, 6), _TRANSLATIONS),
    "ACCE": ((1, None, 3, 12, 2, 6), _TRANSLATIONS),
    "TEMP": ((2, 4, 1, 5, 2, 1), ("TEMP",)),
}


def _ideas_matches(occ, dataset, name) -> bool:
    records = dataset["records"]
    given = False
    for record in (3, 6, 9):
        values = occ.get(f"RECORD_{record}")
        if values is None or record > len(records):
            continue
        given = True
        tokens = records[record - 1].split()
        for k, value in enumerate(as_tuple(values)):
            if value is None:
                continue
            if k >= len(tokens) or int(float(tokens[k])) != int(value):
                return False
    if given:
        return True
    data_type = int(records[5].split()[3])
    return _IDEAS_TYPES.get(data_type, "")[:3] == name[:3]


def _ideas_node(ctx, occ, mesh, label: int, file_name: str) -> int:
    node = mesh.find_node(f"N{label}")
    if node is not None:
        return int(node)
    if not 1 <= label <= mesh.n_nodes or mesh.node_names[label - 1] != file_name:
        ctx.error(f"node {label} ({file_name}) of the file is not a node of the mesh", "UNITE", occ)
    return label - 1


def _ideas_selection(ctx, kw, orders, read) -> list[int]:
    """The orders to keep: TOUT_ORDRE, NUME_ORDRE / LIST_ORDRE, or the
    parameter values (INST / FREQ lists within PRECISION)."""
    wanted = kw.get("NUME_ORDRE") or kw.get("LIST_ORDRE")
    if wanted is not None:
        return [o for o in (int(v) for v in _values_of(wanted)) if o in orders]
    values = next(
        (kw.get(k) for k in ("INST", "LIST_INST", "FREQ", "LIST_FREQ") if kw.get(k) is not None),
        None,
    )
    if values is None:
        kw.mark_used("TOUT_ORDRE")  # every order: what the selection rule leaves
        return list(orders)
    first = next(iter(read.values()))
    precision, relative = kw["PRECISION"], kw["CRITERE"] == "RELATIF"
    picked = []
    for value in _values_of(values):
        tolerance = abs(precision * value) if relative else abs(precision)
        match = [o for o in orders if o in first and abs(first[o][0] - value) <= tolerance]
        if not match:
            ctx.error(f"no dataset at {value:g}", None, kw)
        picked.append(match[0])
    return picked


def _ideas_numbering(kw, mesh, read) -> DofNumbering:
    matrix = kw.get("MATR_RIGI") or kw.get("MATR_MASS")
    if matrix is not None:
        return matrix.numbering
    if kw.get("MODELE") is not None:
        from asterlite.commands.nume_ddl import numbering_for

        return numbering_for(kw["MODELE"], [])
    per_node: dict[int, set] = {}
    for steps in read.values():
        for _, by_node in steps.values():
            for node, comps in by_node.items():
                per_node.setdefault(node, set()).update(comps)
    dofs = [(n, c) for n in sorted(per_node) for c in sort_components(per_node[n])]
    return DofNumbering(mesh=mesh, dofs=dofs)
