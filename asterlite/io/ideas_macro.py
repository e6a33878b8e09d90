"""A dynamic macro-element as an I-DEAS universal file (IMPR_MACR_ELEM).

The datasets follow code_aster's writer, in this order:

- ``481`` (a name record) before each block: ``Junc``, ``Phi_a`` (once
  per dynamic mode), ``Psi_a``, ``Mgen_a``, ``Kgen_a``, ``Mbar_a``,
  ``Kbar_a``, ``Lmat_a``;
- ``757`` the junction DOFs: per interface node its number, 7, and a 0/1
  flag for DX DY DZ DRX DRY DRZ (the components carrying a static mode);
- ``55`` nodal values of each basis vector (dynamic modes one dataset
  each, then the static modes);
- ``252`` dense matrices (type 4, full, column count 2 in the header) in
  ``1P4D20.12`` rows: the generalized mass and stiffness of the dynamic
  modes, of the static modes, and the mass coupling static x dynamic.
"""

from __future__ import annotations

import math

import numpy as np

COMPONENTS = ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")
SEPARATOR = "    -1"


def fortran_exponent(value: float, width: int, digits: int, letter="E", exp_digits=2) -> str:
    """Fortran ``1PEw.dEe`` / ``1PDw.d``: one digit before the point."""
    if not math.isfinite(value):
        return str(value).rjust(width)
    if value == 0.0:
        mantissa, exponent = 0.0, 0
    else:
        exponent = int(math.floor(math.log10(abs(value))))
        mantissa = value / 10.0**exponent
        if round(abs(mantissa), digits) >= 10.0:  # rounding carried a digit
            mantissa /= 10.0
            exponent += 1
    sign = "-" if exponent < 0 else "+"
    text = f"{mantissa:.{digits}f}{letter}{sign}{abs(exponent):0{exp_digits}d}"
    return text.rjust(width)


def name_record(name: str) -> list[str]:
    """Dataset 481 holding a name (written as 2-character pairs)."""
    return [SEPARATOR, "   481", f"{1:10d}", name, SEPARATOR]


def junction(mesh, numbering, static_dofs) -> list[str]:
    """Dataset 757: the interface nodes and the components of their static modes."""
    flags: dict[int, set[str]] = {}
    for dof in static_dofs:
        node, comp = numbering.dofs[int(dof)]
        flags.setdefault(int(node), set()).add(comp)
    lines = [SEPARATOR, "   757", f"{1:10d}", "DDL JONCTION"]
    for node, comps in flags.items():
        bits = "".join(f"{int(c in comps):2d}" for c in COMPONENTS)
        lines.append(f"{node + 1:10d}{7:10d}{bits}")
    return lines + [SEPARATOR]


def nodal_values(basis, column: int, title: str, subtitle: str) -> list[str]:
    """Dataset 55 of one basis vector (analysis type 2: a mode, with its
    number, frequency and generalized mass)."""
    numbering = basis.numbering
    mesh = numbering.mesh
    freq = float(np.asarray(basis.frequencies)[column])
    mass = float(np.asarray(basis.parameters.get("MASS_GENE", basis.generalized_mass))[column])
    number = int(np.asarray(basis.mode_numbers)[column])
    head = f"{title} - {subtitle}"[:80]
    lines = [SEPARATOR, "    55   %VALEURS AUX NOEUDS", head]
    lines.append(f"{title} - {' '.join(COMPONENTS)}"[:80])
    lines += [title[:80], subtitle[:80], ""]
    lines.append("".join(f"{v:10d}" for v in (1, 2, 3, 8, 2, 6)))
    lines.append("".join(f"{v:10d}" for v in (2, 4, column + 1, number)))
    lines.append("".join(fortran_exponent(v, 13, 5, exp_digits=3) for v in (freq, mass, 0, 0)))
    values = basis.shapes[:, column]
    for node in sorted({n for n, _ in numbering.dofs}):
        row = [numbering.index.get((node, c)) for c in COMPONENTS]
        data = [float(values[r]) if r is not None else 0.0 for r in row]
        lines.append(f"{node + 1:10d}     % NOEUD {mesh.node_names[node]}")
        lines.append("".join(fortran_exponent(v, 13, 5, exp_digits=3) for v in data))
    return lines + [SEPARATOR]


def matrix_record(code: int, matrix: np.ndarray, shape=None) -> list[str]:
    """Dataset 252: a full real matrix, values column after column, 4 a row
    (``shape``: the sizes written in the header, when not the matrix's)."""
    rows, cols = matrix.shape if shape is None else shape
    lines = [SEPARATOR, "   252", f"{code:10d}"]
    lines.append("".join(f"{v:10d}" for v in (4, 1, rows, cols, 2)))
    values = np.asarray(matrix, dtype=float).ravel(order="F")
    for start in range(0, values.size, 4):
        chunk = values[start : start + 4]
        lines.append("".join(fortran_exponent(v, 20, 12, letter="D") for v in chunk))
    return lines + [SEPARATOR]


def macro_element_lines(macro, name: str = "") -> list[str]:
    """The whole file of a macro-element whose basis holds the dynamic modes
    first, then the static modes (DEFI_BASE_MODALE CLASSIQUE's order)."""
    basis = macro.basis
    kinds = np.asarray(basis.parameters.get("TYPE_MODE", ["MODE_DYN"] * basis.n_modes))
    static = np.flatnonzero(kinds == "MODE_STA")
    dynamic = np.flatnonzero(kinds != "MODE_STA")
    lines: list[str] = []
    static_dofs = [
        basis.numbering.index[_dof_of(basis, label)]
        for label in np.asarray(basis.parameters.get("NOEUD_CMP"))[static]
    ]
    if static.size:
        lines += name_record("Junc") + junction(basis.numbering.mesh, basis.numbering, static_dofs)
    for k in dynamic:
        lines += name_record("Phi_a ") + nodal_values(basis, int(k), "MODE DYNAMIQUE", name)
    if static.size:
        lines += name_record("Psi_a ")
        for k in static:
            lines += nodal_values(basis, int(k), "MODE STATIQUE", name)
    mass, stiffness = np.asarray(macro.mass), np.asarray(macro.stiffness)
    dyn, sta = np.ix_(dynamic, dynamic), np.ix_(static, static)
    lines += name_record("Mgen_a") + matrix_record(131, mass[dyn])
    lines += name_record("Kgen_a") + matrix_record(139, stiffness[dyn])
    if static.size:
        lines += name_record("Mbar_a") + matrix_record(134, mass[sta])
        lines += name_record("Kbar_a") + matrix_record(142, stiffness[sta])
        # static x dynamic mass coupling, static index fastest (code_aster's
        # layout), under a header that gives the dynamic count first
        coupling = mass[np.ix_(static, dynamic)]
        shape = (dynamic.size, static.size)
        lines += name_record("Lmat_a") + matrix_record(132, coupling, shape)
    return lines


def _dof_of(basis, label: str) -> tuple[int, str]:
    """(node index, component) of a NOEUD_CMP label ``"N3 DX"``."""
    node_name, comp = str(label).split()
    return basis.numbering.mesh.find_node(node_name), comp
