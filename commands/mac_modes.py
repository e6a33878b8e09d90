"""MAC_MODES: the modal assurance criterion of two bases (code_aster's op0141).

For modes x_i of BASE_1 and y_j of BASE_2 (both on one numbering) and W
the MATR_ASSE (identity without it), with <a, b> = aᵀ conj(W b):
MAC_ij = |<x_i, y_j>|² / (|<x_i, x_i>| |<y_j, y_j>|); with IERI='OUI' the
energy indicator IERI_ij = |<d, d>|² / (|<x_i, x_i>|² + |<y_j, y_j>|²) of
d = x_i - y_j. Real bases add Y1_W_Y2 = |<x_i, y_j>|; there code_aster
forms d with BASE_2's i-th mode instead of the j-th (op0141's indexing),
which is kept so that the tables agree. Complex and real bases cannot be
mixed. Rows: NUME_MODE_1 = i, NUME_MODE_2 = j (positions, from 1).
"""

from __future__ import annotations

import numpy as np

from asterlite.concepts.table import Table
from asterlite.modal.renumber import same_dofs


def run(ctx, kw):
    first, second = kw["BASE_1"], kw["BASE_2"]
    for keyword, base in (("BASE_1", first), ("BASE_2", second)):
        if not hasattr(base, "shapes"):
            ctx.unsupported(f"MAC_MODES of a {base.aster_type}", keyword, kw)
    if not same_dofs(first.numbering, second.numbering):
        ctx.error("BASE_1 and BASE_2 are not on the same numbering", "BASE_2", kw)
    x, y = np.asarray(first.shapes), np.asarray(second.shapes)
    complex_values = np.iscomplexobj(x) and np.iscomplexobj(y)
    if np.iscomplexobj(x) != np.iscomplexobj(y):
        ctx.error("one base is complex and the other real", "BASE_2", kw)
    matrix = kw.get("MATR_ASSE")
    if matrix is not None and not same_dofs(matrix.numbering, first.numbering):
        ctx.error("MATR_ASSE is not on the bases' numbering", "MATR_ASSE", kw)
    ieri = kw.get("IERI") == "OUI"

    def weighted(v):
        return v if matrix is None else matrix.matrix @ v

    def product(a, b):
        """<a, b> for every column pair: aᵀ conj(W b)."""
        return a.T @ np.conj(weighted(b))

    own_x = np.abs(np.einsum("di,di->i", x, np.conj(weighted(x))))
    own_y = np.abs(np.einsum("dj,dj->j", y, np.conj(weighted(y))))
    cross = np.abs(product(x, y))
    table = Table(title=kw.get("TITRE") or "")
    criterion = "IERI" if ieri else "MAC"
    for i in range(x.shape[1]):
        for j in range(y.shape[1]):
            if ieri:
                # op0141: complex bases use y_j, real ones y_i
                k = j if complex_values else i
                if k >= y.shape[1]:
                    ctx.error("IERI of real bases needs BASE_2 to have as many modes", "BASE_2")
                d = x[:, i] - y[:, k]
                energy = abs(d @ np.conj(weighted(d)))
                value = energy**2 / (own_x[i] ** 2 + own_y[j] ** 2)
            else:
                value = cross[i, j] ** 2 / (own_x[i] * own_y[j])
            row = {"NUME_MODE_1": i + 1, "NUME_MODE_2": j + 1, criterion: float(value)}
            if not complex_values:
                row["Y1_W_Y2"] = float(cross[i, j])
            table.add_row(row, {"NUME_MODE_1": "I", "NUME_MODE_2": "I"})
    if kw.get("INFO", 1) == 2:
        for row in table.rows:
            ctx.log(
                f"{row['NUME_MODE_1']:4d} {row['NUME_MODE_2']:4d} {criterion} = "
                f"{row[criterion]:.6e}"
            )
    return table
