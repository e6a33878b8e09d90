"""The multifibre commands chained as a deck does: DEFI_GEOM_FIBRE (FIBRE
points), DEFI_COMPOR, AFFE_MATERIAU AFFE_COMPOR, AFFE_CARA_ELEM MULTIFIBRE,
a POU_D_EM cantilever in MECA_STATIQUE and its CALC_CHAMP fields against
beam theory."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.errors import CommandError
from tests.test_fem_structures import line_mesh
from tests.test_fem_support import FakeSession, validated_run

E, LENGTH, N_EL, FORCE = 2.0e11, 2.0, 4, 1000.0
A0, HALF = 1.0e-4, 0.05  # four fibres of area A0 at (±HALF, ±HALF)


def _cantilever(session, load=None):
    mesh = line_mesh(N_EL, LENGTH)
    run = validated_run
    steel = run(session, "DEFI_MATERIAU", ELAS={"E": E, "NU": 0.3, "RHO": 7800.0})
    fibres = run(
        session,
        "DEFI_GEOM_FIBRE",
        FIBRE={
            "GROUP_FIBRE": "F",
            "COOR_AXE_POUTRE": (0.0, 0.0),
            "VALE": (HALF, HALF, A0, -HALF, HALF, A0, -HALF, -HALF, A0, HALF, -HALF, A0),
        },
    )
    compor = run(
        session,
        "DEFI_COMPOR",
        GEOM_FIBRE=fibres,
        MATER_SECT=steel,
        MULTIFIBRE={"GROUP_FIBRE": "F", "MATER": steel},
    )
    model = run(
        session,
        "AFFE_MODELE",
        MAILLAGE=mesh,
        AFFE={"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": "POU_D_EM"},
    )
    field = run(
        session,
        "AFFE_MATERIAU",
        MAILLAGE=mesh,
        AFFE={"TOUT": "OUI", "MATER": steel},
        AFFE_COMPOR={"TOUT": "OUI", "COMPOR": compor},
    )
    inertia = 4 * A0 * HALF**2
    cara = run(
        session,
        "AFFE_CARA_ELEM",
        MODELE=model,
        POUTRE={
            "GROUP_MA": "POUTRE",
            "SECTION": "GENERALE",
            "CARA": ("A", "IY", "IZ", "JX"),
            "VALE": (4 * A0, inertia, inertia, 2 * inertia),
        },
        GEOM_FIBRE=fibres,
        MULTIFIBRE={"GROUP_MA": "POUTRE", "GROUP_FIBRE": "F"},
    )
    clamp = run(
        session, "AFFE_CHAR_MECA", MODELE=model, DDL_IMPO={"GROUP_NO": "A", "LIAISON": "ENCASTRE"}
    )
    if load is None:
        load = {"FORCE_NODALE": {"GROUP_NO": "B", "FY": FORCE}}
    tip = run(session, "AFFE_CHAR_MECA", MODELE=model, **load)
    result = run(
        session,
        "MECA_STATIQUE",
        MODELE=model,
        CHAM_MATER=field,
        CARA_ELEM=cara,
        EXCIT=[{"CHARGE": clamp}, {"CHARGE": tip}],
    )
    return result, inertia


def test_tip_load_deflection_fibre_stresses_and_forces():
    session = FakeSession()
    result, inertia = _cantilever(session)
    dy = result.numbering.dof_indices([N_EL], "DY")[0]
    assert result.fields["DEPL"][0, dy] == pytest.approx(
        FORCE * LENGTH**3 / (3 * E * inertia), rel=1e-10
    )
    result = validated_run(
        session, "CALC_CHAMP", RESULTAT=result, CONTRAINTE=("SIEF_ELGA", "EFGE_ELNO")
    )
    sief = result.element_fields["SIEF_ELGA"]
    assert sief.sub_points == 4 and sief.components == ("SIXX",)
    # first Gauss point of the first cell: M_z = F (L - x), σ = -M_z y / I_z
    x_gauss = (LENGTH / N_EL) * (0.5 - 0.5 / np.sqrt(3.0))
    moment = FORCE * (LENGTH - x_gauss)
    expected = -moment * np.array([HALF, -HALF, -HALF, HALF]) / inertia
    np.testing.assert_allclose(sief.values[0, 0, :4, 0], expected, rtol=1e-9)
    efge = result.element_fields["EFGE_ELNO"]
    column = efge.components.index("MFZ")
    assert efge.values[0, 0, 0, column] == pytest.approx(FORCE * LENGTH, rel=1e-9)


def test_distributed_load_of_the_static_result_is_taken_off_the_forces():
    session = FakeSession()
    q = 300.0
    load = {"FORCE_POUTRE": {"GROUP_MA": "POUTRE", "FY": q}}
    result, _ = _cantilever(session, load=load)
    result = validated_run(session, "CALC_CHAMP", RESULTAT=result, CONTRAINTE=("EFGE_ELNO",))
    efge = result.element_fields["EFGE_ELNO"]
    vy, mfz = efge.components.index("VY"), efge.components.index("MFZ")
    # root: V = q L, M = q L^2 / 2 (sign of code_aster's EFGE); tip: 0
    assert abs(efge.values[0, 0, 0, vy]) == pytest.approx(q * LENGTH, rel=1e-9)
    assert abs(efge.values[0, 0, 0, mfz]) == pytest.approx(q * LENGTH**2 / 2, rel=1e-9)
    assert abs(efge.values[0, -1, 1, vy]) < 1e-6 * q * LENGTH


def test_fibre_area_outside_prec_aire_is_an_error():
    """One fibre of area A0 cannot stand for a circle of radius 0.1."""
    with pytest.raises(CommandError, match="PREC_AIRE"):
        _cantilever_wrong_area(FakeSession())


def _cantilever_wrong_area(session):
    mesh = line_mesh(2, 1.0)
    run = validated_run
    fibres = run(
        session,
        "DEFI_GEOM_FIBRE",
        FIBRE={"GROUP_FIBRE": "F", "COOR_AXE_POUTRE": (0.0, 0.0), "VALE": (0.0, 0.01, A0)},
    )
    model = run(
        session,
        "AFFE_MODELE",
        MAILLAGE=mesh,
        AFFE={"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": "POU_D_EM"},
    )
    run(
        session,
        "AFFE_CARA_ELEM",
        MODELE=model,
        POUTRE={"GROUP_MA": "POUTRE", "SECTION": "CERCLE", "CARA": ("R",), "VALE": (0.1,)},
        GEOM_FIBRE=fibres,
        MULTIFIBRE={"GROUP_MA": "POUTRE", "GROUP_FIBRE": "F"},
    )
