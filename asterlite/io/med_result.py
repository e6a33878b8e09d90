"""Nodal fields of a MED file, step by step (what LIRE_RESU FORMAT='MED' reads).

Read with medcoupling: each time step gives its (iteration, order, time)
and the field's values on the nodes of its profile (every node when it has
none). Node k of the file is node k of the mesh the deck names, as code_aster
reads it (the file is expected to hold that mesh).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from asterlite.io.input_files import InputFileError, open_input
from asterlite.io.med_mesh import check_declared_bytes


class MedResultError(ValueError):
    """A MED file or field that cannot be read as asked."""


@dataclass
class MedStep:
    iteration: int
    order: int  # -1 when the file has none
    time: float
    nodes: np.ndarray  # 0-based mesh node indices
    values: np.ndarray  # (len(nodes), n_components)


@dataclass
class MedNodalField:
    name: str
    components: tuple[str, ...]
    n_mesh_nodes: int
    steps: list[MedStep]


def read_nodal_field(path: str | Path, name: str) -> MedNodalField:
    """Field ``name`` of a MED file: a regular file (read through one
    descriptor, so a FIFO swapped in meanwhile is never opened) whose
    datasets fit the run's memory limit once decompressed."""

    path = Path(path)
    try:
        with open_input(path, "MED file") as (descriptor, _size):
            pinned = Path(f"/proc/self/fd/{descriptor}")
            return _read_field(pinned if pinned.exists() else path, name, path.name)
    except InputFileError as error:
        raise MedResultError(str(error)) from None


def _check_sizes(path: str, shown: str) -> None:
    import h5py

    try:
        with h5py.File(path, "r") as handle:
            check_declared_bytes([handle], shown, "MED file", MedResultError)
    except OSError as exc:
        raise MedResultError(f"{shown} is not a readable MED file ({exc})") from None


def _read_field(path: Path, name: str, shown: str) -> MedNodalField:
    import medcoupling as mc

    path = str(path)
    _check_sizes(path, shown)
    try:
        available = list(mc.GetAllFieldNames(path))
    except Exception as exc:  # medcoupling raises InterpKernelException
        raise MedResultError(f"{shown} is not a readable MED file ({exc})") from None
    if name not in available:
        listed = ", ".join(available) or "none"
        raise MedResultError(f"no field {name!r} in {shown} (fields: {listed})")
    multi = mc.MEDFileFieldMultiTS.New(path, name, True)
    mesh = mc.MEDFileMesh.New(path, multi.getMeshName())
    steps, components = [], None
    for one in multi:
        if mc.ON_NODES not in one.getTypesOfFieldAvailable():
            raise MedResultError(f"field {name!r} is not a field on nodes")
        iteration, order, time = one.getTime()
        array, profile = one.getFieldWithProfile(mc.ON_NODES, 0, mesh)
        comps = tuple(c.strip() for c in array.getInfoOnComponents())
        if components is not None and comps != components:
            raise MedResultError(f"field {name!r} changes components between steps")
        components = comps
        values = array.toNumPyArray().reshape(array.getNumberOfTuples(), len(comps))
        if profile is None:
            nodes = np.arange(values.shape[0])
        else:
            nodes = np.asarray(profile.toNumPyArray(), dtype=int)
        steps.append(MedStep(int(iteration), int(order), float(time), nodes, values.copy()))
    return MedNodalField(name, components or (), mesh.getNumberOfNodes(), steps)
