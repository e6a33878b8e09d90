"""AFFE_CHAR_MECA_C: complex loads in a harmonic response. A clamped-clamped
beam under a uniform complex line load q answers, far below its first mode,
with the static midspan deflection q L^4 / (384 EI) (exact at the nodes of
Euler-Bernoulli elements with consistent loads), real and imaginary parts."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.errors import UnsupportedError
from tests.test_fem_structures import INERTIA, E, beam_model, line_mesh
from tests.test_fem_support import CO, FakeSession, run, validated_run

LENGTH, N_EL = 2.0, 8
Q = 300.0 - 450.0j


def _beam():
    session = FakeSession()
    model, field, cara = beam_model(session, line_mesh(N_EL, LENGTH))
    load = run(
        session,
        "AFFE_CHAR_MECA_C",
        MODELE=model,
        DDL_IMPO={"GROUP_NO": ("A", "B"), "BLOCAGE": ("DEPLACEMENT", "ROTATION")},
        FORCE_POUTRE={"TOUT": "OUI", "FY": Q},
    )
    return session, model, field, cara, load


def test_complex_line_load_gives_the_static_deflection_at_low_frequency():
    session, model, field, cara, load = _beam()
    run(
        session,
        "ASSEMBLAGE",
        MODELE=model,
        CHAM_MATER=field,
        CARA_ELEM=cara,
        CHARGE=load,
        NUME_DDL=CO("NU"),
        MATR_ASSE=[
            {"MATRICE": CO("K"), "OPTION": "RIGI_MECA"},
            {"MATRICE": CO("M"), "OPTION": "MASS_MECA"},
        ],
    )
    k, m = session.bound["K"], session.bound["M"]
    result = validated_run(
        session,
        "DYNA_VIBRA",
        TYPE_CALCUL="HARM",
        BASE_CALCUL="PHYS",
        MATR_MASS=m,
        MATR_RIGI=k,
        FREQ=(1.0e-3,),
        EXCIT={"CHARGE": load, "COEF_MULT": 1.0},
    )
    middle = N_EL // 2
    dy = k.numbering.dof_indices([middle], "DY")[0]
    expected = Q * LENGTH**4 / (384.0 * E * INERTIA)
    assert result.fields["DEPL"][0, dy] == pytest.approx(expected, rel=1e-9)


def test_complex_load_in_a_real_computation_is_refused():
    from asterlite.fem.loads import load_terms

    _, _, _, cara, load = _beam()
    with pytest.raises(UnsupportedError, match="AFFE_CHAR_MECA_C"):
        load_terms(load, cara)
    terms = load_terms(load, cara, complex_values=True)
    total = sum(v for _, c, v in terms if c == "DY")
    assert total == pytest.approx(Q * LENGTH, rel=1e-12)


def test_imposed_values_with_an_imaginary_part_are_refused():
    session = FakeSession()
    model, _, _ = beam_model(session, line_mesh(2, 1.0))
    with pytest.raises(UnsupportedError, match="imaginary part"):
        run(session, "AFFE_CHAR_MECA_C", MODELE=model, DDL_IMPO={"GROUP_NO": "A", "DX": 1.0j})
    # the catalogue makes every value of AFFE_CHAR_MECA_C complex (typ 'C')
    fixed = {"GROUP_NO": "A", "DX": 2.0 + 0j}
    load = run(session, "AFFE_CHAR_MECA_C", MODELE=model, DDL_IMPO=fixed)
    assert [r.rhs for r in load.relations] == [2.0]
    assert np.all([r.rhs == 0.0 for r in load.imaginary.relations])
