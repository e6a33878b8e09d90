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
