"""I-DEAS universal file meshes (``LIRE_MAILLAGE(FORMAT='IDEAS')``).

The universal file is read with pyuff where its dataset readers fit, and
mapped to a :class:`Mesh` with the rules of code_aster's own converter
(PRE_IDEAS, which LIRE_MAILLAGE runs before reading the ASTER text it writes):

- nodes come from datasets 2411, 781 (same layout) or 15, in file order, and
  are named ``N<label>``; a node given in a non-Cartesian coordinate system
  (datasets 2420 / 18) is refused, as code_aster refuses it;
- cells come from datasets 2412, 780 or 71 and are named ``M<label>``; the
  I-DEAS descriptor selects the code_aster type, quadratic cells have their
  nodes reordered (I-DEAS lists corners and mid-side nodes alternately,
  code_aster corners first), and the cells are stored type by type in
  code_aster's type order, as the converter writes them;
- groups come from datasets 752, 2417, 2429, 2430, 2432, 2435, 2452, 2467
  and 2477: the node members form a ``GROUP_NO`` and the cell members a
  ``GROUP_MA`` of the same name. The name is cut to 8 characters and to its
  leading identifier (letters, digits, ``_``, starting with a letter); a
  name that does not start with a letter is dropped, a cell group whose name
  starts with ``COUL_`` is dropped, and a name starting with ``PERMANENT``
  becomes ``GRNO<number>`` / ``GRMA<number>``;
- ``CREA_GROUP_COUL='OUI'`` adds a group ``COUL_<colour>`` of the nodes and
  one of the cells of each colour.

Other datasets are skipped, as the converter skips them (each is listed in
the returned mesh's ``ideas_skipped``); those that would add entities
asterlite does not map (735 geometry, 82/2431 trace lines, thick-shell and
cubic cells) are refused by name.
"""

from __future__ import annotations

import contextlib
import io
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from asterlite.concepts.mesh import Mesh
from asterlite.io.input_files import InputFileError, read_bounded_text
from asterlite.io.non_finite import NonFiniteNumber, finite_float

# bytes of memory taken per byte of universal file text (pyuff's float lists, our records)
PARSE_BYTES_PER_BYTE = 40


class IdeasMeshError(ValueError):
    """A universal file that cannot be read; ``line`` is 1-based (0 when unknown)."""

    def __init__(self, message: str, line: int = 0, filename: str = ""):
        where = f"{filename}:{line}: " if line else (f"{filename}: " if filename else "")
        super().__init__(where + message)
        self.line = line


class IdeasMeshUnsupported(IdeasMeshError):
    """Content the converter would accept but asterlite does not map."""


# -- cell types ---------------------------------------------------------------

#: code_aster converter's "graphic code" -> code_aster cell type
_GRAPHIC_TYPES = {
    1: "SEG2",
    2: "TRIA3",
    3: "TRIA6",
    5: "QUAD4",
    6: "QUAD8",
    14: "TETRA4",
    15: "TETRA10",
    16: "PENTA6",
    17: "PENTA15",
    19: "HEXA8",
    20: "HEXA20",
    29: "SEG2",  # spring between nodes
    30: "POI1",  # spring to ground
    31: "SEG2",  # damper between nodes
    32: "POI1",  # damper to ground
    33: "POI1",  # lumped mass
    34: "SEG2",  # rigid bar
    35: "SEG3",
}

#: graphic codes the converter writes under types code_aster cannot compute on
_REFUSED_GRAPHIC = {
    4: "TRIA9",
    7: "QUAD12",
    8: "PENTAC6",
    9: "PENTAC12",
    10: "PENTAC18",
    11: "HEXACE8",
    12: "HEXACE16",
    13: "HEXACE24",
    18: "PENTA24",
    21: "HEXA32",
}

#: I-DEAS finite-element descriptor (datasets 780, 2412) -> graphic code
_DESCRIPTOR_CODES = {
    171: 1,
    11: 1,
    21: 1,
    23: 1,
    22: 35,
    24: 35,
    172: 35,
    **dict.fromkeys((91, 61, 41, 51, 74, 81), 2),
    **dict.fromkeys((92, 62, 42, 52, 72, 82), 3),
    **dict.fromkeys((93, 63, 43, 53, 73), 4),
    **dict.fromkeys((94, 64, 44, 54, 71, 84), 5),
    **dict.fromkeys((95, 65, 55, 45, 75, 85), 6),
    **dict.fromkeys((96, 66, 46, 56, 76), 7),
    101: 8,
    102: 9,
    103: 10,
    104: 11,
    105: 12,
    106: 13,
    111: 14,
    118: 15,
    112: 16,
    113: 17,
    114: 18,
    115: 19,
    116: 20,
    117: 21,
    136: 29,
    137: 29,
    138: 30,
    139: 30,
    141: 31,
    142: 32,
    161: 33,
    121: 34,
}

#: beam descriptors: their element record carries an extra orientation line
_BEAM_DESCRIPTORS = {11, 21, 22, 23, 24}

#: position (1-based) in code_aster's connectivity of the i-th node I-DEAS lists
_NODE_ORDER = {
    3: (1, 4, 2, 5, 3, 6),
    6: (1, 5, 2, 6, 3, 7, 4, 8),
    15: (1, 5, 2, 6, 3, 7, 8, 9, 10, 4),
    17: (1, 7, 2, 8, 3, 9, 10, 11, 12, 4, 13, 5, 14, 6, 15),
    20: (1, 9, 2, 10, 3, 11, 4, 12, 13, 14, 15, 16, 5, 17, 6, 18, 7, 19, 8, 20),
    35: (1, 3, 2),
}


# -- the file as datasets -------------------------------------------------------


@dataclass
class _Dataset:
    number: int
    first_line: int  # 1-based line of the dataset number
    lines: list[str]  # the body: the lines after the dataset number

    @property
    def text(self) -> str:
        """The block as pyuff's extractors take it (delimiter and number lines first)."""
        return "    -1\n" + f"{self.number:6d}\n" + "\n".join(self.lines) + "\n"


def _is_delimiter(line: str) -> bool:
    # the converter compares the first six characters with '    -1'
    return line[:6] == "    -1"


def _split_datasets(text: str, filename: str) -> list[_Dataset]:
    lines = text.splitlines()
    datasets: list[_Dataset] = []
    i = 0
    while i < len(lines):
        if not _is_delimiter(lines[i]):
            i += 1
            continue
        if i + 1 >= len(lines):
            break
        header = lines[i + 1]
        if _is_delimiter(header):  # an empty pair of delimiters
            i += 1
            continue
        try:
            number = int(header[:6])
        except ValueError:
            # before a first dataset the file may be anything: where, never what
            found = f", found {header[:20]!r}" if datasets else " (the line is not shown)"
            raise IdeasMeshError(f"expected a dataset number{found}", i + 2, filename) from None
        end = i + 2
        while end < len(lines) and not _is_delimiter(lines[end]):
            end += 1
        datasets.append(_Dataset(number, i + 2, lines[i + 2 : end]))
        i = end + 1
        if i < len(lines) and _bare_number(lines[i]):
            i = end  # its closing delimiter opens the next dataset (code_aster reads it so)
    return datasets


def _bare_number(line: str) -> bool:
    """A dataset number alone on its line (six columns, nothing after)."""
    return line[:6].strip().isdigit() and not line[6:].strip()


def _ints(line: str, width: int, count: int, where: tuple[int, str]) -> list[int]:
    """``count`` fixed-width integer fields (Fortran ``I<width>``: blank reads 0)."""
    values = []
    for k in range(count):
        field_text = line[k * width : (k + 1) * width].strip()
        try:
            values.append(int(field_text) if field_text else 0)
        except ValueError:
            raise IdeasMeshError(
                f"expected an integer in columns {k * width + 1}-{(k + 1) * width}, "
                f"found {field_text!r}",
                *where,
            ) from None
    return values


# -- collected entities -------------------------------------------------------


@dataclass
class _Cell:
    label: int
    code: int  # converter's graphic code
    nodes: list[int]  # node labels, code_aster order
    color: int
    line: int


@dataclass
class _Group:
    number: int
    name: str  # as in the file (first 20 characters, stripped)
    nodes: list[int]
    cells: list[int]
    line: int


@dataclass
class _Collected:
    filename: str
    node_labels: list[int] = field(default_factory=list)
    node_xyz: list[np.ndarray] = field(default_factory=list)
    node_cs: list[np.ndarray] = field(default_factory=list)
    node_colors: list[int] = field(default_factory=list)
    node_lines: list[int] = field(default_factory=list)
    cells: list[_Cell] = field(default_factory=list)
    groups: list[_Group] = field(default_factory=list)
    systems: dict[int, int] = field(default_factory=dict)  # label -> type (0 Cartesian)
    skipped: list[int] = field(default_factory=list)


def _pyuff_extractor(number: int):
    """pyuff's reader of one dataset type (pyuff is a declared dependency)."""
    from pyuff.datasets import dataset_15, dataset_2411, dataset_2420, dataset_2467

    return {
        15: dataset_15._extract15,
        2411: dataset_2411._extract2411,
        2420: dataset_2420._extract2420,
        2467: dataset_2467._extract2467,
    }[number]


def _run_pyuff(number: int, ds: _Dataset, filename: str, as_number: int | None = None):
    extract = _pyuff_extractor(as_number or number)
    text = ds.text if as_number is None else ds.text.replace(f"{number:6d}", f"{as_number:6d}", 1)
    try:
        # pyuff 2.5.8's group reader prints every group it reads
        with contextlib.redirect_stdout(io.StringIO()):
            return extract(text)
    except Exception as exc:  # pyuff raises bare Exceptions on malformed blocks
        raise IdeasMeshError(
            f"dataset {number} could not be read ({exc})", ds.first_line, filename
        ) from None


def _refuse_non_finite(ds: _Dataset, filename: str) -> None:
    """A NaN or an infinity among a dataset's numbers, however spelt (``nan``,
    ``1.#QNAN``, ``1.0D+999``), is refused at its line: pyuff would read
    some as NaN and fail on others with a message of its own."""
    for offset, line in enumerate(ds.lines):
        for token in line.split():
            try:
                finite_float(token, fortran_exponent=True)
            except NonFiniteNumber as error:
                message = f"dataset {ds.number}: {error}"
                raise IdeasMeshError(message, ds.first_line + 1 + offset, filename) from None
            except ValueError:
                continue  # text: pyuff's reader judges it


def _read_nodes(ds: _Dataset, out: _Collected) -> None:
    _refuse_non_finite(ds, out.filename)
    # 781 has the layout of 2411 (label, 3 integers, then 3 coordinates on a line)
    as_number = 2411 if ds.number == 781 else None
    dset = _run_pyuff(ds.number, ds, out.filename, as_number)
    labels = np.asarray(dset["node_nums"], dtype=float)
    count = len(labels)
    xyz = np.column_stack([np.asarray(dset[c], dtype=float) for c in "xyz"])
    if xyz.shape[0] != count:
        raise IdeasMeshError(
            f"dataset {ds.number}: incomplete node records", ds.first_line, out.filename
        )
    step = 1 if ds.number == 15 else 2
    out.node_labels.extend(int(v) for v in labels)
    out.node_xyz.append(xyz)
    out.node_cs.append(np.asarray(dset["def_cs"], dtype=float).astype(int))
    out.node_colors.extend(int(v) for v in np.asarray(dset["color"], dtype=float))
    out.node_lines.extend(ds.first_line + 1 + step * k for k in range(count))


def _read_systems(ds: _Dataset, out: _Collected) -> None:
    if ds.number == 2420:
        dset = _run_pyuff(2420, ds, out.filename)
        pairs = zip(dset["CS_sys_labels"], dset["CS_types"], strict=False)
    else:  # 18: one record of 5 integers, then 2 lines of reals, per system
        records = ds.lines[0::3]
        where = (ds.first_line, out.filename)
        pairs = [tuple(_ints(rec, 10, 2, where)) for rec in records if rec.strip()]
    if out.systems:
        out.skipped.append(ds.number)  # code_aster warns: a second system dataset replaces
        out.systems = {}
    out.systems.update({int(label): int(kind) for label, kind in pairs})


def _element_records(ds: _Dataset, filename: str):
    """(label, graphic code, colour, node count, line index) of each element record,
    and the index of the line after it, for datasets 71, 780 and 2412.

    Own reader: pyuff 2.5.8's 2412 reader takes only the first line of a
    node list, and it reads neither 780 nor 71."""
    i = 0
    lines = ds.lines
    while i < len(lines):
        where = (ds.first_line + 1 + i, filename)
        record = lines[i]
        if not record.strip():
            i += 1
            continue
        if ds.number == 71:
            label, code, _, _, _, color, count = _ints(record, 10, 7, where)
            descriptor = None
        elif ds.number == 780:
            label, descriptor, _, _, _, _, color, count = _ints(record, 10, 8, where)
        else:
            label, descriptor, _, _, color, count = _ints(record, 10, 6, where)
        i += 1
        if descriptor is not None:
            if descriptor in _BEAM_DESCRIPTORS:
                i += 1  # orientation node and cross-section numbers
            code = _DESCRIPTOR_CODES.get(descriptor)
            if code is None:
                raise IdeasMeshUnsupported(
                    f"element {label}: I-DEAS descriptor {descriptor} has no code_aster cell type",
                    *where,
                )
        node_lines = -(-count // 8)  # 8 labels a line
        yield label, code, color, count, i, where[0]
        i += node_lines


def _read_cells(ds: _Dataset, out: _Collected) -> None:
    for label, code, color, count, first, line in _element_records(ds, out.filename):
        if code in _REFUSED_GRAPHIC or code not in _GRAPHIC_TYPES:
            name = _REFUSED_GRAPHIC.get(code, f"graphic code {code}")
            raise IdeasMeshUnsupported(
                f"element {label}: cells of type {name} are not supported", line, out.filename
            )
        where = (ds.first_line + 1 + first, out.filename)
        listed: list[int] = []
        for k in range(-(-count // 8)):
            if first + k >= len(ds.lines):
                raise IdeasMeshError(f"element {label}: node list cut short", *where)
            n_on_line = min(8, count - 8 * k)
            listed.extend(_ints(ds.lines[first + k], 10, n_on_line, where))
        out.cells.append(_Cell(label, code, _aster_order(code, listed), color, line))


def _aster_order(code: int, listed: list[int]) -> list[int]:
    order = _NODE_ORDER.get(code)
    if order is None or len(order) != len(listed):
        return listed
    nodes = [0] * len(listed)
    for position, label in zip(order, listed, strict=True):
        nodes[position - 1] = label
    return nodes


#: group datasets: (column width skipped before the entity count, entities a line)
_GROUP_LAYOUTS = {
    752: (40, 4),
    2417: (50, 4),
    2429: (60, 4),
    2430: (60, 4),
    2432: (60, 4),
    2435: (60, 2),
    2452: (60, 2),
    2467: (60, 2),
    2477: (60, 2),
}

_NODE_ENTITY, _CELL_ENTITY = 7, 8


def _read_groups(ds: _Dataset, out: _Collected) -> None:
    if _GROUP_LAYOUTS[ds.number][1] == 2:
        _read_groups_pyuff(ds, out)
    else:
        _read_groups_fixed(ds, out)


def _read_groups_pyuff(ds: _Dataset, out: _Collected) -> None:
    """Datasets with two entities a line share the layout of 2467, which pyuff reads."""
    as_number = None if ds.number == 2467 else 2467
    dset = _run_pyuff(ds.number, ds, out.filename, as_number)
    line = ds.first_line + 1
    for group in dset["groups"]:
        codes = np.asarray(group["entity_type_code"], dtype=int)
        tags = np.asarray(group["entity_tag"], dtype=int)
        out.groups.append(
            _Group(
                number=int(group["group_number"]),
                name=_raw_group_name(ds, line),
                nodes=[int(t) for t in tags[codes == _NODE_ENTITY]],
                cells=[int(t) for t in tags[codes == _CELL_ENTITY]],
                line=line,
            )
        )
        line += 2 + -(-int(group["number_of_entities_in_group"]) // 2)


def _raw_group_name(ds: _Dataset, line: int) -> str:
    # the converter reads 20 characters of the name line (pyuff keeps 40)
    return ds.lines[line - ds.first_line][:20].strip()


def _read_groups_fixed(ds: _Dataset, out: _Collected) -> None:
    skip, per_line = _GROUP_LAYOUTS[ds.number]
    lines = ds.lines
    i = 0
    while i < len(lines):
        if not lines[i].strip():
            i += 1
            continue
        where = (ds.first_line + 1 + i, out.filename)
        number = _ints(lines[i], 10, 1, where)[0]
        count = _ints(lines[i][10 + skip :], 10, 1, where)[0]
        if i + 1 >= len(lines):
            raise IdeasMeshError(f"group {number}: name line missing", *where)
        name = lines[i + 1][:20].strip()
        nodes: list[int] = []
        cells: list[int] = []
        n_lines = -(-count // per_line)
        for k in range(n_lines):
            row = i + 2 + k
            if row >= len(lines):
                raise IdeasMeshError(f"group {name}: entity list cut short", *where)
            n_on_line = min(per_line, count - per_line * k)
            values = _ints(lines[row], 10, 2 * n_on_line, (where[0] + 2 + k, out.filename))
            for code, tag in zip(values[0::2], values[1::2], strict=True):
                if code == _NODE_ENTITY:
                    nodes.append(tag)
                elif code == _CELL_ENTITY:
                    cells.append(tag)
        out.groups.append(_Group(number, name, nodes, cells, where[0]))
        i += 2 + n_lines


_REFUSED_DATASETS = {
    735: "geometry-attached nodes and cells (dataset 735)",
    82: "trace lines (dataset 82)",
    2431: "trace lines (dataset 2431)",
}


def _collect(datasets: list[_Dataset], filename: str) -> _Collected:
    out = _Collected(filename)
    for ds in datasets:
        if ds.number in (15, 781, 2411):
            _read_nodes(ds, out)
        elif ds.number in (71, 780, 2412):
            _read_cells(ds, out)
        elif ds.number in _GROUP_LAYOUTS:
            _read_groups(ds, out)
        elif ds.number in (18, 2420):
            _read_systems(ds, out)
        elif ds.number in _REFUSED_DATASETS:
            raise IdeasMeshUnsupported(
                f"{_REFUSED_DATASETS[ds.number]} is not supported", ds.first_line, filename
            )
        else:
            out.skipped.append(ds.number)
    return out


# -- mapping to code_aster's mesh -----------------------------------------------

_IDENTIFIER = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
_IDENTIFIER_END = set(" +-.=():;,%&*/!")


def group_name(raw: str, number: int, kind: str) -> tuple[str | None, str]:
    """code_aster's name for an I-DEAS group (``kind`` 'GROUP_NO' or 'GROUP_MA'),
    or None when the converter drops it; and a note when the name was changed."""
    if raw.startswith("PERMANENT"):
        return ("GRNO" if kind == "GROUP_NO" else "GRMA") + str(number), ""
    short = raw[:8]
    match = _IDENTIFIER.match(short)
    end = match.end() if match else 0
    if not match or (end < len(short) and short[end] not in _IDENTIFIER_END):
        return None, f"group name {raw!r} is not a valid name: group dropped"
    name = match.group()
    if kind == "GROUP_MA" and name.startswith("COUL_"):
        return None, f"group {raw!r}: a name may not start with COUL_: cell group dropped"
    note = f"group name {raw!r} cut to {name!r}" if name != raw else ""
    return name, note


def _nodes_xyz(col: _Collected) -> np.ndarray:
    if not col.node_xyz:
        return np.zeros((0, 3))
    xyz = np.vstack(col.node_xyz)
    # the converter passes coordinates through its ASTER text (1PE21.14): 15 digits
    return np.array([float(f"{v:.14E}") for v in xyz.ravel()]).reshape(xyz.shape)


def _check_systems(col: _Collected) -> None:
    if not col.systems:
        return
    cs = np.concatenate(col.node_cs) if col.node_cs else np.zeros(0, dtype=int)
    for k, label in enumerate(cs):
        if col.systems.get(int(label), 0) != 0:
            raise IdeasMeshUnsupported(
                f"node {col.node_labels[k]} is given in coordinate system {label}, which is "
                "not Cartesian (code_aster reads Cartesian coordinates only)",
                col.node_lines[k],
                col.filename,
            )


def _build_mesh(col: _Collected, color_groups: bool) -> Mesh:
    if not col.node_labels and not col.cells:
        raise IdeasMeshError("no node, cell or group dataset found", 0, col.filename)
    _check_systems(col)
    node_names = [f"N{label}" for label in col.node_labels]
    node_index: dict[str, int] = {}
    for k, name in enumerate(node_names):
        if name in node_index:
            raise IdeasMeshError(f"node {name} defined twice", col.node_lines[k], col.filename)
        node_index[name] = k

    # cells type by type in the converter's type order, file order within a type
    ordered = sorted(col.cells, key=lambda c: c.code)
    cell_names, cell_types, cell_nodes = [], [], []
    cell_index: dict[str, int] = {}
    for cell in ordered:
        name = f"M{cell.label}"
        if name in cell_index:
            raise IdeasMeshError(f"cell {name} defined twice", cell.line, col.filename)
        try:
            cell_nodes.append(tuple(node_index[f"N{n}"] for n in cell.nodes))
        except KeyError as exc:
            raise IdeasMeshError(
                f"cell {name} uses unknown node {exc.args[0]}", cell.line, col.filename
            ) from None
        cell_index[name] = len(cell_names)
        cell_names.append(name)
        cell_types.append(_GRAPHIC_TYPES[cell.code])

    node_groups, cell_groups, notes = _build_groups(col, node_index, cell_index)
    if color_groups:
        _add_color_groups(col, node_groups, cell_groups, cell_index)
    mesh = Mesh(
        coords=_nodes_xyz(col),
        node_names=node_names,
        cell_names=cell_names,
        cell_types=cell_types,
        cell_nodes=cell_nodes,
        node_groups=node_groups,
        cell_groups=cell_groups,
        dim=3,  # the converter always writes COOR_3D
        title="AUTEUR=INTERFACE_IDEAS",
    )
    mesh.ideas_notes = notes
    mesh.ideas_skipped = sorted(set(col.skipped))
    return mesh


def _build_groups(col: _Collected, node_index, cell_index):
    node_groups: dict[str, np.ndarray] = {}
    cell_groups: dict[str, np.ndarray] = {}
    notes: list[str] = []
    for group in col.groups:
        for kind, members, table, lookup, prefix in (
            ("GROUP_NO", group.nodes, node_groups, node_index, "N"),
            ("GROUP_MA", group.cells, cell_groups, cell_index, "M"),
        ):
            if not members:
                continue
            name, note = group_name(group.name, group.number, kind)
            if note:
                notes.append(note)
            if name is None:
                continue
            if name in table:
                raise IdeasMeshError(f"{kind} {name} defined twice", group.line, col.filename)
            try:
                table[name] = np.array([lookup[f"{prefix}{m}"] for m in members], dtype=int)
            except KeyError as exc:
                raise IdeasMeshError(
                    f"group {group.name!r} names unknown {exc.args[0]}", group.line, col.filename
                ) from None
    return node_groups, cell_groups, notes


def _add_color_groups(col: _Collected, node_groups, cell_groups, cell_index) -> None:
    by_color: dict[int, list[int]] = {}
    for k, color in enumerate(col.node_colors):
        by_color.setdefault(color, []).append(k)
    for color in sorted(by_color):
        node_groups[f"COUL_{color}"] = np.array(by_color[color], dtype=int)
    by_color = {}
    for cell in col.cells:  # file order, as the converter lists them
        by_color.setdefault(cell.color, []).append(cell_index[f"M{cell.label}"])
    for color in sorted(by_color):
        cell_groups[f"COUL_{color}"] = np.array(by_color[color], dtype=int)


def parse_ideas_mesh(text: str, filename: str = "", color_groups: bool = False) -> Mesh:
    """Build a :class:`Mesh` from the text of an I-DEAS universal file."""
    datasets = _split_datasets(text, filename)
    if not datasets:
        raise IdeasMeshError("no I-DEAS dataset found (no '    -1' delimiter)", 0, filename)
    return _build_mesh(_collect(datasets, filename), color_groups)


def read_ideas_mesh(path: str | Path, color_groups: bool = False) -> Mesh:
    """Read an I-DEAS universal file mesh (refused before reading when parsing it
    would pass the run's memory limit)."""

    path = Path(path)
    try:
        text = read_bounded_text(path, "I-DEAS mesh", PARSE_BYTES_PER_BYTE)
    except InputFileError as error:
        raise IdeasMeshError(str(error).split(": ", 1)[-1], 0, str(path)) from None
    return parse_ideas_mesh(text, str(path), color_groups)
