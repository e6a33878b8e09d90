"""Reading an untrusted MED file without risking the run.

A few damaged bytes in a MED file can make HDF5 or medcoupling abort the
process (std::bad_alloc, SIGABRT, SIGSEGV) instead of raising an error. So a
mesh is read in a child process (``python -I ... asterlite.io.med_check``,
isolated from the current folder: :mod:`asterlite.isolation`):

1. the child validates the file with h5py: the MED layout (``ENS_MAA``,
   ``NOE/COO``, ``MAI/<type>/NOD``), the sizes each dataset declares against
   its ``NBR`` attribute and a bound on the whole, the types (floating
   coordinates, integer connectivity and families) and connectivity within
   the node range (finite coordinates are checked by the reader, which
   names the node);
2. it then reads the mesh with medcoupling and hands the result back
   (pickled into a temporary file);
3. a child that dies (a signal, or no result) becomes a MedMeshError naming
   the file and what happened, which LIRE_MAILLAGE reports at its deck line.

The child inherits the run's address-space cap and is given the run's
remaining time.
"""

from __future__ import annotations

import json
import math
import os
import pickle
import signal
import subprocess
import sys
import tempfile
from pathlib import Path

# numbers one MED file may declare in all (coordinates, connectivity,
# families, numbers, names): beyond it the file is refused before reading
MAX_MED_VALUES = 400_000_000
IN_CHILD = "ASTERLITE_MED_CHILD"
MEMORY_VARIABLE = "ASTERLITE_MED_MEMORY_MB"  # the run's memory limit, handed to the child
# memory the reading takes per byte of data the mesh declares (HDF5's buffers,
# medcoupling's arrays, the numpy copies and the pickle handed back)
MED_BYTES_PER_BYTE = 4
DEFAULT_TIMEOUT = 3600.0


def read_isolated(path: Path, name: str | None, read):
    """``read(path, name)`` in a child process; MedMeshError if it fails."""
    from asterlite.io.med_mesh import MedMeshError
    from asterlite.isolation import python_command

    if os.environ.get(IN_CHILD):  # already the child: read here
        return _read_pinned(path, name, read)
    with tempfile.TemporaryDirectory(prefix="asterlite-med-") as folder:
        result = Path(folder) / "mesh.pickle"
        # isolated: a json.py or numpy.py beside the study is never imported
        command = python_command("asterlite.io.med_check", str(path), name or "", str(result))
        environment = dict(os.environ, **{IN_CHILD: "1", MEMORY_VARIABLE: _memory_text()})
        try:
            child = subprocess.run(
                command, env=environment, capture_output=True, timeout=_timeout(), check=False
            )
        except subprocess.TimeoutExpired:
            raise MedMeshError(f"{path}: reading the MED file did not end in time") from None
        if child.returncode < 0:
            died = signal.Signals(-child.returncode).name
            raise MedMeshError(
                f"{path}: the MED/HDF5 library crashed reading this file ({died}): "
                "the file is damaged or not a MED file"
            )
        if not result.exists():
            tail = child.stderr.decode("utf-8", "replace").strip().splitlines()[-1:]
            detail = f" ({tail[0][:200]})" if tail else ""
            raise MedMeshError(
                f"{path}: the MED reader stopped (exit status {child.returncode}){detail}"
            )
        with open(result, "rb") as stream:
            kind, payload = pickle.load(stream)  # written by the child below, our own data
    if kind == "error":
        raise MedMeshError(payload)
    return payload


def _read_pinned(path: Path, name: str | None, read):
    """In the child: validate and read the file through one descriptor on a
    regular file (``/proc/self/fd/N``), so that a FIFO or device swapped in
    at ``path`` after the checks is never opened."""
    from asterlite.io.input_files import InputFileError, open_input
    from asterlite.io.med_mesh import MedMeshError

    try:
        with open_input(path, "MED file") as (descriptor, _size):
            pinned = Path(f"/proc/self/fd/{descriptor}")
            if not pinned.exists():  # no /proc: the path itself, checked just above
                pinned = path
            try:
                validate_med(pinned, name, shown=path)
                return read(pinned, name)
            except MedMeshError as error:
                raise MedMeshError(str(error).replace(str(pinned), str(path))) from None
    except InputFileError as error:
        raise MedMeshError(str(error)) from None


def _memory_text() -> str:
    from asterlite.runtime import watchdog

    limit = watchdog.memory_limit_mb()
    return f"{limit:g}" if limit else ""


def memory_limit_mb() -> float | None:
    """The run's memory limit: handed down by the parent, else this process's."""
    text = os.environ.get(MEMORY_VARIABLE)
    if text is not None:
        try:
            return float(text) or None
        except ValueError:
            return None
    from asterlite.runtime import watchdog

    return watchdog.memory_limit_mb()


def _timeout() -> float:
    """The run's remaining time (its limit is CPU time; the child's is wall time)."""
    from asterlite.runtime import watchdog

    deadline = getattr(watchdog._state, "deadline", None)
    if deadline is None:
        return DEFAULT_TIMEOUT
    return max(10.0, deadline - watchdog._spent())


# ------------------------------------------------------------- validation


def validate_med(path: Path, name: str | None = None, shown: Path | None = None) -> None:
    """Check a MED file's layout with h5py before medcoupling reads it
    (``shown``: the path to name in messages, when ``path`` is a descriptor's)."""
    import h5py

    from asterlite.io.med_mesh import MedMeshError

    try:
        handle = h5py.File(path, "r")
    except OSError as error:
        raise MedMeshError(f"{shown or path}: not a readable MED file (HDF5: {error})") from None
    path = shown or path
    with handle:
        try:
            _validate(handle, path, name)
        except MedMeshError:
            raise
        except (KeyError, ValueError, TypeError, OSError, RuntimeError) as error:
            raise MedMeshError(
                f"{path}: damaged MED file ({type(error).__name__}: {error})"
            ) from None


def _validate(handle, path: Path, name: str | None) -> None:
    from asterlite.io.med_mesh import MedMeshError

    meshes = handle.get("ENS_MAA")
    if meshes is None or not hasattr(meshes, "keys"):
        raise MedMeshError(f"{path}: no ENS_MAA group: not a MED mesh file")
    names = list(meshes.keys())
    if not names:
        raise MedMeshError(f"{path}: the MED file holds no mesh")
    chosen = names if name is None else [n for n in names if n == name]
    # sizes first, from the metadata alone: nothing is decompressed before
    families = [handle[f"FAS/{n}"] for n in chosen if f"FAS/{n}" in handle]
    check_declared_bytes([meshes[n] for n in chosen] + families, path, "mesh", MedMeshError)
    budget = [MAX_MED_VALUES]
    for mesh_name in chosen:
        mesh = meshes[mesh_name]
        for step_name in mesh.keys():
            step = mesh[step_name]
            if hasattr(step, "keys"):
                _validate_step(step, path, f"{mesh_name}/{step_name}", budget)
    if budget[0] < 0:
        raise MedMeshError(
            f"{path}: the file declares more than {MAX_MED_VALUES:,} values: refused"
        )


def check_declared_bytes(groups, path: Path, what: str, error_type) -> int:
    """The bytes the datasets under ``groups`` hold once decompressed, or
    ``error_type`` when they (or any one chunk HDF5 would decompress at once)
    pass what the run's memory limit allows for reading them. Shapes and
    types are metadata: a 16 kB file whose compressed (or never written,
    fill-valued) datasets declare gigabytes is refused before reading."""
    budget = _byte_budget()
    datasets = []

    def collect(_name, item):
        if _is_dataset(item):
            datasets.append(item)

    for group in groups:
        if _is_dataset(group):
            datasets.append(group)
        else:
            group.visititems(collect)
    declared = stored = 0
    for dataset in datasets:
        size = _dataset_bytes(dataset, path, error_type)
        declared += size
        stored += dataset.id.get_storage_size()
        chunk = math.prod(dataset.chunks or ()) * dataset.dtype.itemsize
        if chunk > budget:
            raise error_type(
                f"{path}: dataset {dataset.name} is stored in chunks of {chunk / 1e6:.0f} MB, "
                f"more than the {budget / 1e6:.0f} MB this run can spend reading it: refused"
            )
    if declared > budget:
        raise error_type(
            f"{path}: the {what} holds {declared / 1e6:.0f} MB of data once decompressed "
            f"({stored / 1e6:.3g} MB stored in the file), more than the {budget / 1e6:.0f} MB "
            f"this run can spend reading it ({_budget_reason()}): refused"
        )
    return declared


def _is_dataset(item) -> bool:
    import h5py

    return isinstance(item, h5py.Dataset)


def _dataset_bytes(dataset, path: Path, error_type) -> int:
    """size x item size; variable-length items (whose size the metadata
    does not bound) are refused: MED stores none."""
    import h5py

    dtype = dataset.dtype
    if h5py.check_vlen_dtype(dtype) is not None or dtype.hasobject:
        raise error_type(f"{path}: dataset {dataset.name} holds variable-length items: refused")
    return int(dataset.size or 0) * dtype.itemsize


def _byte_budget() -> int:
    """Bytes of data a MED file may declare: the run's memory limit over
    what reading takes per byte, and never more than MAX_MED_VALUES doubles."""
    ceiling = MAX_MED_VALUES * 8
    limit = memory_limit_mb()
    if not limit:
        return ceiling
    return min(ceiling, int(limit * 1024 * 1024 / MED_BYTES_PER_BYTE))


def _budget_reason() -> str:
    limit = memory_limit_mb()
    if not limit:
        return f"at most {MAX_MED_VALUES:,} values of 8 bytes"
    return (
        f"its memory limit of {limit:g} MB, about {MED_BYTES_PER_BYTE} bytes of memory "
        "per byte of data"
    )


def _validate_step(step, path: Path, where: str, budget: list) -> None:
    from asterlite.io.med_mesh import MedMeshError

    def fail(message: str):
        raise MedMeshError(f"{path}: mesh {where}: {message}")

    nodes = step.get("NOE")
    coordinates = nodes.get("COO") if nodes is not None else None
    if coordinates is None:
        fail("no node coordinates (NOE/COO)")
    count = _declared_count(coordinates, fail, "NOE/COO")
    if coordinates.dtype.kind != "f":
        fail(f"NOE/COO holds {coordinates.dtype}, not floating-point coordinates")
    if count < 0 or (count and coordinates.size % count) or coordinates.size > 3 * count:
        fail(f"NOE/COO has {coordinates.size} values for {count} nodes")
    _spend(budget, coordinates.size, fail)
    # finite coordinates: checked by the reader, which names the node
    _check_companions(nodes, count, "NOE", budget, fail)
    cells = step.get("MAI")
    for type_name in cells.keys() if cells is not None else ():
        group = cells[type_name]
        if hasattr(group, "keys"):
            _validate_cells(group, f"MAI/{type_name}", count, budget, fail)


def _validate_cells(group, where: str, n_nodes: int, budget: list, fail) -> None:
    connectivity = group.get("NOD")
    if connectivity is None:
        return  # a type stored otherwise (polygons): left to medcoupling
    count = _declared_count(connectivity, fail, f"{where}/NOD")
    if connectivity.dtype.kind not in "iu":
        fail(f"{where}/NOD holds {connectivity.dtype}, not node numbers")
    geometry = int(group.attrs.get("GEO", 0))
    per_cell = geometry % 100 if geometry < 400 else None
    if per_cell and connectivity.size != count * per_cell:
        fail(f"{where}/NOD has {connectivity.size} values for {count} cells of {per_cell} nodes")
    _spend(budget, connectivity.size, fail)
    values = connectivity[()]
    if values.size and (values.min() < 1 or values.max() > n_nodes):
        fail(f"{where}/NOD refers to nodes outside 1..{n_nodes}")
    _check_companions(group, count, where, budget, fail)


def _check_companions(group, count: int, where: str, budget: list, fail) -> None:
    """FAM and NUM: one integer per entity; NOM: names of 80 bytes each."""
    for key in ("FAM", "NUM"):
        dataset = group.get(key)
        if dataset is None:
            continue
        if dataset.dtype.kind not in "iu" or dataset.size != count:
            fail(f"{where}/{key}: expected {count} integers, found {dataset.size} {dataset.dtype}")
        _spend(budget, dataset.size, fail)
    names = group.get("NOM")
    if names is not None:
        _spend(budget, names.size * max(names.dtype.itemsize, 1), fail)


def _declared_count(dataset, fail, where: str) -> int:
    count = dataset.attrs.get("NBR")
    try:
        count = int(count)
    except (TypeError, ValueError):
        fail(f"{where} declares no entity count (NBR)")
    if count < 0 or count > MAX_MED_VALUES:
        fail(f"{where} declares {count} entities")
    if len(dataset.shape) != 1:
        fail(f"{where} is not a flat array (shape {dataset.shape})")
    return count


def _spend(budget: list, values: int, fail) -> None:
    budget[0] -= int(values)
    if budget[0] < 0:
        fail(f"the file declares more than {MAX_MED_VALUES:,} values: refused")


# ------------------------------------------------------------------ child


# the child's address space: its libraries, plus this many times the run's limit
CHILD_ADDRESS_SPACE_HEADROOM = 2


def _cap_own_memory() -> None:
    """Cap the child's address space at its size once its libraries are
    loaded plus twice the run's memory limit: whatever slips past the
    validation fails there with a MemoryError (std::bad_alloc), not by
    taking the machine's memory."""
    import h5py  # noqa: F401  (loaded before the cap: libraries are not the file's data)

    try:
        import medcoupling  # noqa: F401
    except ImportError:
        pass
    from asterlite.runtime import watchdog

    limit = memory_limit_mb()
    size = watchdog.address_space_size()
    if not limit or size is None:
        return
    try:
        import resource

        cap = size + int(CHILD_ADDRESS_SPACE_HEADROOM * limit * watchdog.MEGABYTE)
        soft, hard = resource.getrlimit(resource.RLIMIT_AS)
        for existing in (soft, hard):
            if existing != resource.RLIM_INFINITY:
                cap = min(cap, existing)
        resource.setrlimit(resource.RLIMIT_AS, (cap, hard))
    except (ImportError, ValueError, OSError):
        pass


def _child(path: str, name: str, result: str) -> int:
    from asterlite.io.med_mesh import MedMeshError, read_med_mesh

    _cap_own_memory()
    try:
        outcome = ("mesh", read_med_mesh(Path(path), name or None))
    except MedMeshError as error:
        outcome = ("error", str(error))
    except MemoryError:
        outcome = ("error", f"{path}: reading this MED file needs more memory than the run allows")
    except Exception as error:  # medcoupling's own errors on a damaged file
        first = (str(error).strip().splitlines() or [""])[0][:200]
        outcome = ("error", f"{path}: cannot read the MED file ({type(error).__name__}: {first})")
    with open(result + ".part", "wb") as stream:
        pickle.dump(outcome, stream)
    os.replace(result + ".part", result)
    return 0


if __name__ == "__main__":  # python -m asterlite.io.med_check PATH NAME RESULT
    if len(sys.argv) != 4:
        print(json.dumps({"usage": "python -m asterlite.io.med_check PATH NAME RESULT"}))
        raise SystemExit(2)
    raise SystemExit(_child(*sys.argv[1:]))
