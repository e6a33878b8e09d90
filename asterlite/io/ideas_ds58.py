"""Universal file dataset 58 (function at a node and direction), as code_aster's
LIRE_RESU FORMAT='IDEAS_DS58' reads it (lect58, lectvl).

Each dataset: a ``-1`` line, ``58``, eleven header records, the values, a
``-1`` line. Record 6 holds the response node (field 6, a label; 0: the
entity name in columns 32-41 names it) and its direction (field 7, ±1..3
for X, Y, Z); record 7 the data kind (field 1: 2 or 4 real, 5 or 6 complex,
single or double precision), the number of values (field 2), whether the
abscissas are evenly spaced (field 3, 1: even, from field 4 with step field 5);
record 9 the ordinate kind (field 1: 2 stress, 3 strain, 8 displacement,
11 velocity, 12 acceleration). Values are in fixed columns: 6 per line of
13 characters in single precision, 4 of 20 in double; complex values are
(real, imaginary) pairs, uneven abscissas precede each value.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

#: record 9's ordinate kind of each field name
ORDINATE_KIND = {"SIEF_NOEU": 2, "EPSI_NOEU": 3, "DEPL": 8, "VITE": 11, "ACCE": 12}


class Ds58ReadError(ValueError):
    """A dataset 58 that cannot be read."""


@dataclass
class Ds58Function:
    node_label: int  # 0 when the node is named by ``node_name``
    node_name: str
    direction: int  # ±1, ±2, ±3
    ordinate_kind: int
    abscissas: np.ndarray
    values: np.ndarray  # real or complex, one per abscissa

    @property
    def is_complex(self) -> bool:
        return np.iscomplexobj(self.values)


def read_datasets_58(path: Path | str) -> list[Ds58Function]:
    lines = Path(path).read_text(errors="replace").splitlines()
    out = []
    i = 0
    while i < len(lines):
        if lines[i].strip() == "-1" and i + 1 < len(lines) and lines[i + 1].strip() == "58":
            function, i = _dataset(lines, i + 2)
            out.append(function)
        else:
            i += 1
    return out


def _int_field(record: str, position: int) -> int:
    fields = record.split()
    try:
        return int(fields[position - 1])
    except (IndexError, ValueError) as exc:
        raise Ds58ReadError(f"record {record!r}: no integer field {position}") from exc


def _real_field(record: str, position: int) -> float:
    fields = record.split()
    try:
        return float(fields[position - 1].replace("D", "E"))
    except (IndexError, ValueError) as exc:
        raise Ds58ReadError(f"record {record!r}: no real field {position}") from exc


def _dataset(lines: list[str], start: int) -> tuple[Ds58Function, int]:
    records = lines[start : start + 11]
    if len(records) < 11:
        raise Ds58ReadError("a dataset 58 ends within its header")
    rec6, rec7, rec9 = records[5], records[6], records[8]
    nature = _int_field(rec7, 1)
    count = _int_field(rec7, 2)
    even = _int_field(rec7, 3) == 1
    label = _int_field(rec6, 6)
    name = rec6[31:41].strip() if label == 0 else ""
    if nature not in (2, 4, 5, 6):
        raise Ds58ReadError(f"data kind {nature} (2, 4: real; 5, 6: complex)")
    width, per_line = (13, 6) if nature in (2, 5) else (20, 4)
    per_value = (2 if nature in (5, 6) else 1) + (0 if even else 1)
    wanted = count * per_value
    numbers: list[float] = []
    i = start + 11
    while len(numbers) < wanted:
        if i >= len(lines) or lines[i].strip() == "-1":
            raise Ds58ReadError(f"a dataset 58 has fewer than its {count} values")
        text = lines[i]
        for k in range(per_line):
            cell = text[k * width : (k + 1) * width].strip()
            if cell and len(numbers) < wanted:
                numbers.append(float(cell.replace("D", "E")))
        i += 1
    while i < len(lines) and lines[i].strip() != "-1":
        i += 1
    data = np.array(numbers).reshape(count, per_value)
    if even:
        abscissas = _real_field(rec7, 4) + np.arange(count) * _real_field(rec7, 5)
    else:
        abscissas, data = data[:, 0], data[:, 1:]
    values = data[:, 0] + 1j * data[:, 1] if nature in (5, 6) else data[:, 0]
    return (
        Ds58Function(
            node_label=label,
            node_name=name,
            direction=_int_field(rec6, 7),
            ordinate_kind=_int_field(rec9, 1),
            abscissas=np.asarray(abscissas, dtype=float),
            values=values,
        ),
        i + 1,
    )
