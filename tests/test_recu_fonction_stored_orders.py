"""RECU_FONCTION of an element field over every order (no access keyword)
takes only the orders where the field is stored, as code_aster's rsutn2:
CALC_CHAMP with LIST_INST leaves the other orders without it (NaN here)."""

from __future__ import annotations

import numpy as np

from asterlite.concepts.assembly import DofNumbering, ElementField
from asterlite.concepts.transient import DynaTrans
from tests.test_fem_support import FakeSession, chain_mesh, run


def _result():
    mesh = chain_mesh(2)
    numbering = DofNumbering(mesh=mesh, dofs=[(0, "DX"), (1, "DX")])
    values = np.full((3, 1, 1, 1), np.nan)
    values[1:, 0, 0, 0] = [4.0, -6.0]  # computed at orders 1 and 2 only
    result = DynaTrans(
        numbering, np.array([0.0, 0.5, 1.0]), np.array([0, 1, 2]), {"DEPL": np.zeros((3, 2))}
    )
    result.element_fields = {"SIEF_ELGA": ElementField("SIEF_ELGA", np.array([0]), ("N",), values)}
    return result


def test_every_order_means_those_holding_the_field():
    function = run(
        FakeSession(),
        "RECU_FONCTION",
        RESULTAT=_result(),
        NOM_CHAM="SIEF_ELGA",
        NOM_CMP="N",
        MAILLE="S1",
        POINT=1,
        TOUT_ORDRE="OUI",
    )
    np.testing.assert_array_equal(function.abscissas, [0.5, 1.0])
    np.testing.assert_array_equal(function.ordinates, [4.0, -6.0])


def test_explicit_instants_are_kept():
    function = run(
        FakeSession(),
        "RECU_FONCTION",
        RESULTAT=_result(),
        NOM_CHAM="SIEF_ELGA",
        NOM_CMP="N",
        MAILLE="S1",
        POINT=1,
        INST=(0.5, 1.0),
    )
    np.testing.assert_array_equal(function.ordinates, [4.0, -6.0])
