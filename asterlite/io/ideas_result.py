"""Nodal fields of results in I-DEAS universal file format, dataset 55
("VALEURS AUX NOEUDS"), laid out as code_aster's IMPR_RESU(FORMAT='IDEAS')
writes them (ecrtes, irdesr, irdesc):

- ten header records: ``-1``, ``55``, five title lines, record 6
  ``model type, analysis type, data characteristic, data type, value type,
  values per node`` (6I10: 1, then 2 for modes / 4 for a transient / 5 for a
  harmonic result, 3 for 6-DOF data, 8 / 11 / 12 for DEPL / VITE / ACCE, 2
  for reals / 5 for complex values, 6), record 7 (8I10: for modes 2, 4, the
  order and the mode number; otherwise 2, 1, 1, the order), record 8
  (6E13.5: the frequency and for modes the generalized mass and damping, or
  the instant);
- then, node by node, the node number and ``% NOEUD name``, and the six
  slots DX DY DZ DRX DRY DRZ (zero where the node lacks the DOF) in
  1PE13.5E3 for reals, real and imaginary parts interleaved in 1PE13.5 for
  complex values (two lines of six);
- ``-1`` to close the dataset.

The title lines name the result and the field; code_aster's carry its own
version and date, the only difference. LIRE_RESU finds the records by
position (RECORD_6, POSI_ORDRE, POSI_FREQ...).
"""

from __future__ import annotations

import math
import re
import sys

import numpy as np

SLOTS = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")
DATA_TYPES = {"DEPL": 8, "VITE": 11, "ACCE": 12}


def fortran_e(value: float, exponent_digits: int = 2) -> str:
    """Fortran 1PE13.5 (or 1PE13.5E3 with ``exponent_digits=3``)."""
    mantissa, exponent = f"{float(value):.5E}".split("E")
    sign = "-" if exponent.startswith("-") else "+"
    text = f"{mantissa}E{sign}{abs(int(exponent)):0{exponent_digits}d}"
    return text.rjust(13)


def _line80(text: str) -> str:
    return text[:80].ljust(80)


def header(title: str, subtitle: str, components: str, record_6, record_7, record_8) -> list:
    """The ten header records (ecrtes), entete(4) naming the components."""
    sub = subtitle[: min(len(subtitle), 36)]
    head = title[: min(len(title), 72 - len(sub))]
    width = min(len(title), 80 - len(components) - 2)
    return [
        "    -1",
        "    55   %VALEURS AUX NOEUDS",
        _line80(f"{head} - {sub}"),
        _line80(f"{title[:width]} - {components}"),
        _line80(title),
        _line80(subtitle),
        _line80(""),
        "".join(f"{v:10d}" for v in record_6),
        "".join(f"{v:10d}" for v in record_7),
        "".join(fortran_e(v, 3) for v in record_8),
    ]


def field_lines(
    numbering, values, field: str, analysis: int, record_7, record_8, title: str, subtitle: str,
    nodes=None,
) -> list[str]:  # fmt: skip
    """One dataset 55 of one nodal field (``values`` on ``numbering``'s DOFs,
    real or complex) on the nodes carrying it (``nodes``: a subset, mesh
    order kept). Empty when no node carries a slot component."""
    values = np.asarray(values)
    complex_values = np.iscomplexobj(values)
    mesh = numbering.mesh
    by_node: dict[int, dict[str, int]] = {}
    for row, (node, component) in enumerate(numbering.dofs):
        if component in SLOTS:
            by_node.setdefault(int(node), {})[component] = row
    present = [c for c in SLOTS if any(c in comps for comps in by_node.values())]
    chosen = sorted(by_node) if nodes is None else [n for n in sorted(by_node) if n in set(nodes)]
    if not chosen:
        return []
    record_6 = (1, analysis, 3, DATA_TYPES.get(field, 0), 5 if complex_values else 2, 6)
    lines = header(title, subtitle, " ".join(present), record_6, record_7, record_8)
    for node in chosen:
        slots = np.zeros(6, dtype=values.dtype)
        for k, component in enumerate(SLOTS):
            row = by_node[node].get(component)
            if row is not None:
                slots[k] = values[row]
        lines.append(f"{node + 1:10d}     % NOEUD {mesh.node_names[node]}")
        if complex_values:
            pairs = np.column_stack([slots.real, slots.imag]).ravel()
            lines.append("".join(fortran_e(v) for v in pairs[:6]))
            lines.append("".join(fortran_e(v) for v in pairs[6:]))
        else:
            lines.append("".join(fortran_e(v, 3) for v in slots))
    lines.append("    -1")
    return lines


# ----------------------------------------------------------------------------- reading


class IdeasReadError(ValueError):
    pass


def read_datasets_55(path) -> list[dict]:
    """Every dataset 55 of a universal file: ``records`` (the eight records
    after the ``55`` line, as text), ``labels`` and ``names`` of the nodes
    and ``values`` (n_nodes, n_values), complex when record 6's value type is
    5 or 6 (real and imaginary parts interleaved), as code_aster's lridea
    reads them (I10, A13, A8 node lines; 6E13.5 value lines)."""
    lines = open(path, encoding="utf-8", errors="replace").read().splitlines()
    out = []
    i = 0
    while i < len(lines):
        if lines[i][:6] != "    55":
            i += 1
            continue
        records = lines[i + 1 : i + 9]
        if len(records) < 8:
            raise IdeasReadError("a dataset 55 ends within its header")
        record_6 = [int(t) for t in records[5].split()]
        if len(record_6) < 6:
            raise IdeasReadError(f"record 6 of a dataset 55 has {len(record_6)} fields, not 6")
        complex_values = record_6[4] in (5, 6)
        count = record_6[5] * (2 if complex_values else 1)
        per_line = 6
        i += 9
        labels, names, rows = [], [], []
        while i < len(lines):
            head = lines[i]
            label = int(head[:10])
            if label == -1:
                i += 1
                break
            labels.append(label)
            names.append(head[23:31].strip() if len(head) > 23 else "")
            i += 1
            values: list[float] = []
            while len(values) < count:
                text = lines[i]
                values.extend(
                    fortran_float(text[13 * k : 13 * (k + 1)])
                    for k in range(per_line)
                    if text[13 * k : 13 * (k + 1)].strip()
                )
                i += 1
            values = np.asarray(values[:count])
            rows.append(values[0::2] + 1j * values[1::2] if complex_values else values)
        out.append(
            {
                "records": records,
                "labels": np.asarray(labels, dtype=int),
                "names": names,
                "values": np.asarray(rows),
            }
        )
    return out


_NO_EXPONENT_LETTER = re.compile(r"^([+-]?[0-9.]+)([+-][0-9]+)$")


def fortran_float(text: str) -> float:
    """A real as Fortran writes it: ``1.5D+02``, or ``0.17977+309`` where a
    three-digit exponent leaves no room for the letter. The largest real,
    rounded up when written (code_aster's R8MAEM), reads as the largest real."""
    text = text.strip().replace("D", "E").replace("d", "e")
    match = _NO_EXPONENT_LETTER.match(text)
    if match:
        text = f"{match.group(1)}E{match.group(2)}"
    value = float(text)
    if math.isinf(value) and "inf" not in text.lower():
        return math.copysign(sys.float_info.max, value)
    return value


def record_field(records, record: int, field: int) -> str:
    """Field ``field`` (1-based, blank-separated) of record ``record`` (1-based)."""
    tokens = records[record - 1].split()
    if not 1 <= field <= len(tokens):
        raise IdeasReadError(f"record {record} has no field {field}")
    return tokens[field - 1]
