"""Python values to and from HDF5, for the result store
(:mod:`asterlite.io.result_store`, :mod:`asterlite.io.basis_store`):
strings, attributes, member names."""

from __future__ import annotations

import re
from typing import Any

import numpy as np


def h5py_module():
    try:
        import h5py
    except ImportError as exc:  # pragma: no cover - declared dependency
        raise RuntimeError("the HDF5 result store needs the 'h5py' package") from exc
    return h5py


def strings(values) -> np.ndarray:
    """UTF-8 variable-length strings."""
    return np.array([str(v) for v in values], dtype=h5py_module().string_dtype())


def read_strings(dataset) -> list[str]:
    return [str(s) for s in dataset.asstr()[()]]


def attribute_value(value):
    """A value HDF5 can hold as an attribute, or None when it cannot."""
    if value is None:
        return None
    if isinstance(value, bool | np.bool_):
        return bool(value)
    if isinstance(value, int | float | str | np.integer | np.floating):
        return value
    if isinstance(value, list | tuple | np.ndarray):
        array = np.asarray(value)
        if array.dtype.kind in "biuf" and array.size <= 4096:
            return array
    return None


def write_attributes(node, mapping: dict) -> list[str]:
    """Scalar/array entries of ``mapping`` as attributes; returns the keys skipped."""
    skipped = []
    for key, value in mapping.items():
        converted = attribute_value(value)
        if converted is None:
            skipped.append(str(key))
        else:
            node.attrs[str(key)] = converted
    return skipped


def plain(value):
    if isinstance(value, bytes):
        return value.decode()
    if isinstance(value, np.generic):
        return value.item()
    return value


def read_attrs(node) -> dict[str, Any]:
    return {k: plain(v) for k, v in node.attrs.items()}


def read_group_arrays(node) -> dict[str, np.ndarray]:
    return {k: node[k][()] for k in node}


_MEMBER_NAME_BAD = re.compile(r"[/.]")


def unique_member_names(labels, fallback: str) -> list[str]:
    """One HDF5 member name per label ('/' and '.' replaced, empty labels
    named ``fallback.format(k)`` with k 1-based), made unique by suffixes."""
    names, seen = [], set()
    for k, label in enumerate(labels):
        base = _MEMBER_NAME_BAD.sub("_", (label or "").strip()) or fallback.format(k + 1)
        name, n = base, 2
        while name in seen:
            name, n = f"{base}_{n}", n + 1
        seen.add(name)
        names.append(name)
    return names
