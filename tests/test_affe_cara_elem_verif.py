"""AFFE_CARA_ELEM VERIF='MAILLE': every cell of an occurrence must carry an
element of the keyword's family, or code_aster stops (op0019/vafcar)."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.errors import CommandError, UnsupportedError
from tests.test_fem_support import FakeSession, chain_mesh, run


def _springs_only():
    session = FakeSession()
    model = run(
        session,
        "AFFE_MODELE",
        MAILLAGE=chain_mesh(4),
        AFFE={"GROUP_MA": "RESSORTS", "PHENOMENE": "MECANIQUE", "MODELISATION": "DIS_T"},
    )
    return session, model


def _cara(session, model, **extra):
    return run(
        session,
        "AFFE_CARA_ELEM",
        MODELE=model,
        DISCRET={"GROUP_MA": "RESSORTS", "CARA": "K_T_D_L", "VALE": (1.0, 1.0, 1.0)},
        ORIENTATION={"GROUP_MA": "MASSES", "CARA": "ANGL_NAUT", "VALE": (0.0, 0.0, 0.0)},
        **extra,
    )


def test_orientation_of_cells_without_elements_stops_with_verif():
    session, model = _springs_only()
    with pytest.raises(CommandError, match="ORIENTATION is given to cell P1, which carries no"):
        _cara(session, model, VERIF="MAILLE")


def test_without_verif_the_orientation_is_kept():
    session, model = _springs_only()
    cara = _cara(session, model)
    assert len(cara.discrete) == 3


def test_verif_on_families_asterlite_does_not_check_is_refused():
    session, model = _springs_only()
    with pytest.raises(UnsupportedError, match="VERIF='MAILLE' with COQUE"):
        run(
            session,
            "AFFE_CARA_ELEM",
            MODELE=model,
            VERIF="MAILLE",
            COQUE={"GROUP_MA": "RESSORTS", "EPAIS": 0.1},
        )


def test_point_mass_under_discret_on_plane_discretes():
    """A point mass (M_T_D_N, one value) means the same to 2D_DIS_T and DIS_T:
    code_aster takes it under DISCRET on either; a stiffness (3 values in 3D,
    2 in 2D) is still refused on the other family."""
    session = FakeSession()
    model = run(
        session,
        "AFFE_MODELE",
        MAILLAGE=chain_mesh(3, dim=2),
        AFFE={"TOUT": "OUI", "PHENOMENE": "MECANIQUE", "MODELISATION": "2D_DIS_T"},
    )
    cara = run(
        session,
        "AFFE_CARA_ELEM",
        MODELE=model,
        DISCRET={"GROUP_MA": "MASSES", "CARA": "M_T_D_N", "VALE": 2.0},
    )
    assert len(cara.discrete) == 3
    with pytest.raises(CommandError, match="needs DIS_T elements"):
        run(
            session,
            "AFFE_CARA_ELEM",
            MODELE=model,
            DISCRET={"GROUP_MA": "RESSORTS", "CARA": "K_T_D_L", "VALE": (1.0, 1.0, 1.0)},
        )


def test_discrete_cells_without_elements_take_nothing_unless_verif():
    """A DISCRET group with cells the model leaves bare: code_aster gives the
    characteristic to the cells with an element; VERIF='MAILLE' stops."""
    session, model = _springs_only()
    mesh = model.mesh
    mesh.cell_groups["BOTH"] = np.concatenate(
        [mesh.cell_groups["RESSORTS"], mesh.cell_groups["MASSES"]]
    )
    both = {"GROUP_MA": "BOTH", "CARA": "K_T_D_L", "VALE": (1.0, 1.0, 1.0)}
    cara = run(session, "AFFE_CARA_ELEM", MODELE=model, DISCRET=both)
    assert set(cara.discrete) == set(mesh.cell_groups["RESSORTS"].tolist())
    with pytest.raises(CommandError, match="carries no element of the model"):
        run(session, "AFFE_CARA_ELEM", MODELE=model, DISCRET=both, VERIF="MAILLE")
    with pytest.raises(CommandError, match="carries no element of the model"):
        run(session, "AFFE_CARA_ELEM", MODELE=model,
            DISCRET={"GROUP_MA": "MASSES", "CARA": "M_T_D_N", "VALE": 1.0})  # fmt: skip
