"""Reader for code_aster's native text mesh format (``FORMAT='ASTER'``).

The file is a sequence of sections, each opened by a keyword line and closed
by ``FINSF``; ``FIN`` ends the file and ``%`` starts a comment. Sections:

- ``TITRE``: free text;
- ``COOR_1D`` / ``COOR_2D`` / ``COOR_3D``: ``name x [y [z]]`` per node;
- a cell type (``POI1``, ``SEG2``, ``QUAD4``...): ``name node1 node2 ...``;
- ``GROUP_NO`` / ``GROUP_MA``: the group name (first token, or ``NOM=name``
  on the keyword line) followed by member names.

A keyword line's ``KEY=VALUE`` options may go on over the lines after it.

Entries may wrap over several lines: only the token count matters.

Errors quote the file's tokens only once its first line has been read as a
section keyword: before, the file may be any file the user can read. A
coordinate that is a NaN or an infinity, however spelt (``nan``, ``1.#QNAN``,
``1.D+999``...), is refused naming the node and the line.
"""

from __future__ import annotations

import gc
from pathlib import Path

import numpy as np

from asterlite.concepts.mesh import CELL_NODE_COUNTS, Mesh
from asterlite.io.input_files import InputFileError, read_bounded_text
from asterlite.io.non_finite import NonFiniteNumber, finite_float


class AsterMeshError(ValueError):
    """A malformed mesh file; ``line`` is 1-based (0 when unknown)."""

    def __init__(self, message: str, line: int = 0, filename: str = ""):
        where = f"{filename}:{line}: " if line else (f"{filename}: " if filename else "")
        super().__init__(where + message)
        self.line = line


_COORD_SECTIONS = {"COOR_1D": 1, "COOR_2D": 2, "COOR_3D": 3}
_GROUP_SECTIONS = ("GROUP_NO", "GROUP_MA")
_SECTIONS = frozenset(
    {"TITRE", "FIN", "FINSF", *_COORD_SECTIONS, *_GROUP_SECTIONS, *CELL_NODE_COUNTS}
)
# a file whose first line is not a section keyword may be anything the user
# can read (F mail /etc/passwd): where, and what was expected, never its text
NOT_A_MESH = (
    "not an ASTER mesh: a section keyword was expected (TITRE, COOR_3D, a cell type "
    "such as SEG2, GROUP_NO, GROUP_MA or FIN); the line is not shown"
)


def _lines(text: str):
    """(line number, tokens) for each non-empty line, comments removed."""
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.split("%", 1)[0].replace(",", " ")
        tokens = line.split()
        if tokens:
            yield number, tokens


def _header_options(tokens: list[str]) -> tuple[dict[str, str], list[str]]:
    """Split ``KEY=VALUE`` / ``KEY = VALUE`` options off a section's keyword line."""
    joined = " ".join(tokens).replace(" =", "=").replace("= ", "=")
    options, rest = {}, []
    for tok in joined.split():
        if "=" in tok:
            key, _, value = tok.partition("=")
            options[key.upper()] = value
        else:
            rest.append(tok)
    return options, rest


def _all_options(tokens: list[str]) -> bool:
    """Whether a line holds only ``KEY=VALUE`` options (a section's header
    going on), never names or numbers."""
    options, rest = _header_options(tokens)
    return bool(options) and not rest


def _to_float(token: str, node: str, line: int, filename: str) -> float:
    """A coordinate: a finite number, NaN and infinities refused however spelt."""
    try:
        return finite_float(token, fortran_exponent=True)
    except NonFiniteNumber as error:
        raise AsterMeshError(f"node {node}: {error}", line, filename) from None
    except ValueError:
        raise AsterMeshError(f"expected a number, found {token!r}", line, filename) from None


class _Body:
    """A section's tokens and their line numbers, read as (token, line) pairs."""

    def __init__(self, words: list[str], numbers: list[int]):
        self.words, self.numbers = words, numbers

    def __len__(self) -> int:
        return len(self.words)

    def __getitem__(self, k):
        if isinstance(k, slice):
            return list(zip(self.words[k], self.numbers[k], strict=True))
        return self.words[k], self.numbers[k]


def _coordinates(words: list[str], ndim: int) -> np.ndarray | None:
    """(nodes, ndim) coordinates of a COOR section's tokens (a name, then
    ndim numbers, per node), read as float() reads them; None when one is
    not a finite number as it stands (then read one by one, to name it)."""
    try:
        columns = [list(map(float, words[j :: ndim + 1])) for j in range(1, ndim + 1)]
    except ValueError:
        return None
    xyz = np.array(columns, dtype=float).T.reshape(-1, ndim)
    return xyz if np.isfinite(xyz).all() else None


def parse_aster_mesh(text: str, filename: str = "") -> Mesh:
    """Build a :class:`Mesh` from the text of an ASTER-format mesh file."""
    # hundreds of thousands of small objects and no cycle among them: the
    # cyclic collector, run every few hundred allocations, would scan them
    # over and over (a third of the time on a 30 000-cell mesh)
    enabled = gc.isenabled()
    gc.disable()
    try:
        return _parse(text, filename)
    finally:
        if enabled:
            gc.enable()


def _parse(text: str, filename: str) -> Mesh:
    node_names: list[str] = []
    node_xyz: list[tuple[float, float, float]] = []
    node_lines: dict[str, int] = {}
    # per cell section: names, type, node names column by column, lines
    cells: list[tuple[list[str], str, list[list[str]], list[int]]] = []
    groups: list[tuple[str, str, list[str], int]] = []  # kind, name, members, line
    title: list[str] = []
    dim = 0

    lines = list(_lines(text))
    raw_lines = text.splitlines()
    recognised = False
    i = 0
    while i < len(lines):
        number, tokens = lines[i]
        keyword = tokens[0].upper()
        i += 1
        if not recognised and keyword not in _SECTIONS:
            raise AsterMeshError(NOT_A_MESH, number, filename)
        recognised = True  # an ASTER mesh: its tokens may be quoted from here on
        if keyword == "FIN":
            break
        if keyword == "FINSF":
            continue
        # the keyword line's options may go on over the next lines (NUMIN=1
        # NUMAX=148, AUTEUR=..., DATE=...): lines whose every token is an option
        header = list(tokens[1:])
        while i < len(lines) and keyword != "TITRE" and _all_options(lines[i][1]):
            header.extend(lines[i][1])
            i += 1
        # collect the section body (every token up to FINSF) and each token's line
        words: list[str] = []
        numbers: list[int] = []
        while i < len(lines) and lines[i][1][0].upper() != "FINSF":
            words.extend(lines[i][1])
            numbers.extend([lines[i][0]] * len(lines[i][1]))
            i += 1
        body = _Body(words, numbers)
        if i >= len(lines):
            raise AsterMeshError(f"section {keyword} is not closed by FINSF", number, filename)
        i += 1  # skip FINSF

        if keyword == "TITRE":
            # keep the raw text (tokens lose spacing)
            first = body[0][1] if body else number + 1
            last = body[-1][1] if body else number
            title.extend(raw_lines[k - 1].rstrip() for k in range(first, last + 1))
            continue
        options, extra = _header_options(header)
        if keyword in _COORD_SECTIONS:
            ndim = _COORD_SECTIONS[keyword]
            dim = max(dim, ndim)
            if len(body) % (ndim + 1):
                raise AsterMeshError(
                    f"{keyword}: expected entries of a name and {ndim} coordinates",
                    number,
                    filename,
                )
            names = words[:: ndim + 1]
            xyz = _coordinates(words, ndim)
            if (
                xyz is None
                or len(set(names)) < len(names)
                or not node_lines.keys().isdisjoint(names)
            ):
                # one by one: Fortran exponents read, or the wrong entry named
                values = []
                for k in range(0, len(body), ndim + 1):
                    name, line = body[k]
                    if name in node_lines:
                        raise AsterMeshError(f"node {name} defined twice", line, filename)
                    values.append(
                        [
                            _to_float(tok, name, ln, filename)
                            for tok, ln in body[k + 1 : k + 1 + ndim]
                        ]
                    )
                    node_lines[name] = line
                xyz = np.array(values, dtype=float).reshape(-1, ndim)
            node_lines.update(zip(names, numbers[:: ndim + 1], strict=True))
            node_names.extend(names)
            node_xyz.append(np.pad(xyz, ((0, 0), (0, 3 - ndim))))
        elif keyword in CELL_NODE_COUNTS:
            count = CELL_NODE_COUNTS[keyword]
            if len(body) % (count + 1):
                raise AsterMeshError(
                    f"{keyword}: expected entries of a name and {count} node names",
                    number,
                    filename,
                )
            # name, then each node's column: the cells of a section as columns
            columns = [words[j :: count + 1] for j in range(1, count + 1)]
            cells.append((words[:: count + 1], keyword, columns, numbers[:: count + 1]))
        elif keyword in _GROUP_SECTIONS:
            members = extra + words
            name = options.get("NOM")
            if name is None:
                if not members:
                    raise AsterMeshError(f"{keyword} without a name", number, filename)
                name, members = members[0], members[1:]
            groups.append((keyword, name, members, number))
        else:
            raise AsterMeshError(f"unknown section keyword {tokens[0]!r}", number, filename)

    node_index = {n: k for k, n in enumerate(node_names)}
    cell_names, cell_types, cell_nodes = [], [], []
    cell_index: dict[str, int] = {}
    for names, cell_type, columns, cell_lines in cells:
        try:
            indices = [list(map(node_index.__getitem__, column)) for column in columns]
        except KeyError:
            indices = None
        fresh = len(set(names)) == len(names) and cell_index.keys().isdisjoint(names)
        if indices is None or not fresh:
            # the entry that is wrong, named (one by one)
            seen = set(cell_index)
            for k, name in enumerate(names):
                if name in seen:
                    raise AsterMeshError(f"cell {name} defined twice", cell_lines[k], filename)
                seen.add(name)
                for column in columns:
                    if column[k] not in node_index:
                        message = f"cell {name} uses unknown node {column[k]}"
                        raise AsterMeshError(message, cell_lines[k], filename)
        cell_index.update(
            zip(names, range(len(cell_names), len(cell_names) + len(names)), strict=True)
        )
        cell_names.extend(names)
        cell_types.extend([cell_type] * len(names))
        cell_nodes.extend(zip(*indices, strict=True) if columns else [()] * len(names))

    node_groups: dict[str, np.ndarray] = {}
    cell_groups: dict[str, np.ndarray] = {}
    for kind, name, members, line in groups:
        table, lookup = (
            (node_groups, node_index) if kind == "GROUP_NO" else (cell_groups, cell_index)
        )
        if name in table:
            raise AsterMeshError(f"{kind} {name} defined twice", line, filename)
        try:
            table[name] = np.array([lookup[m] for m in members], dtype=int)
        except KeyError as exc:
            what = "node" if kind == "GROUP_NO" else "cell"
            raise AsterMeshError(
                f"{kind} {name} names unknown {what} {exc.args[0]}", line, filename
            ) from None

    coords = np.ascontiguousarray(np.concatenate(node_xyz)) if node_xyz else np.zeros((0, 3))
    return Mesh(
        coords=coords,
        node_names=node_names,
        cell_names=cell_names,
        cell_types=cell_types,
        cell_nodes=cell_nodes,
        node_groups=node_groups,
        cell_groups=cell_groups,
        dim=dim or 3,
        title="\n".join(title),
    )


# bytes of memory the parser takes per byte of mesh text (measured: about 36)
PARSE_BYTES_PER_BYTE = 40


def read_aster_mesh(path: str | Path) -> Mesh:
    """Read an ASTER-format mesh file (refused before reading when parsing it
    would pass the run's memory limit)."""

    path = Path(path)
    try:
        text = read_bounded_text(path, "ASTER mesh", PARSE_BYTES_PER_BYTE)
    except InputFileError as error:
        raise AsterMeshError(str(error).split(": ", 1)[-1], 0, str(path)) from None
    return parse_aster_mesh(text, str(path))
