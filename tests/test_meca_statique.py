"""MECA_STATIQUE: a cantilever's tip deflection F L^3 / (3 EI) at each instant
of a list, forces and imposed displacements scaled by FONC_MULT."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.errors import UnsupportedError
from tests.test_fem_structures import INERTIA, E, beam_model, line_mesh
from tests.test_fem_support import FakeSession, run

LENGTH, N_EL, FORCE = 2.0, 4, 350.0


def _setup():
    session = FakeSession()
    model, field, cara = beam_model(session, line_mesh(N_EL, LENGTH))
    clamp = run(
        session, "AFFE_CHAR_MECA", MODELE=model, DDL_IMPO={"GROUP_NO": "A", "LIAISON": "ENCASTRE"}
    )
    tip = run(session, "AFFE_CHAR_MECA", MODELE=model, FORCE_NODALE={"GROUP_NO": "B", "FY": FORCE})
    return session, model, field, cara, clamp, tip


def test_cantilever_at_each_instant():
    session, model, field, cara, clamp, tip = _setup()
    ramp = run(session, "DEFI_FONCTION", NOM_PARA="INST", VALE=(0.0, 0.0, 10.0, 10.0))
    times = run(session, "DEFI_LIST_REEL", DEBUT=0.5, INTERVALLE={"JUSQU_A": 1.5, "PAS": 0.5})
    result = run(
        session,
        "MECA_STATIQUE",
        MODELE=model,
        CHAM_MATER=field,
        CARA_ELEM=cara,
        LIST_INST=times,
        EXCIT=[{"CHARGE": clamp}, {"CHARGE": tip, "FONC_MULT": ramp}],
    )
    assert result.aster_type == "evol_elas" and result.times.tolist() == [0.5, 1.0, 1.5]
    dy = result.numbering.dof_indices([N_EL], "DY")[0]
    static = FORCE * LENGTH**3 / (3 * E * INERTIA)
    np.testing.assert_allclose(result.fields["DEPL"][:, dy], static * result.times, rtol=1e-10)


def test_imposed_displacement_scaled_and_default_instant():
    session, model, field, cara, clamp, _ = _setup()
    lift = run(session, "AFFE_CHAR_MECA", MODELE=model, DDL_IMPO={"GROUP_NO": "B", "DY": 0.01})
    double = run(session, "DEFI_FONCTION", NOM_PARA="INST", VALE=(0.0, 2.0, 1.0, 2.0))
    result = run(
        session,
        "MECA_STATIQUE",
        MODELE=model,
        CHAM_MATER=field,
        CARA_ELEM=cara,
        EXCIT=[{"CHARGE": clamp}, {"CHARGE": lift, "FONC_MULT": double}],
    )
    assert result.times.tolist() == [0.0]
    dy = result.numbering.dof_indices([N_EL], "DY")[0]
    assert result.fields["DEPL"][0, dy] == pytest.approx(0.02)
    # a cantilever whose tip is moved bends as under a tip force: w(L/2) = 5/16 w(L)
    middle = result.numbering.dof_indices([N_EL // 2], "DY")[0]
    assert result.fields["DEPL"][0, middle] == pytest.approx(0.02 * 5.0 / 16.0, rel=1e-10)


def test_reuse_is_refused():
    session, model, field, cara, clamp, tip = _setup()
    with pytest.raises(UnsupportedError, match="reuse"):
        run(session, "MECA_STATIQUE", MODELE=model, CHAM_MATER=field, CARA_ELEM=cara,
            RESULTAT=object(), EXCIT=[{"CHARGE": clamp}])  # fmt: skip


def test_the_stress_field_code_aster_stores_unasked_is_unsupported_not_missing():
    """code_aster's MECA_STATIQUE stores SIEF_ELGA by default; asterlite
    computes it through CALC_CHAMP only: CREA_CHAMP of it is asterlite's
    limit, said by name, not the deck's mistake."""
    session, model, field, cara, clamp, tip = _setup()
    result = run(
        session,
        "MECA_STATIQUE",
        MODELE=model,
        CHAM_MATER=field,
        CARA_ELEM=cara,
        EXCIT=[{"CHARGE": clamp}, {"CHARGE": tip}],
    )
    with pytest.raises(UnsupportedError, match="SIEF_ELGA of an evol_elas result"):
        run(
            session,
            "CREA_CHAMP",
            OPERATION="EXTR",
            TYPE_CHAM="ELGA_SIEF_R",
            RESULTAT=result,
            NOM_CHAM="SIEF_ELGA",
            NUME_ORDRE=1,
        )
