"""Results as data: uniform access to the nodal fields of result concepts,
and an HDF5 store for generalized transient results (``tran_gene``).

Nodal fields of results
-----------------------
:func:`result_steps` and :func:`nodal_series` read ``dyna_trans``
(:class:`DynaTrans`), ``mode_meca`` (:class:`ModeResult`) and ``mult_elas``
(:class:`MultElasResult`) results the same way: the stored steps (NUME_ORDRE
with INST, or NUME_MODE and FREQ, or NOM_CAS) and any nodal field as an array
(n_steps, n_nodes, n_components). IMPR_RESU, POST_RELEVE_T and the store use
them.

HDF5 store
----------
:func:`save_tran_gene` writes one ``tran_gene`` under a group named after
it; :func:`load_tran_gene` reads it back as a :class:`TranGene` (or plain
arrays); :func:`save_session_results` saves every ``tran_gene`` of a deck
namespace. A save never leaves a partly written file: it writes a temporary
copy next to the target and renames it over the target once complete. The
layout is described in ``docs/results.md``::

    /<NAME>                         attrs: aster_type, layout_version, scheme, step,
                                           n_modes, n_archived
      times, order                  (n_archived,)
      depl, vite, acce              (n_archived, n_modes)
      scheme/                       attrs: every scalar of the integration summary
      shocks/<INTITULE>/            attrs: name, relation, node_1, node_2, index, parameters
        FN, FT1, ..., VINT20        (n_archived,)
      basis/                        attrs: basis_type, name, ...; what depends on the
                                    kind of basis (asterlite.io.basis_store):
        (mode_meca, mode_flamb, mode_meca_c: a physical basis)
        shapes                      (n_dofs, n_modes)
        dof_nodes, dof_components   (n_dofs,)  node index (0-based) and component name
        dof_labels                  (n_dofs,)  "NODE COMPONENT"
        frequencies, generalized_mass, generalized_stiffness, mode_numbers  (n_modes,)
        parameters/<PARA>           (n_modes,)
        mesh/                       attrs: name, dim, title
          coords (n_nodes, 3), node_names (n_nodes,)
          cell_names, cell_types, cell_offsets, cell_connectivity
          node_groups/<G>, cell_groups/<G>   0-based indices
        (mode_gene: generalized modes)
        vectors                     (n_gene, n_modes)
        frequencies, ..., parameters/
        numbering/                  the NUME_DDL_GENE, built on a basis (basis/, nested)
                                    or on a generalized model (offsets, constraints, model/)
        (none: no basis)
      tables/<NOM_TABLE>/           attrs: name, title, concept, n_rows
        columns/<PARA>              (n_rows,)  attrs: parameter, type (R, I, C, K8...)
        present/<PARA>              (n_rows,)  bool, only for parameters some rows lack
"""

from __future__ import annotations

import os
import shutil
import uuid
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from asterlite.concepts.harmonic import DynaHarmo
from asterlite.concepts.modes import ModeResult, MultElasResult
from asterlite.concepts.table import Table
from asterlite.concepts.transient import DynaTrans, ShockHistory, TranGene
from asterlite.errors import CommandError
from asterlite.io.basis_store import basis_from, read_basis, write_basis
from asterlite.io.hdf5_values import (
    h5py_module,
    plain,
    read_attrs,
    read_group_arrays,
    read_strings,
    strings,
    unique_member_names,
    write_attributes,
)
from asterlite.io.med_writer import dofs_to_nodal

# 2: tables/ (files of version 1 read back with no tables); 3: basis/ of every
# kind, with basis_type (older files hold a mode_meca, without parameters/)
LAYOUT_VERSION = 3
NODAL_DOF_FIELDS = ("DEPL", "VITE", "ACCE")


# =============================================================================
# nodal fields of result concepts
# =============================================================================


@dataclass
class ResultSteps:
    """The stored steps of a result: NUME_ORDRE and the access parameters."""

    orders: np.ndarray
    times: np.ndarray | None = None  # INST (dyna_trans)
    frequencies: np.ndarray | None = None  # FREQ (mode_meca)
    mode_numbers: np.ndarray | None = None  # NUME_MODE (mode_meca)
    case_names: list[str] | None = None  # NOM_CAS (mult_elas)

    @property
    def count(self) -> int:
        return len(self.orders)

    def time_values(self) -> np.ndarray:
        """What a MED time step carries: the instant, else the frequency, else 0."""
        if self.times is not None:
            return np.asarray(self.times, dtype=float)
        if self.frequencies is not None:
            return np.asarray(self.frequencies, dtype=float)
        return np.zeros(self.count)

    def parameters(self, k: int) -> dict[str, Any]:
        """Access parameters of step ``k`` (0-based) by code_aster name."""
        out: dict[str, Any] = {}
        if self.times is not None:
            out["INST"] = float(self.times[k])
        if self.mode_numbers is not None:
            out["NUME_MODE"] = int(self.mode_numbers[k])
        if self.frequencies is not None:
            out["FREQ"] = float(self.frequencies[k])
        if self.case_names:
            out["NOM_CAS"] = self.case_names[k]
        return out


def is_physical_result(result) -> bool:
    return isinstance(result, DynaTrans | ModeResult | MultElasResult)


def result_steps(result) -> ResultSteps:
    """Stored steps of a DynaTrans, ModeResult, MultElasResult or DynaHarmo."""
    if isinstance(result, DynaTrans):
        return ResultSteps(np.asarray(result.order, dtype=int), times=np.asarray(result.times))
    if isinstance(result, ModeResult):
        n = result.n_modes
        return ResultSteps(
            np.arange(1, n + 1),
            frequencies=np.asarray(result.frequencies, dtype=float),
            mode_numbers=np.asarray(result.mode_numbers, dtype=int),
        )
    if isinstance(result, MultElasResult):
        names = list(result.case_names) or [str(k + 1) for k in range(result.n_cases)]
        return ResultSteps(np.arange(1, result.n_cases + 1), case_names=names)
    if isinstance(result, DynaHarmo):
        return ResultSteps(
            np.asarray(result.order, dtype=int),
            frequencies=np.asarray(result.frequencies, dtype=float),
        )
    raise TypeError(f"no stored steps in a {type(result).__name__}")


def _matching(stored, wanted, precision: float, criterion: str, what: str) -> np.ndarray:
    """Index of the stored value closest to each wanted one, within PRECISION
    (CRITERE RELATIF scales by |wanted|, absolute for zero)."""
    stored = np.asarray(stored, dtype=float)
    out = []
    for w in np.atleast_1d(np.asarray(wanted, dtype=float)):
        k = int(np.argmin(np.abs(stored - w))) if stored.size else -1
        tolerance = precision * abs(w) if criterion == "RELATIF" and w != 0 else precision
        if k < 0 or abs(stored[k] - w) > tolerance:
            span = f"{stored.min():g}..{stored.max():g}" if stored.size else "none"
            raise CommandError(
                f"no stored {what} matches {w:g} (PRECISION={precision:g}, "
                f"CRITERE={criterion}; stored {what}: {span})"
            )
        out.append(k)
    return np.asarray(out, dtype=int)


def _matching_exact(stored, wanted, what: str) -> np.ndarray:
    lookup = {v: k for k, v in enumerate(stored)}
    missing = [w for w in wanted if w not in lookup]
    if missing:
        raise CommandError(f"{what} {missing[0]} is not stored (stored: {list(stored)})")
    return np.asarray([lookup[w] for w in wanted], dtype=int)


def select_steps(
    steps: ResultSteps,
    *,
    nume_ordre=None,
    nume_mode=None,
    inst=None,
    freq=None,
    nom_cas=None,
    precision: float = 1e-6,
    criterion: str = "RELATIF",
) -> np.ndarray:
    """0-based indices of the stored steps chosen by one access keyword
    (NUME_ORDRE, NUME_MODE, INST, FREQ or NOM_CAS, in the order given), or of
    every step when none is given. Raises CommandError for a step not stored."""
    if nume_ordre is not None:
        return _matching_exact(
            [int(o) for o in steps.orders], [int(n) for n in nume_ordre], "NUME_ORDRE"
        )
    if nume_mode is not None:
        if steps.mode_numbers is None:
            raise CommandError("NUME_MODE needs a modal result")
        stored = [int(m) for m in steps.mode_numbers]
        return _matching_exact(stored, [int(n) for n in nume_mode], "NUME_MODE")
    if inst is not None:
        if steps.times is None:
            raise CommandError("INST needs a result stored by instant")
        return _matching(steps.times, inst, precision, criterion, "instant")
    if freq is not None:
        if steps.frequencies is None:
            raise CommandError("FREQ needs a result stored by frequency")
        return _matching(steps.frequencies, freq, precision, criterion, "frequency")
    if nom_cas is not None:
        if not steps.case_names:
            raise CommandError("NOM_CAS needs a mult_elas result")
        return _matching_exact(
            [c.strip() for c in steps.case_names], [str(c).strip() for c in nom_cas], "NOM_CAS"
        )
    return np.arange(steps.count)


def _dof_fields(result) -> dict[str, np.ndarray]:
    """DOF-vector fields of a result: name -> (n_steps, n_dofs)."""
    if isinstance(result, DynaTrans):
        return dict(result.fields)
    if isinstance(result, ModeResult):
        return {"DEPL": np.asarray(result.shapes).T}
    if isinstance(result, MultElasResult):
        return {"DEPL": np.asarray(result.fields).T}
    if isinstance(result, DynaHarmo):
        return dict(result.fields)  # complex
    return {}


def nodal_field_names(result) -> list[str]:
    """Nodal fields a result holds (DOF fields first, then *_NOEU fields)."""
    names = list(_dof_fields(result))
    names += [n for n in (getattr(result, "node_fields", None) or {}) if n not in names]
    return names


def element_field_names(result) -> list[str]:
    return list(getattr(result, "element_fields", None) or {})


def nodal_series(result, name: str, nodes=None, components=()) -> tuple:
    """``(nodes, components, values)`` of nodal field ``name`` at every stored
    step: values (n_steps, n_nodes, n_components), zero where a node lacks a
    component. ``nodes`` / ``components`` restrict (and order) the output;
    a node that carries no value is left out. KeyError if absent."""

    dof_fields = _dof_fields(result)
    if name in dof_fields:
        return dofs_to_nodal(result.numbering, dof_fields[name], nodes, components)
    node_fields = getattr(result, "node_fields", None) or {}
    if name not in node_fields:
        raise KeyError(name)
    field = node_fields[name]
    field_nodes = np.asarray(field.nodes, dtype=int)
    rows = {int(n): k for k, n in enumerate(field_nodes)}
    picked = field_nodes if nodes is None else [int(n) for n in nodes if int(n) in rows]
    comps = tuple(components) if components else tuple(field.components)
    values = np.zeros((field.values.shape[0], len(picked), len(comps)))
    for j, comp in enumerate(comps):
        if comp in field.components:
            values[:, :, j] = field.values[
                :, [rows[n] for n in picked], field.components.index(comp)
            ]
    return np.asarray(picked, dtype=int), comps, values


# =============================================================================
# HDF5 store of tran_gene results
# =============================================================================


def _shock_group_names(shocks: list[ShockHistory]) -> list[str]:
    """One HDF5 group name per shock: its INTITULE, made unique."""
    return unique_member_names([shock.name for shock in shocks], "CHOC_{}")


def _write_shocks(group, shocks: list[ShockHistory]) -> None:
    for k, (name, shock) in enumerate(zip(_shock_group_names(shocks), shocks, strict=True)):
        sub = group.create_group(name, track_order=True)
        sub.attrs["index"] = k + 1
        sub.attrs["name"] = shock.name or ""
        sub.attrs["relation"] = shock.relation or ""
        sub.attrs["node_1"] = shock.node_1 or ""
        sub.attrs["node_2"] = shock.node_2 or ""
        skipped = write_attributes(sub, shock.parameters)
        if skipped:
            sub.attrs["parameters_not_stored"] = ", ".join(skipped)
        for field, values in shock.fields.items():
            sub[field] = np.asarray(values)


def _table_column(table: Table, parameter: str) -> tuple[np.ndarray, np.ndarray]:
    """(values, present) of one parameter: values typed after its code
    (R float, I int64, C complex, else strings), a neutral filler (0, "")
    where a row lacks it -- never NaN, so a stored table stays finite."""
    type_code = table.types[parameter]
    cells = table.column(parameter)
    present = np.array([v is not None for v in cells], dtype=bool)
    if type_code == "R":
        return np.array([0.0 if v is None else float(v) for v in cells], dtype=float), present
    if type_code == "I":
        return np.array([0 if v is None else int(v) for v in cells], dtype=np.int64), present
    if type_code == "C":
        return np.array([0j if v is None else complex(v) for v in cells], dtype=complex), present
    return strings("" if v is None else v for v in cells), present


def _write_table(group, key: str, table: Table) -> None:
    group.attrs["name"] = key
    group.attrs["title"] = table.title or ""
    group.attrs["concept"] = table.name or ""
    group.attrs["n_rows"] = len(table)
    columns = group.create_group("columns", track_order=True)
    present_group = None
    names = unique_member_names(table.columns, "PARA_{}")
    for name, parameter in zip(names, table.columns, strict=True):
        values, present = _table_column(table, parameter)
        dataset = columns.create_dataset(name, data=values)
        dataset.attrs["parameter"] = parameter
        dataset.attrs["type"] = table.types[parameter]
        if not present.all():
            if present_group is None:
                present_group = group.create_group("present", track_order=True)
            present_group[name] = present


def _write_tables(group, tables: dict) -> None:
    """The tables kept with a result (RECU_TABLE NOM_TABLE), by their key."""
    kept = {str(k): v for k, v in tables.items() if isinstance(v, Table)}
    skipped = [str(k) for k, v in tables.items() if not isinstance(v, Table)]
    if skipped:
        group.attrs["tables_not_stored"] = ", ".join(skipped)
    for name, (key, table) in zip(unique_member_names(kept, "TABLE_{}"), kept.items(), strict=True):
        _write_table(group.create_group(name, track_order=True), key, table)


def _write_tran_gene(f, tran_gene: TranGene, name: str) -> None:
    if name in f:
        del f[name]
    group = f.create_group(name, track_order=True)
    group.attrs["aster_type"] = "tran_gene"
    group.attrs["layout_version"] = LAYOUT_VERSION
    group.attrs["scheme"] = tran_gene.scheme or ""
    group.attrs["step"] = float(tran_gene.step)
    group.attrs["n_modes"] = int(tran_gene.n_modes)
    group.attrs["n_archived"] = len(tran_gene.times)
    group["times"] = np.asarray(tran_gene.times, dtype=float)
    group["order"] = np.asarray(tran_gene.order, dtype=np.int64)
    for field in ("depl", "vite", "acce"):
        group[field] = np.asarray(getattr(tran_gene, field), dtype=float)
    for field in ("step_sizes", "rejections"):
        if getattr(tran_gene, field) is not None:
            group[field] = np.asarray(getattr(tran_gene, field), dtype=float)
    scheme = group.create_group("scheme")
    scheme.attrs["name"] = tran_gene.scheme or ""
    scheme.attrs["step"] = float(tran_gene.step)
    skipped = write_attributes(scheme, tran_gene.info)
    if skipped:
        scheme.attrs["info_not_stored"] = ", ".join(skipped)
    _write_shocks(group.create_group("shocks", track_order=True), tran_gene.shocks)
    write_basis(group.create_group("basis"), tran_gene.basis)
    _write_tables(group.create_group("tables", track_order=True), tran_gene.tables or {})


@contextmanager
def _updating(path: Path):
    """An HDF5 file open for writing that replaces ``path`` only when the
    block completes: the writes go to a copy next to it (or a new file),
    renamed over ``path`` at the end; on an error the copy is removed and
    ``path`` is left as it was."""
    h5py = h5py_module()
    temporary = path.with_name(f".{path.name}.{os.getpid()}.{uuid.uuid4().hex[:8]}.tmp")
    try:
        if path.exists():
            shutil.copy2(path, temporary)
            f = h5py.File(temporary, "a")
        else:
            f = h5py.File(temporary, "w", track_order=True)
        with f:
            yield f
        os.replace(temporary, path)
    finally:
        temporary.unlink(missing_ok=True)


def _group_name(tran_gene: TranGene, name: str | None) -> str:
    return (name or tran_gene.name or "TRAN_GENE").replace("/", "_")


def save_tran_gene(path: str | Path, tran_gene: TranGene, name: str | None = None) -> Path:
    """Write ``tran_gene`` (with the tables it keeps) to the HDF5 file
    ``path`` under group ``name`` (default: the concept's name); an existing
    group of that name is replaced, other groups of the file are kept. The
    file is replaced whole once written, never left half written."""
    path = Path(path)
    with _updating(path) as f:
        _write_tran_gene(f, tran_gene, _group_name(tran_gene, name))
    return path


def stored_names(path: str | Path) -> list[str]:
    """Names of the tran_gene results stored in a file."""
    h5py = h5py_module()
    with h5py.File(path, "r") as f:
        return [k for k in f if f[k].attrs.get("aster_type") == "tran_gene"]


def _read_table(group) -> dict[str, Any]:
    """A stored table as plain data: ``types`` and ``columns`` by parameter
    (arrays; lists of str for text columns), ``present`` (bool arrays) for
    the parameters some rows lack, where ``columns`` holds a filler."""
    h5py = h5py_module()
    attrs = read_attrs(group)
    out = {
        "name": str(attrs.get("name", group.name.rsplit("/", 1)[-1])),
        "title": str(attrs.get("title", "")),
        "concept": str(attrs.get("concept", "")) or None,
        "n_rows": int(attrs.get("n_rows", 0)),
        "types": {},
        "columns": {},
        "present": {},
    }
    masks = group["present"] if "present" in group else {}
    for key, dataset in group["columns"].items():
        parameter = str(plain(dataset.attrs.get("parameter", key)))
        text = h5py.check_string_dtype(dataset.dtype) is not None
        out["types"][parameter] = str(plain(dataset.attrs.get("type", "K24" if text else "R")))
        out["columns"][parameter] = read_strings(dataset) if text else dataset[()]
        if key in masks:
            out["present"][parameter] = np.asarray(masks[key][()], dtype=bool)
    return out


def read_tran_gene_dict(path: str | Path, name: str | None = None) -> dict[str, Any]:
    """A stored tran_gene as plain Python data (arrays, lists, dicts)."""
    h5py = h5py_module()
    with h5py.File(path, "r") as f:
        name = _pick_name(f, name, path)
        group = f[name]
        out = {"name": name, **read_attrs(group)}
        for key in ("times", "order", "depl", "vite", "acce"):
            out[key] = group[key][()]
        for key in ("step_sizes", "rejections"):  # absent from older files
            out[key] = group[key][()] if key in group else None
        out["scheme_info"] = read_attrs(group["scheme"])
        out["shocks"] = [
            {
                "group": key,
                "attributes": read_attrs(group["shocks"][key]),
                "fields": read_group_arrays(group["shocks"][key]),
            }
            for key in group["shocks"]
        ]
        out["basis"] = read_basis(group["basis"])
        tables = group["tables"] if "tables" in group else {}  # absent from version 1
        out["tables"] = {t["name"]: t for t in map(_read_table, tables.values())}
    return out


def _pick_name(f, name: str | None, path) -> str:
    candidates = [k for k in f if f[k].attrs.get("aster_type") == "tran_gene"]
    if name is None:
        if not candidates:
            raise KeyError(f"{path}: no tran_gene stored")
        return candidates[0]
    if name not in candidates:
        raise KeyError(f"{path}: no tran_gene named {name!r} (stored: {', '.join(candidates)})")
    return name


_SHOCK_KEYS = ("index", "name", "relation", "node_1", "node_2", "parameters_not_stored")


def _shock_from(data: dict[str, Any]) -> ShockHistory:
    attrs = data["attributes"]
    parameters = {k: v for k, v in attrs.items() if k not in _SHOCK_KEYS}
    return ShockHistory(
        name=str(attrs.get("name", data["group"])),
        relation=str(attrs.get("relation", "")),
        node_1=str(attrs.get("node_1", "")),
        node_2=(str(attrs["node_2"]) or None) if attrs.get("node_2") else None,
        fields=dict(data["fields"]),
        parameters=parameters,
    )


def _table_from(data: dict[str, Any]) -> Table:
    """A :class:`Table` back from :func:`_read_table`'s data: same
    parameters in order, same type codes, the values as Python float, int,
    complex or str, absent where the row lacked them."""
    table = Table(title=data["title"])
    table.name = data.get("concept") or None
    cells: dict[str, list] = {}
    for parameter, values in data["columns"].items():
        table.add_column(parameter, data["types"][parameter])
        values = values if isinstance(values, list) else np.asarray(values).tolist()
        present = data["present"].get(parameter)
        if present is not None:
            values = [v if p else None for v, p in zip(values, present, strict=True)]
        cells[parameter] = values
    table.extend(data["n_rows"], cells)
    return table


def load_tran_gene(path: str | Path, name: str | None = None, *, concept: bool = True):
    """Read a stored tran_gene: a :class:`TranGene` (``concept=True``, with
    its basis rebuilt as it was: a modal basis with its DOF numbering and
    mesh, generalized modes with their generalized numbering -- down to the
    substructures of a generalized model --, or None) or the plain dict of
    :func:`read_tran_gene_dict` (``concept=False``). ``name`` defaults to the
    first tran_gene of the file."""
    data = read_tran_gene_dict(path, name)
    if not concept:
        return data
    info = {k: v for k, v in data["scheme_info"].items() if k not in ("name", "step")}
    result = TranGene(
        basis=basis_from(data["basis"]),
        times=data["times"],
        order=data["order"],
        depl=data["depl"],
        vite=data["vite"],
        acce=data["acce"],
        shocks=[_shock_from(s) for s in data["shocks"]],
        scheme=str(data.get("scheme", "")),
        step=float(data.get("step", 0.0)),
        info=info,
        step_sizes=data["step_sizes"],
        rejections=data["rejections"],
        tables={key: _table_from(t) for key, t in data["tables"].items()},
    )
    result.name = data["name"]
    return result


def save_session_results(path: str | Path, namespace: dict[str, Any]) -> list[str]:
    """Save every TranGene of a deck namespace (keyed by concept name), with
    its tables, to ``path`` in one replacement of the file; returns the names
    saved, in namespace order. A concept bound to several names is saved
    once, under its own name when it has one."""
    saved: list[str] = []
    seen: set[int] = set()
    results = []
    for key, value in namespace.items():
        if not isinstance(value, TranGene) or id(value) in seen:
            continue
        seen.add(id(value))
        results.append((value.name or key, value))
    if not results:
        return saved
    with _updating(Path(path)) as f:
        for name, value in results:
            name = _group_name(value, name)
            _write_tran_gene(f, value, name)
            saved.append(name)
    return saved


__all__ = [
    "ResultSteps",
    "element_field_names",
    "is_physical_result",
    "load_tran_gene",
    "nodal_field_names",
    "nodal_series",
    "read_tran_gene_dict",
    "result_steps",
    "save_session_results",
    "save_tran_gene",
    "select_steps",
    "stored_names",
]
