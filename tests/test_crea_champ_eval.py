"""CREA_CHAMP of a field of functions (TYPE_CHAM='NOEU_NEUT_F', AFFE VALE_F)
and its evaluation (OPERATION='EVAL') with the parameters read from the
components of CHAM_PARA fields (the geometry's X, Y, Z, a NEUT_R's X1...)."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.assembly import NodalField
from asterlite.errors import CommandError
from tests.test_fem_support import FakeSession, chain_mesh, run


def test_neut_f_field_evaluated_on_the_geometry_and_a_neut_r_field():
    session = FakeSession()
    mesh = chain_mesh(5, length=4.0)  # nodes at x = 0, 1, 2, 3, 4
    geometry = run(
        session, "CREA_CHAMP", TYPE_CHAM="NOEU_GEOM_R", OPERATION="EXTR", MAILLAGE=mesh,
        NOM_CHAM="GEOMETRIE",
    )  # fmt: skip
    along_x = run(session, "FORMULE", VALE="3.6e10 * X / 200.0", NOM_PARA=("X",))
    mixed = run(session, "FORMULE", VALE="X * X1 + 1.0", NOM_PARA=("X", "X1"))
    constant = run(session, "DEFI_CONSTANTE", VALE=7.0)
    functions = run(
        session, "CREA_CHAMP", TYPE_CHAM="NOEU_NEUT_F", OPERATION="AFFE", MAILLAGE=mesh,
        AFFE=[
            {"GROUP_NO": "ENDS", "NOM_CMP": ("X1", "X2"), "VALE_F": (along_x, constant)},
        ],
    )  # fmt: skip
    values = run(
        session, "CREA_CHAMP", TYPE_CHAM="NOEU_NEUT_R", OPERATION="EVAL", CHAM_F=functions,
        CHAM_PARA=(geometry,),
    )  # fmt: skip
    assert isinstance(values, NodalField)
    assert values.numbering.dofs == [(0, "X1"), (0, "X2"), (4, "X1"), (4, "X2")]
    np.testing.assert_allclose(values.values, [0.0, 7.0, 3.6e10 * 4.0 / 200.0, 7.0])
    # a function of X and of X1, X1 given by the field just evaluated
    second = run(
        session, "CREA_CHAMP", TYPE_CHAM="NOEU_NEUT_F", OPERATION="AFFE", MAILLAGE=mesh,
        AFFE={"NOEUD": ("N5",), "NOM_CMP": "X3", "VALE_F": mixed},
    )  # fmt: skip
    out = run(
        session, "CREA_CHAMP", TYPE_CHAM="NOEU_NEUT_R", OPERATION="EVAL", CHAM_F=second,
        CHAM_PARA=(geometry, values),
    )  # fmt: skip
    assert out.values.tolist() == pytest.approx([4.0 * 3.6e10 * 4.0 / 200.0 + 1.0])
    # a parameter no CHAM_PARA field gives is named
    with pytest.raises(CommandError, match="no CHAM_PARA field gives X1 at node N5"):
        run(
            session, "CREA_CHAMP", TYPE_CHAM="NOEU_NEUT_R", OPERATION="EVAL", CHAM_F=second,
            CHAM_PARA=(geometry,),
        )  # fmt: skip
