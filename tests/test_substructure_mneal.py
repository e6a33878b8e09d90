"""MacNeal interfaces: one attachment mode (static response to a unit force)
per interface DOF that the matrices leave free; a DOF they block carries
none (code_aster's DEFI_INTERF_DYNA leaves blocked components out of an
MNEAL interface's deformations: gesdef/maskmn)."""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from asterlite.concepts.assembly import DofNumbering, LinearRelation
from asterlite.substructure.interfaces import static_modes


def _two_direction_chain(n: int, k: float):
    """n nodes with DX and DY, springs k between neighbours in each
    direction; node 0 clamped in both, the last node's DX blocked."""
    dofs = [(node, comp) for node in range(n) for comp in ("DX", "DY")]
    numbering = DofNumbering(mesh=None, dofs=dofs)
    numbering.relations = [
        LinearRelation([(0, "DX", 1.0)]),
        LinearRelation([(0, "DY", 1.0)]),
        LinearRelation([(n - 1, "DX", 1.0)]),
    ]
    stiffness = np.zeros((2 * n, 2 * n))
    for e in range(n - 1):
        for c in range(2):
            i, j = 2 * e + c, 2 * (e + 1) + c
            stiffness[np.ix_([i, j], [i, j])] += k * np.array([[1.0, -1.0], [-1.0, 1.0]])
    return numbering, sp.csr_matrix(stiffness)


def test_blocked_interface_dofs_carry_no_attachment_mode():
    n, k = 5, 2.0e3
    numbering, stiffness = _two_direction_chain(n, k)
    last = n - 1
    interface = np.array([numbering.index[(last, "DX")], numbering.index[(last, "DY")]])
    modes, owners = static_modes("MNEAL", interface, numbering, stiffness)
    assert owners.tolist() == [numbering.index[(last, "DY")]]
    assert modes.shape == (2 * n, 1)
    # a unit force at the free end of the DY chain: u_i = i / k at node i
    expected = np.zeros(2 * n)
    expected[1::2] = np.arange(n) / k
    assert np.allclose(modes[:, 0], expected, rtol=1e-12, atol=1e-15)
