"""Reader for MED meshes (SALOME's HDF5 format, ``LIRE_MAILLAGE(FORMAT='MED')``).

Built on ``medcoupling`` (``MEDFileUMesh``). The result is a
:class:`~asterlite.concepts.mesh.Mesh` laid out as code_aster reads it:

- coordinates padded to 3D (``dim`` keeps the MED space dimension);
- cells of every dimension (points, segments, faces, volumes), numbered by
  increasing MED geometric type (POI1, SEG2, SEG3, SEG4, TRIA3, QUAD4, ...,
  HEXA27), in file order within a type, with code_aster type names and
  code_aster node ordering (MED and code_aster differ for volumes);
- node and cell names from the file when it has them (meshes written by
  code_aster do), else ``N1, N2, ...`` and ``M1, M2, ...``;
- node groups and cell groups rebuilt from the families; a name used at
  both levels gives a node group and a cell group, as in code_aster.

An untrusted file is read without risking the run: a few damaged bytes in a
MED file can make HDF5 or medcoupling abort the process (std::bad_alloc,
SIGABRT, SIGSEGV) instead of raising an error. So a mesh is read in a child
process, forked by a reading server (one ``python -I -m asterlite.io.med_mesh
--serve`` per process, isolated from the current folder:
:mod:`asterlite.isolation`) that loads the MED libraries once, so that a
read costs a fork, not a Python start (where the platform has no fork, or
the server fails, a new isolated Python reads each file):

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

h5py and medcoupling are imported where a MED file is read, not with this
module: they cost ~90 ms and ~220 ms of CPU at start-up (measured on the
2-core machine, 2026-11-28), which runs that read no MED file do not pay.
"""

from __future__ import annotations

import atexit
import json
import math
import os
import pickle
import select
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from asterlite import watchdog
from asterlite.concepts.mesh import Mesh
from asterlite.errors import CommandError
from asterlite.io.input_files import InputFileError, check_regular_file, open_input
from asterlite.isolation import python_command


class MedMeshError(ValueError):
    """A MED file asterlite cannot read as a mesh."""


# MED geometric type number (code_aster numbers cells in increasing order of
# it), code_aster name, and the MED positions of code_aster's nodes (0-based)
# when the two numberings differ. Keyed by medcoupling's type names.
_TYPES = {
    "NORM_POINT1": (1, "POI1", None),
    "NORM_SEG2": (102, "SEG2", None),
    "NORM_SEG3": (103, "SEG3", None),
    "NORM_SEG4": (104, "SEG4", None),
    "NORM_TRI3": (203, "TRIA3", None),
    "NORM_QUAD4": (204, "QUAD4", None),
    "NORM_TRI6": (206, "TRIA6", None),
    "NORM_TRI7": (207, "TRIA7", None),
    "NORM_QUAD8": (208, "QUAD8", None),
    "NORM_QUAD9": (209, "QUAD9", None),
    "NORM_TETRA4": (304, "TETRA4", (0, 2, 1, 3)),
    "NORM_PYRA5": (305, "PYRAM5", (0, 3, 2, 1, 4)),
    "NORM_PENTA6": (306, "PENTA6", (0, 2, 1, 3, 5, 4)),
    "NORM_HEXA8": (308, "HEXA8", (0, 3, 2, 1, 4, 7, 6, 5)),
    "NORM_TETRA10": (310, "TETRA10", (0, 2, 1, 3, 6, 5, 4, 7, 9, 8)),
    "NORM_PYRA13": (313, "PYRAM13", (0, 3, 2, 1, 4, 8, 7, 6, 5, 9, 12, 11, 10)),
    "NORM_PENTA15": (315, "PENTA15", (0, 2, 1, 3, 5, 4, 8, 7, 6, 12, 14, 13, 11, 10, 9)),
    "NORM_PENTA18": (
        318,
        "PENTA18",
        (0, 2, 1, 3, 5, 4, 8, 7, 6, 12, 14, 13, 11, 10, 9, 17, 16, 15),
    ),
    "NORM_HEXA20": (
        320,
        "HEXA20",
        (0, 3, 2, 1, 4, 7, 6, 5, 11, 10, 9, 8, 16, 19, 18, 17, 15, 14, 13, 12),
    ),
    "NORM_HEXA27": (
        327,
        "HEXA27",
        (0, 3, 2, 1, 4, 7, 6, 5, 11, 10, 9, 8, 16, 19, 18, 17, 15, 14, 13, 12)
        + (20, 24, 23, 22, 21, 25, 26),
    ),
}


def _medcoupling():
    try:
        import medcoupling
    except ImportError as exc:  # pragma: no cover - declared dependency
        raise MedMeshError("reading MED files needs the 'medcoupling' package") from exc
    return medcoupling


def med_mesh_names(path: Path) -> list[str]:
    """Names of the meshes stored in a MED file."""
    mc = _medcoupling()
    try:
        return list(mc.GetMeshNames(str(path)))
    except Exception as exc:  # medcoupling raises InterpKernelException
        raise MedMeshError(f"{path}: not a readable MED file ({_first_line(exc)})") from exc


def _first_line(exc: Exception) -> str:
    text = str(exc).strip().splitlines()
    return text[0] if text else type(exc).__name__


def _names(field, count: int, prefix: str) -> list[str]:
    """Names from a MED name field, or generated ones when absent, blank or
    not unique (names must identify entities)."""
    if field is not None:
        names = [s.strip() for s in field.toStrList()[:count]]
        if len(names) == count and all(names) and len(set(names)) == count:
            return names
    return [f"{prefix}{i + 1}" for i in range(count)]


def read_med_mesh(path: Path, name: str | None = None) -> Mesh:
    """Read mesh ``name`` (default: the first) of a MED file: validated, then
    read in a child process whose crash on a damaged file becomes a
    MedMeshError (:func:`read_isolated`)."""
    path = Path(path)
    try:  # a FIFO or a device is refused here and again in the child, on its descriptor
        check_regular_file(path, "MED file")
    except FileNotFoundError:
        raise MedMeshError(f"{path}: no such MED file") from None
    except InputFileError as error:
        raise MedMeshError(str(error)) from None
    return read_isolated(path, name, _read_here)


def _read_here(path: Path, name: str | None) -> Mesh:
    """The reading itself, in this process (the file is validated already)."""
    mc = _medcoupling()
    available = med_mesh_names(path)
    if not available:
        raise MedMeshError(f"{path}: the MED file holds no mesh")
    if name is None:
        name = available[0]
    elif name not in available:
        raise MedMeshError(f"{path}: no mesh named '{name}' (the file has {', '.join(available)})")
    try:
        med = mc.MEDFileMesh.New(str(path), name)
    except Exception as exc:
        raise MedMeshError(f"{path}: cannot read mesh '{name}' ({_first_line(exc)})") from exc
    if not isinstance(med, mc.MEDFileUMesh):
        raise MedMeshError(f"{path}: mesh '{name}' is not unstructured ({type(med).__name__})")

    coords = med.getCoords().toNumPyArray().reshape(med.getNumberOfNodes(), -1)
    dim = coords.shape[1]
    if dim > 3:
        raise MedMeshError(f"{path}: space dimension {dim} is not supported")
    coords3 = np.zeros((len(coords), 3))
    coords3[:, :dim] = coords
    n_nodes = len(coords3)
    node_names = _names(med.getNameFieldAtLevel(1), n_nodes, "N")
    _check_finite(path, name, coords3, node_names)

    # cells of each level, tagged with their MED type number for ordering
    parts = []  # (med type number, level, indices in level, aster type, connectivity)
    level_sizes = {}
    for level in med.getNonEmptyLevels():
        umesh = med.getMeshAtLevel(level)
        level_sizes[level] = umesh.getNumberOfCells()
        conn = umesh.getNodalConnectivity().toNumPyArray()
        index = umesh.getNodalConnectivityIndex().toNumPyArray()
        types = conn[index[:-1]]
        for code in np.unique(types):
            type_name = mc.MEDCouplingUMesh.GetReprOfGeometricType(int(code))
            if type_name not in _TYPES:
                raise MedMeshError(f"{path}: cells of type {type_name} are not supported")
            number, aster_type, order = _TYPES[type_name]
            cells = np.flatnonzero(types == code)
            width = int(index[cells[0] + 1] - index[cells[0]] - 1)
            nodes = conn[index[cells][:, None] + 1 + np.arange(width)]
            if order is not None:
                nodes = nodes[:, order]
            parts.append((number, level, cells, aster_type, nodes))
    parts.sort(key=lambda p: (p[0], -p[1]))  # stable in file order within a type

    # global numbering: position of (level, index in level) in the cell list
    global_index = {lev: np.full(size, -1, dtype=int) for lev, size in level_sizes.items()}
    cell_types: list[str] = []
    cell_nodes: list[tuple[int, ...]] = []
    level_names = {lev: _level_names(med, lev, size) for lev, size in level_sizes.items()}
    raw_names: list[str | None] = []
    for _, level, cells, aster_type, nodes in parts:
        global_index[level][cells] = np.arange(len(cell_types), len(cell_types) + len(cells))
        cell_types.extend([aster_type] * len(cells))
        cell_nodes.extend(tuple(int(n) for n in row) for row in nodes)
        names = level_names[level]
        raw_names.extend(names[c] if names is not None else None for c in cells)
    n_cells = len(cell_types)
    if raw_names and all(raw_names) and len(set(raw_names)) == n_cells:
        cell_names = list(raw_names)
    else:
        cell_names = [f"M{i + 1}" for i in range(n_cells)]

    node_groups: dict[str, np.ndarray] = {}
    cell_groups: dict[str, np.ndarray] = {}
    for group in med.getGroupsNames():
        levels = med.getGrpNonEmptyLevelsExt(group)
        if 1 in levels:
            node_groups[group] = np.sort(med.getNodeGroupArr(group).toNumPyArray()).astype(int)
        members = [
            global_index[lev][med.getGroupArr(lev, group).toNumPyArray()]
            for lev in levels
            if lev != 1 and lev in global_index
        ]
        if members:
            cell_groups[group] = np.sort(np.concatenate(members)).astype(int)

    return Mesh(
        coords=coords3,
        node_names=node_names,
        cell_names=cell_names,
        cell_types=cell_types,
        cell_nodes=cell_nodes,
        node_groups=node_groups,
        cell_groups=cell_groups,
        dim=dim,
        title=(med.getDescription() or "").strip(),
    )


def _check_finite(path: Path, mesh: str, coords: np.ndarray, node_names: list[str]) -> None:
    """A NaN or infinite coordinate has no place in a mesh: name the first such node."""
    bad = np.flatnonzero(~np.isfinite(coords).all(axis=1))
    if bad.size:
        node = int(bad[0])
        coordinates = ", ".join(repr(float(v)) for v in coords[node])
        more = f" (and {bad.size - 1} more nodes)" if bad.size > 1 else ""
        raise MedMeshError(
            f"{path}: mesh '{mesh}': node {node_names[node]} (number {node + 1}) has a "
            f"non-finite coordinate ({coordinates}){more}"
        )


def _level_names(med, level: int, size: int) -> list[str] | None:
    field = med.getNameFieldAtLevel(level)
    if field is None:
        return None
    names = [s.strip() for s in field.toStrList()[:size]]
    return names if len(names) == size else None


class ReadableMesh(Mesh):
    """``CA.Mesh()`` of code_aster 16-17: empty until ``readMedFile`` reads
    an input file of the run into it (by name, as the export gives it)."""

    deck_methods = Mesh.deck_methods | {"readMedFile"}

    @classmethod
    def empty(cls, find_input) -> ReadableMesh:
        mesh = cls(np.zeros((0, 3)), [], [], [], [])
        mesh._find_input = find_input  # name -> Path of an input file of the run
        return mesh

    def readMedFile(self, filename, meshname=None, verbose=0) -> None:  # noqa: N802
        path = self._find_input(filename)
        try:
            read = read_med_mesh(path, meshname or None)
        except (ValueError, KeyError) as error:
            raise CommandError(f"readMedFile({filename!r}): {error}") from None
        name, find_input = self.name, self._find_input
        self.__dict__.update(read.__dict__)
        self.name, self._find_input = name, find_input
        self.refresh_indices()


# ------------------------------------------------------- isolated reading


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
    if os.environ.get(IN_CHILD):  # already the child: read here
        return _read_pinned(path, name, read)
    with tempfile.TemporaryDirectory(prefix="asterlite-med-") as folder:
        result = Path(folder) / "mesh.pickle"
        returncode, stderr = _reading_child(path, name, result)
        if returncode < 0:
            died = signal.Signals(-returncode).name
            raise MedMeshError(
                f"{path}: the MED/HDF5 library crashed reading this file ({died}): "
                "the file is damaged or not a MED file"
            )
        if not result.exists():
            tail = stderr.strip().splitlines()[-1:]
            detail = f" ({tail[0][:200]})" if tail else ""
            raise MedMeshError(f"{path}: the MED reader stopped (exit status {returncode}){detail}")
        with open(result, "rb") as stream:
            kind, payload = pickle.load(stream)  # written by the child below, our own data
    if kind == "error":
        raise MedMeshError(payload)
    return payload


def _reading_child(path: Path, name: str | None, result: Path) -> tuple[int, str]:
    """A child reads the file: its exit status (negative: the signal that
    ended it) and standard error. Where the platform forks, the child is
    forked by the reading server (:class:`_ReadingServer`), which has h5py,
    medcoupling and this module loaded already (a few ms instead of ~0.4 s of
    imports for a new Python); else a new isolated Python reads the file."""
    if not hasattr(os, "fork"):
        return _spawned_child(path, name, result)
    timeout = _timeout()
    request = {"path": str(path), "name": name or "", "result": str(result)}
    request.update(memory=_memory_text(), timeout=timeout)
    answer = _ReadingServer.ask(request, timeout + 5.0)
    if answer is None:  # the server itself failed: one new Python for this file
        return _spawned_child(path, name, result)
    if answer.get("timeout"):
        raise MedMeshError(f"{path}: reading the MED file did not end in time")
    return int(answer["status"]), ""


class _ReadingServer:
    """One long-lived isolated Python (``python -I -m asterlite.io.med_mesh
    --serve``) that loads the MED libraries once, then forks one child per
    file to read: a crash still ends only that child. It reads requests on
    its standard input, one JSON line each, answers one line each, and ends
    when this process closes the pipe (or ends)."""

    process: subprocess.Popen | None = None

    @classmethod
    def ask(cls, request: dict, timeout: float) -> dict | None:
        for _attempt in range(2):  # a server that has died is started again, once
            server = cls._running()
            try:
                server.stdin.write((json.dumps(request) + "\n").encode())
                server.stdin.flush()
                ready, _, _ = select.select([server.stdout], [], [], timeout)
                line = server.stdout.readline() if ready else b""
            except (OSError, ValueError):
                line = b""
            if line:
                return json.loads(line)
            cls.stop()
            if not ready:  # no answer in time: do not try again
                return None
        return None

    @classmethod
    def _running(cls) -> subprocess.Popen:
        if cls.process is None or cls.process.poll() is not None:
            cls.process = subprocess.Popen(
                python_command("asterlite.io.med_mesh", "--serve"),
                stdin=subprocess.PIPE,
                stdout=subprocess.PIPE,
                stderr=subprocess.DEVNULL,
                env=dict(os.environ, **{IN_CHILD: "1"}),
            )
            atexit.register(cls.stop)
        return cls.process

    @classmethod
    def stop(cls) -> None:
        if cls.process is not None:
            cls.process.kill()
            cls.process.wait()
            cls.process = None


def _serve() -> int:
    """The reading server's loop (see :class:`_ReadingServer`)."""
    _load_libraries()
    for line in sys.stdin.buffer:
        request = json.loads(line)
        pid = os.fork()
        if pid == 0:  # the child: reads, writes the outcome file, never returns
            status = 1
            try:
                # the answers' pipe is the server's: the libraries print elsewhere
                os.dup2(os.open(os.devnull, os.O_WRONLY), 1)
                _write_outcome(
                    request["path"], request["name"], request["result"], request["memory"]
                )
                status = 0
            finally:
                os._exit(status)
        answer = _wait_child(pid, float(request["timeout"]))
        sys.stdout.write(json.dumps(answer) + "\n")
        sys.stdout.flush()
    return 0


def _wait_child(pid: int, timeout: float) -> dict:
    """The child's exit status, or a timeout once it is killed."""

    deadline = time.monotonic() + timeout
    delay = 0.0005
    while True:
        done, status = os.waitpid(pid, os.WNOHANG)
        if done:
            return {"status": os.waitstatus_to_exitcode(status)}
        if time.monotonic() > deadline:
            os.kill(pid, signal.SIGKILL)
            os.waitpid(pid, 0)
            return {"timeout": True}
        time.sleep(delay)
        delay = min(2 * delay, 0.02)


def _spawned_child(path: Path, name: str | None, result: Path) -> tuple[int, str]:
    """A new Python reads the file: its exit status and standard error."""
    command = python_command("asterlite.io.med_mesh", str(path), name or "", str(result))
    environment = dict(os.environ, **{IN_CHILD: "1", MEMORY_VARIABLE: _memory_text()})
    try:
        child = subprocess.run(
            command, env=environment, capture_output=True, timeout=_timeout(), check=False
        )
    except subprocess.TimeoutExpired:
        raise MedMeshError(f"{path}: reading the MED file did not end in time") from None
    return child.returncode, child.stderr.decode("utf-8", "replace")


def _read_pinned(path: Path, name: str | None, read):
    """In the child: validate and read the file through one descriptor on a
    regular file (``/proc/self/fd/N``), so that a FIFO or device swapped in
    at ``path`` after the checks is never opened."""
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
    return watchdog.memory_limit_mb()


def _timeout() -> float:
    """The run's remaining time (its limit is CPU time; the child's is wall time)."""
    deadline = getattr(watchdog._state, "deadline", None)
    if deadline is None:
        return DEFAULT_TIMEOUT
    return max(10.0, deadline - watchdog._spent())


# ------------------------------------------------------------- validation


def validate_med(path: Path, name: str | None = None, shown: Path | None = None) -> None:
    """Check a MED file's layout with h5py before medcoupling reads it
    (``shown``: the path to name in messages, when ``path`` is a descriptor's)."""
    import h5py

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
        if "NOE" in mesh:
            # MED 2.x (files of code_aster 10): one state, in the mesh group itself,
            # beside its families (FAS)
            _validate_step(mesh, path, mesh_name, budget)
            continue
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


def _load_libraries() -> None:
    """h5py and medcoupling, loaded before any cap: libraries are not the
    file's data."""
    import h5py  # noqa: F401

    try:
        import medcoupling  # noqa: F401
    except ImportError:
        pass


def _cap_own_memory() -> None:
    """Cap the child's address space at its size once its libraries are
    loaded plus twice the run's memory limit: whatever slips past the
    validation fails there with a MemoryError (std::bad_alloc), not by
    taking the machine's memory."""
    _load_libraries()
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


def _write_outcome(path: str, name: str, result: str, memory: str | None = None) -> None:
    """In the child: read the mesh and pickle the outcome to ``result``
    (``memory``: the run's memory limit in MB, handed down by the parent)."""
    os.environ[IN_CHILD] = "1"
    if memory is not None:
        os.environ[MEMORY_VARIABLE] = memory
        _release_inherited_limits()
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


def _release_inherited_limits() -> None:
    """A child of the fork server has the soft limits of the run that started
    the server (an earlier one, maybe): back to the hard limits, before the
    cap of this run's own (the parent bounds the child's time)."""
    try:
        import resource

        for which in (resource.RLIMIT_AS, resource.RLIMIT_CPU):
            _soft, hard = resource.getrlimit(which)
            resource.setrlimit(which, (hard, hard))
    except (ImportError, ValueError, OSError):
        pass


def _child(path: str, name: str, result: str) -> int:
    _write_outcome(path, name, result)
    return 0


if __name__ == "__main__":  # python -m asterlite.io.med_mesh PATH NAME RESULT | --serve
    if sys.argv[1:] == ["--serve"]:
        raise SystemExit(_serve())
    if len(sys.argv) != 4:
        print(json.dumps({"usage": "python -m asterlite.io.med_mesh PATH NAME RESULT"}))
        raise SystemExit(2)
    raise SystemExit(_child(*sys.argv[1:]))
