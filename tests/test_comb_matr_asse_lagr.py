"""COMB_MATR_ASSE SANS_CMP='LAGR' on physical matrices: code_aster sums the
matrices without their Lagrange multiplier terms; asterlite's matrices hold the
physical DOFs only, so the result is the physical combination (a Rayleigh
damping C = a M + b K whose modal ratios are (a / w + b w) / 2)."""

from __future__ import annotations

import numpy as np
import scipy.linalg

from tests.test_fem_support import chain_matrices, run

K, M, N = 1.0e4, 2.0, 6
ALPHA, BETA = 5.0, 5.0e-4


def test_rayleigh_damping_without_lagrange_terms():
    session, model, k, m = chain_matrices(
        N,
        (K, K, K),
        M,
        ddl_impo=[{"GROUP_NO": "FIRST", "DX": 0.0}, {"TOUT": "OUI", "DY": 0.0, "DZ": 0.0}],
    )
    assert k.numbering.relations, "the chain is constrained (code_aster has Lagrange terms)"
    c = run(
        session,
        "COMB_MATR_ASSE",
        COMB_R=[{"MATR_ASSE": m, "COEF_R": ALPHA}, {"MATR_ASSE": k, "COEF_R": BETA}],
        SANS_CMP="LAGR",
    )
    assert c.numbering is k.numbering
    expected = ALPHA * m.matrix.toarray() + BETA * k.matrix.toarray()
    np.testing.assert_allclose(c.matrix.toarray(), expected, rtol=1e-15)
    # modal damping ratios of the clamped-free chain (DX of N2..N6 free)
    free = k.numbering.dof_indices(range(1, N), "DX")
    kf, mf, cf = (a.matrix.toarray()[np.ix_(free, free)] for a in (k, m, c))
    w2, phi = scipy.linalg.eigh(kf, mf)
    omega = np.sqrt(w2)
    ratios = np.einsum("ji,jk,ki->i", phi, cf, phi) / (2.0 * omega)
    np.testing.assert_allclose(ratios, 0.5 * (ALPHA / omega + BETA * omega), rtol=1e-12)
