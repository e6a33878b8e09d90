"""POST_GENE_PHYS of a harm_gene (code_aster's pgpcrt): complex values
u(f) = Φ_rows q(f) at the chosen frequencies, in a table with FREQ and VALE_C
(components outer, nodes inner); RECU_FONCTION of its FREQ / VALE_C columns
is a fonction_c."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.function import ComplexFunction
from asterlite.concepts.harmonic import HarmGene
from asterlite.errors import CommandError
from tests.test_fem_support import chain_matrices, run

K_VALUES = (4.0e4, 9.0e4, 1.6e5)


def _harm_gene():
    session, _, k, m = chain_matrices(3, K_VALUES, 2.0)
    modes = run(session, "CALC_MODES", MATR_RIGI=k, MATR_MASS=m, CALC_FREQ={"NMAX_FREQ": 4})
    q = np.array([[1.0 + 2.0j, -0.5j, 0.25, 3.0], [2.0, 1.0j, -1.0, 0.5 + 0.5j]])
    result = HarmGene(
        basis=modes,
        numbering=None,
        frequencies=np.array([5.0, 15.0]),
        order=np.array([1, 2]),
        fields={"DEPL": q},
    )
    return session, modes, result


def test_values_are_the_recombined_complex_displacements():
    session, modes, result = _harm_gene()
    table = run(
        session,
        "POST_GENE_PHYS",
        RESU_GENE=result,
        OBSERVATION={"NOM_CHAM": "DEPL", "NOM_CMP": ("DX", "DY"), "GROUP_NO": "ENDS", "FREQ": 15.0},
    )
    assert "VALE_C" in table.types and "INST" not in table.types and "VALE_R" not in table.types
    assert table.column("FREQ") == [15.0] * 4
    assert table.column("NOM_CMP") == ["DX", "DX", "DY", "DY"]  # components outer, nodes inner
    numbering = modes.numbering
    expected = [
        complex(np.asarray(modes.shapes)[numbering.index[(node, comp)]] @ result.fields["DEPL"][1])
        for comp in ("DX", "DY")
        for node in (0, 2)
    ]
    np.testing.assert_allclose(table.column("VALE_C"), expected, rtol=1e-14)
    assert any(abs(v.imag) > 0 for v in table.column("VALE_C"))
    function = run(session, "RECU_FONCTION", TABLE=table, PARA_X="FREQ", PARA_Y="VALE_C")
    assert isinstance(function, ComplexFunction)


def test_instants_do_not_apply_to_a_harm_gene():
    session, _, result = _harm_gene()
    with pytest.raises(CommandError, match="INST applies to transient results"):
        run(
            session,
            "POST_GENE_PHYS",
            RESU_GENE=result,
            OBSERVATION={"NOM_CHAM": "DEPL", "GROUP_NO": "ENDS", "INST": 1.0},
        )
