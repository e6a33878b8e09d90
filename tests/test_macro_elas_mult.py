"""MACRO_ELAS_MULT on a cantilever: each case's vector takes the loads of
CHAR_MECA_GLOBAL as well as its own (code_aster's macro calls
CALC_VECT_ELEM on both), gravity on a beam included; the result knows its
model, material field and characteristics, so CALC_CHAMP reads it as it
reads a MECA_STATIQUE result."""

from __future__ import annotations

import pytest

from asterlite.errors import UnsupportedError
from tests.test_fem_structures import AREA, INERTIA, RHO, E, beam_model, line_mesh
from tests.test_fem_support import FakeSession, run

LENGTH, N_EL, FORCE, G = 2.0, 8, 350.0, 9.81


def test_global_loads_act_in_every_case_and_fields_follow():
    session = FakeSession()
    model, field, cara = beam_model(session, line_mesh(N_EL, LENGTH))
    clamp = run(
        session, "AFFE_CHAR_MECA", MODELE=model, DDL_IMPO={"GROUP_NO": "A", "LIAISON": "ENCASTRE"}
    )
    weight = run(
        session, "AFFE_CHAR_MECA", MODELE=model, PESANTEUR={"GRAVITE": G, "DIRECTION": (0, -1, 0)}
    )
    tip_y, tip_z = (
        run(session, "AFFE_CHAR_MECA", MODELE=model, FORCE_NODALE={"GROUP_NO": "B", c: FORCE})
        for c in ("FY", "FZ")
    )
    result = run(
        session,
        "MACRO_ELAS_MULT",
        MODELE=model,
        CHAM_MATER=field,
        CARA_ELEM=cara,
        CHAR_MECA_GLOBAL=(clamp, weight),
        CAS_CHARGE=[
            {"NOM_CAS": "Y", "CHAR_MECA": tip_y},
            {"NOM_CAS": "Z", "CHAR_MECA": tip_z},
        ],
    )
    q = RHO * AREA * G  # the beam's weight per length
    sag = -q * LENGTH**4 / (8 * E * INERTIA)
    tip = FORCE * LENGTH**3 / (3 * E * INERTIA)
    dy, dz = (result.numbering.dof_indices([N_EL], c)[0] for c in ("DY", "DZ"))
    assert result.fields[dy, 0] == pytest.approx(sag + tip, rel=1e-9)
    assert result.fields[dy, 1] == pytest.approx(sag, rel=1e-9)
    assert result.fields[dz, 1] == pytest.approx(tip, rel=1e-9)
    # CALC_CHAMP finds the characteristics in the result: the root's bending
    # moment about y in case Z is the tip force's (the weight bends about z)
    fields = run(session, "CALC_CHAMP", RESULTAT=result, CONTRAINTE="EFGE_ELNO")
    efge = fields.element_fields["EFGE_ELNO"]
    mfy = efge.components.index("MFY")
    assert abs(efge.values[1, 0, 0, mfy]) == pytest.approx(FORCE * LENGTH, rel=1e-9)


def test_a_beam_field_asterlite_lacks_is_unsupported_by_name():
    """EPSI_ELNO is computed on beams by code_aster, on solids only by
    asterlite: CALC_CHAMP says so, it does not call the deck wrong."""
    session = FakeSession()
    model, field, cara = beam_model(session, line_mesh(N_EL, LENGTH))
    clamp = run(
        session, "AFFE_CHAR_MECA", MODELE=model, DDL_IMPO={"GROUP_NO": "A", "LIAISON": "ENCASTRE"}
    )
    tip = run(session, "AFFE_CHAR_MECA", MODELE=model, FORCE_NODALE={"GROUP_NO": "B", "FY": 1.0})
    result = run(
        session,
        "MACRO_ELAS_MULT",
        MODELE=model,
        CHAM_MATER=field,
        CARA_ELEM=cara,
        CHAR_MECA_GLOBAL=clamp,
        CAS_CHARGE=[{"NOM_CAS": "Y", "CHAR_MECA": tip}],
    )
    with pytest.raises(UnsupportedError, match="EPSI_ELNO of beam cells"):
        run(session, "CALC_CHAMP", RESULTAT=result, DEFORMATION="EPSI_ELNO")
