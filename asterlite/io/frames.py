"""Concepts as Python data, for :mod:`asterlite.api`.

- transient results (``tran_gene``) and results with nodal fields
  (``dyna_trans``, ``mode_meca``, ``mult_elas``): arrays with named
  dimensions, an ``xarray.Dataset`` when xarray is installed, else the plain
  dict xarray itself uses for a dataset (``Dataset.to_dict(data="array")``:
  ``dims``, ``coords`` and ``data_vars``, each variable a ``{"dims", "data",
  "attrs"}`` dict holding a numpy array), which ``xarray.Dataset.from_dict``
  turns into the same dataset later; as for a Dataset, ``data["FN"]`` gives a
  variable (its numpy array, :class:`PlainDataset`);
- tables and functions: a ``pandas.DataFrame`` when pandas is installed, else
  a :class:`Columns` dict of numpy columns with ``columns`` and
  ``to_numpy()`` as a DataFrame has.

Neither xarray nor pandas is a dependency of asterlite: both are looked for
when a concept is converted, never at import.
"""

from __future__ import annotations

import importlib
from typing import Any

import numpy as np

from asterlite.concepts.function import Function, Nappe
from asterlite.concepts.modes import GeneralizedModes, ModeResult, MultElasResult
from asterlite.concepts.table import Table
from asterlite.concepts.transient import DynaTrans, TranGene
from asterlite.fem.dofs import sort_components
from asterlite.io.result_store import nodal_field_names, nodal_series, result_steps

TRANSIENT_FIELDS = ("depl", "vite", "acce")  # the names of the HDF5 store (docs/results.md)


def optional(module: str):
    """The module if it imports, else None (xarray and pandas are optional)."""
    try:
        return importlib.import_module(module)
    except ImportError:
        return None


class Columns(dict):
    """A table as ``{column: numpy array}`` when pandas is not installed."""

    @property
    def columns(self) -> list[str]:
        return list(self)

    @property
    def n_rows(self) -> int:
        return len(next(iter(self.values()))) if self else 0

    def to_numpy(self) -> np.ndarray:
        """(rows, columns), of the common dtype of the columns (object if mixed)."""
        if not self:
            return np.empty((0, 0))
        return np.column_stack([np.asarray(v) for v in self.values()])


class PlainDataset(dict):
    """xarray's dict form of a dataset when xarray is not installed; indexing
    by a variable or coordinate name gives its numpy array."""

    def __missing__(self, name: str) -> np.ndarray:
        for part in ("data_vars", "coords"):
            if name in dict.get(self, part, {}):
                return dict.__getitem__(self, part)[name]["data"]
        raise KeyError(name)

    def __contains__(self, name) -> bool:
        parts = (dict.get(self, "data_vars", {}), dict.get(self, "coords", {}))
        return dict.__contains__(self, name) or any(name in part for part in parts)

    def dims_of(self, name: str) -> tuple[str, ...]:
        """The dimension names of a variable or coordinate."""
        for part in ("data_vars", "coords"):
            if name in self[part]:
                return tuple(self[part][name]["dims"])
        raise KeyError(name)


# ------------------------------------------------------------------ builders


def dataset(data_vars: dict, coords: dict, attrs: dict):
    """An xarray.Dataset, or xarray's dict form of it. ``data_vars`` and
    ``coords`` map names to ``(dims, array)``."""
    xr = optional("xarray")
    if xr is not None:
        return xr.Dataset(data_vars=data_vars, coords=coords, attrs=attrs)
    sizes: dict[str, int] = {}
    for dims, array in [*data_vars.values(), *coords.values()]:
        sizes.update(zip(dims, np.shape(array), strict=True))

    def variables(named: dict) -> dict:
        return {n: {"dims": d, "data": np.asarray(a), "attrs": {}} for n, (d, a) in named.items()}

    return PlainDataset(
        dims=sizes, coords=variables(coords), data_vars=variables(data_vars), attrs=attrs
    )


def frame(columns: dict[str, np.ndarray], attrs: dict):
    """A pandas.DataFrame (with ``attrs``), or :class:`Columns`."""
    pd = optional("pandas")
    if pd is None:
        return Columns(columns)
    table = pd.DataFrame(columns)
    table.attrs.update(attrs)
    return table


# ---------------------------------------------------------------- transients


def _mode_coords(basis: ModeResult | GeneralizedModes) -> dict:
    count = basis.n_modes
    numbers = np.asarray(basis.mode_numbers, dtype=int)
    return {
        "mode": (("mode",), numbers[:count]),
        "frequency": (("mode",), np.asarray(basis.frequencies, dtype=float)[:count]),
    }


def _dof_labels(numbering) -> list[str]:
    names = numbering.mesh.node_names
    return [f"{names[node]} {component}" for node, component in numbering.dofs]


def transient_data(tran: TranGene):
    """A tran_gene: depl/vite/acce (time, mode); each shock quantity (FN,
    FT1, ...) as (time, shock), NaN for a shock that lacks it; the mode
    shapes (dof, mode) that give physical values (``depl @ shapes.T``), or
    for generalized modes (a mode_gene) their vectors (generalized_dof,
    mode) that give the NUME_DDL_GENE's unknowns (``depl @ vectors.T``)."""
    times = np.asarray(tran.times, dtype=float)
    data_vars = {
        name: (("time", "mode"), np.asarray(getattr(tran, name))) for name in TRANSIENT_FIELDS
    }
    shock_names = [shock.name for shock in tran.shocks]
    quantities = list(dict.fromkeys(q for shock in tran.shocks for q in shock.fields))
    for quantity in quantities:
        columns = [
            np.asarray(shock.fields[quantity], dtype=float)
            if quantity in shock.fields
            else np.full(len(times), np.nan)
            for shock in tran.shocks
        ]
        data_vars[quantity] = (("time", "shock"), np.column_stack(columns))
    coords = {"time": (("time",), times), "order": (("time",), np.asarray(tran.order))}
    if isinstance(tran.basis, GeneralizedModes):  # no mesh: the generalized unknowns
        coords.update(_mode_coords(tran.basis))
        data_vars["vectors"] = (("generalized_dof", "mode"), np.asarray(tran.basis.vectors))
    elif tran.basis is not None:
        coords.update(_mode_coords(tran.basis))
        if tran.basis.numbering is not None:
            coords["dof"] = (("dof",), np.array(_dof_labels(tran.basis.numbering)))
            data_vars["shapes"] = (("dof", "mode"), np.asarray(tran.basis.shapes))
    if shock_names:
        coords["shock"] = (("shock",), np.array(shock_names))
    attrs = {
        "name": tran.name or "",
        "aster_type": "tran_gene",
        "scheme": tran.scheme,
        "step": float(tran.step),
    }
    return dataset(data_vars, coords, attrs)


def _step_coords(result) -> tuple[str, dict]:
    """The name of the steps' dimension and its coordinates."""

    steps = result_steps(result)
    if steps.times is not None:
        dim, values = "time", np.asarray(steps.times, dtype=float)
    elif steps.case_names:
        dim, values = "case", np.array(steps.case_names)
    elif steps.mode_numbers is not None:
        dim, values = "mode", np.asarray(steps.mode_numbers, dtype=int)
    else:
        dim, values = "order", np.asarray(steps.orders, dtype=int)
    coords = {dim: ((dim,), values)}
    if dim != "order":
        coords["order"] = ((dim,), np.asarray(steps.orders, dtype=int))
    if steps.frequencies is not None:
        coords["frequency"] = ((dim,), np.asarray(steps.frequencies, dtype=float))
    return dim, coords


def physical_data(result):
    """A result with nodal fields (dyna_trans, mode_meca, mult_elas): each
    nodal field as (step, node, component) over the nodes and components of
    all its fields, NaN where a field has no value; the step dimension is
    named time, mode or case after the result."""

    dim, coords = _step_coords(result)
    series = {name: nodal_series(result, name) for name in nodal_field_names(result)}
    nodes = np.unique(np.concatenate([s[0] for s in series.values()] or [np.zeros(0, int)]))
    components = sort_components({c for s in series.values() for c in s[1]})
    node_at = {int(n): k for k, n in enumerate(nodes)}
    data_vars = {}
    for name, (field_nodes, field_components, values) in series.items():
        spread = np.full((values.shape[0], len(nodes), len(components)), np.nan)
        rows = [node_at[int(n)] for n in field_nodes]
        for j, component in enumerate(field_components):
            spread[:, rows, components.index(component)] = values[:, :, j]
        data_vars[name] = ((dim, "node", "component"), spread)
    mesh = result.numbering.mesh
    coords["node"] = (("node",), np.array([mesh.node_names[int(n)] for n in nodes]))
    coords["component"] = (("component",), np.array(components))
    attrs = {"name": result.name or "", "aster_type": result.aster_type}
    return dataset(data_vars, coords, attrs)


# ---------------------------------------------------------- tables, functions


def _column(values: list, type_code: str) -> np.ndarray:
    """One table column; a missing cell is NaN (numbers) or None (text)."""
    if type_code.startswith("K"):
        return np.array(values, dtype=object)
    if type_code == "C":
        return np.array([np.nan if v is None else v for v in values], dtype=complex)
    if type_code == "I" and all(v is not None for v in values):
        return np.array(values, dtype=int)
    return np.array([np.nan if v is None else v for v in values], dtype=float)


def table_data(table: Table):
    columns = {
        name: _column(table.column(name), table.types.get(name, "R")) for name in table.columns
    }
    return frame(columns, {"name": table.name or "", "title": table.title})


def function_data(function: Function):
    """The function's points: columns named NOM_PARA and NOM_RESU."""
    result_name = function.NOM_RESU
    if result_name == function.NOM_PARA:
        result_name += "_RESU"
    columns = {function.NOM_PARA: function.abscissas, result_name: function.ordinates}
    attrs = {
        "name": function.name or "",
        "interpol": tuple(function.INTERPOL),
        "prol_gauche": function.PROL_GAUCHE,
        "prol_droite": function.PROL_DROITE,
    }
    return frame(columns, attrs)


def nappe_data(nappe: Nappe):
    """A function of two parameters in long form: NOM_PARA, NOM_PARA_FONC, NOM_RESU."""
    para = np.concatenate(
        [
            np.full(len(f.abscissas), p, dtype=float)
            for p, f in zip(nappe.parameters, nappe.functions, strict=True)
        ]
    )
    columns = {
        nappe.NOM_PARA: para,
        nappe.NOM_PARA_FONC: np.concatenate([f.abscissas for f in nappe.functions]),
        nappe.NOM_RESU: np.concatenate([f.ordinates for f in nappe.functions]),
    }
    return frame(columns, {"name": nappe.name or ""})


def as_python(concept) -> Any:
    """The concept as data (see the module docstring); any other concept
    (mesh, model, matrices, formulas...) is returned as it is."""
    if isinstance(concept, TranGene):
        return transient_data(concept)
    if isinstance(concept, DynaTrans | ModeResult | MultElasResult) and getattr(
        concept, "numbering", None
    ):
        return physical_data(concept)
    if isinstance(concept, Table):
        return table_data(concept)
    if isinstance(concept, Nappe):
        return nappe_data(concept)
    if isinstance(concept, Function):
        return function_data(concept)
    return concept


__all__ = ["Columns", "PlainDataset", "as_python", "dataset", "frame", "optional", "transient_data"]
