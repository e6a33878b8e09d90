"""AFFE_CHAR_CINE / _F / CALC_CHAR_CINE: a kinematic load gives the solution
of the same AFFE_CHAR_MECA DDL_IMPO and the closed form (a cantilever whose
tip is moved by w bends as under a tip force: w(L/2) = 5/16 w)."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.errors import UnsupportedError
from tests.test_fem_structures import beam_model, line_mesh
from tests.test_fem_support import FakeSession, run

LENGTH, N_EL, LIFT = 2.0, 4, 0.01


def _static(session, model, field, cara, loads):
    result = run(session, "MECA_STATIQUE", MODELE=model, CHAM_MATER=field, CARA_ELEM=cara,
                 EXCIT=[{"CHARGE": load} for load in loads])  # fmt: skip
    return result, result.fields["DEPL"][0]


def test_static_kinematic_equals_ddl_impo_and_closed_form():
    session = FakeSession()
    model, field, cara = beam_model(session, line_mesh(N_EL, LENGTH))
    clamp_cine = run(session, "AFFE_CHAR_CINE", MODELE=model,
                     MECA_IMPO={"GROUP_NO": "A", "DX": 0.0, "DY": 0.0, "DZ": 0.0,
                                "DRX": 0.0, "DRY": 0.0, "DRZ": 0.0})  # fmt: skip
    lift_cine = run(
        session, "AFFE_CHAR_CINE", MODELE=model, MECA_IMPO={"GROUP_NO": "B", "DY": LIFT}
    )
    assert clamp_cine.aster_type == "char_cine_meca"
    clamp = run(session, "AFFE_CHAR_MECA", MODELE=model,
                DDL_IMPO={"GROUP_NO": "A", "LIAISON": "ENCASTRE"})  # fmt: skip
    lift = run(session, "AFFE_CHAR_MECA", MODELE=model, DDL_IMPO={"GROUP_NO": "B", "DY": LIFT})
    result, kinematic = _static(session, model, field, cara, [clamp_cine, lift_cine])
    _, dualised = _static(session, model, field, cara, [clamp, lift])
    np.testing.assert_allclose(kinematic, dualised, rtol=1e-12, atol=1e-15)
    middle = result.numbering.dof_indices([N_EL // 2], "DY")[0]
    assert kinematic[middle] == pytest.approx(LIFT * 5.0 / 16.0, rel=1e-10)


def test_function_values_and_calc_char_cine_field():
    session = FakeSession()
    model, _, _ = beam_model(session, line_mesh(N_EL, LENGTH))
    in_x = run(session, "FORMULE", NOM_PARA=("X", "INST"), VALE="0.1*X + INST")
    load = run(session, "AFFE_CHAR_CINE_F", MODELE=model, MECA_IMPO={"TOUT": "OUI", "DZ": in_x})
    numbering = run(session, "NUME_DDL", MODELE=model)
    field = run(session, "CALC_CHAR_CINE", NUME_DDL=numbering, CHAR_CINE=load, INST=2.0)
    dz = numbering.dof_indices(np.arange(N_EL + 1), "DZ")
    x = model.mesh.coords[:, 0]
    np.testing.assert_allclose(field.values[dz], 0.1 * x + 2.0, rtol=1e-12)
    dy = numbering.dof_indices(np.arange(N_EL + 1), "DY")
    assert not field.values[dy].any()


def test_unhonoured_forms_are_refused_by_name():
    session = FakeSession()
    model, _, _ = beam_model(session, line_mesh(N_EL, LENGTH))
    with pytest.raises(UnsupportedError, match="EVOL_IMPO"):
        run(session, "AFFE_CHAR_CINE", MODELE=model, EVOL_IMPO=object())
    with pytest.raises(UnsupportedError, match="TEMP"):
        run(session, "AFFE_CHAR_CINE", MODELE=model, MECA_IMPO={"TOUT": "OUI", "TEMP": 1.0})


# ----------------------------------------------------------------------------- harmonic

HARM_DECK = """DEBUT(CODE="OUI")
MAIL = LIRE_MAILLAGE(FORMAT="ASTER")
MODELE = AFFE_MODELE(MAILLAGE=MAIL, AFFE=_F(TOUT="OUI", PHENOMENE="MECANIQUE",
                     MODELISATION="DIS_T"))
CARA = AFFE_CARA_ELEM(MODELE=MODELE, DISCRET=(
    _F(GROUP_MA="P2", CARA="M_T_D_N", VALE={M2}),
    _F(GROUP_MA="P3", CARA="M_T_D_N", VALE={M3}),
    _F(GROUP_MA="S12", CARA="K_T_D_L", VALE=({K1}, 1.0, 1.0)),
    _F(GROUP_MA="S23", CARA="K_T_D_L", VALE=({K2}, 1.0, 1.0)),
    _F(GROUP_MA="S12", CARA="A_T_D_L", VALE=({C1}, 0.0, 0.0)),
    _F(GROUP_MA="S23", CARA="A_T_D_L", VALE=({C2}, 0.0, 0.0)),
))
GUIDE = AFFE_CHAR_MECA(MODELE=MODELE, DDL_IMPO=_F(TOUT="OUI", DY=0.0, DZ=0.0))
BASE_CINE = AFFE_CHAR_CINE(MODELE=MODELE, MECA_IMPO=_F(GROUP_NO="N1", DX={U0}, DY=0.0, DZ=0.0))
BASE_MECA = AFFE_CHAR_MECA(MODELE=MODELE, DDL_IMPO=_F(GROUP_NO="N1", DX={U0}))
LF = DEFI_LIST_REEL(VALE={FREQS})
RESU = {{}}
for name, charges, cine in (("CINE", (GUIDE,), BASE_CINE), ("MECA", (GUIDE, BASE_MECA), None)):
    RIGEL = CALC_MATR_ELEM(MODELE=MODELE, OPTION="RIGI_MECA", CARA_ELEM=CARA, CHARGE=charges)
    MASEL = CALC_MATR_ELEM(MODELE=MODELE, OPTION="MASS_MECA", CARA_ELEM=CARA, CHARGE=charges)
    AMOEL = CALC_MATR_ELEM(MODELE=MODELE, OPTION="AMOR_MECA", CARA_ELEM=CARA, CHARGE=charges)
    NUM = NUME_DDL(MATR_RIGI=RIGEL)
    if cine is None:
        RIGI = ASSE_MATRICE(MATR_ELEM=RIGEL, NUME_DDL=NUM)
        MASS = ASSE_MATRICE(MATR_ELEM=MASEL, NUME_DDL=NUM)
        AMOR = ASSE_MATRICE(MATR_ELEM=AMOEL, NUME_DDL=NUM)
        base = BASE_MECA
    else:
        RIGI = ASSE_MATRICE(MATR_ELEM=RIGEL, NUME_DDL=NUM, CHAR_CINE=cine)
        MASS = ASSE_MATRICE(MATR_ELEM=MASEL, NUME_DDL=NUM, CHAR_CINE=cine)
        AMOR = ASSE_MATRICE(MATR_ELEM=AMOEL, NUME_DDL=NUM, CHAR_CINE=cine)
        base = cine
    RESU[name] = DYNA_VIBRA(TYPE_CALCUL="HARM", BASE_CALCUL="PHYS", MATR_MASS=MASS,
        MATR_RIGI=RIGI, MATR_AMOR=AMOR, LIST_FREQ=LF, NOM_CHAM="DEPL",
        EXCIT=_F(CHARGE=base, COEF_MULT_C={COEF}))
HCINE = RESU["CINE"]
HMECA = RESU["MECA"]
FIN()
"""
M2, M3, K1, K2, C1, C2, U0, COEF = 3.0, 1.5, 2.0e4, 1.0e4, 12.0, 4.0, 0.002, 2.0 - 0.5j
FREQS = (2.0, 9.5, 17.0, 31.0)


def test_harmonic_base_motion_equals_ddl_impo_and_closed_form(tmp_path):
    from asterlite.io.export import describe_run
    from asterlite.runtime.session import Session
    from tests.test_harmonic import MESH

    deck = HARM_DECK.format(M2=M2, M3=M3, K1=K1, K2=K2, C1=C1, C2=C2, U0=U0, COEF=COEF,
                            FREQS=FREQS)  # fmt: skip
    (tmp_path / "d.mail").write_text(MESH)
    (tmp_path / "d.comm").write_text(deck)
    export = tmp_path / "d.export"
    export.write_text("P time_limit 300\nF comm d.comm D 1\nF mail d.mail D 20\n")
    session = Session(describe_run(export), output_dir=tmp_path / "out")
    session.run_all()
    cine, meca = session.namespace["HCINE"], session.namespace["HMECA"]
    mesh = cine.numbering.mesh
    columns = [cine.numbering.dof_index(mesh.node_index[n], "DX") for n in ("N1", "N2", "N3")]
    got = cine.fields["DEPL"][:, columns]
    np.testing.assert_allclose(meca.fields["DEPL"][:, columns], got, rtol=1e-10)
    base = U0 * COEF
    for k, f in enumerate(FREQS):
        w = 2 * np.pi * f
        dynamic = np.array([[K1 + K2 + 1j * w * (C1 + C2) - w**2 * M2, -(K2 + 1j * w * C2)],
                            [-(K2 + 1j * w * C2), K2 + 1j * w * C2 - w**2 * M3]])  # fmt: skip
        exact = np.linalg.solve(dynamic, [(K1 + 1j * w * C1) * base, 0.0])
        np.testing.assert_allclose(got[k], [base, *exact], rtol=1e-10)


# ----------------------------------------------------------------------------- transient


def _kinematic_oscillator(tmp_path, imposed: str, coefficient: float):
    """sdld110a's base-driven oscillator of test_dynamics_physical_imposed,
    its support moved by AFFE_CHAR_CINE(_F) eliminated from the matrices."""
    from asterlite.runtime.runner import run_deck
    from tests.test_dynamics_physical_imposed import DECK, MESH

    deck = DECK.replace(
        'CHAR = AFFE_CHAR_MECA_F(MODELE=MOD, DDL_IMPO=_F(GROUP_NO="P1", DX=MOTION, DY=ZERO))',
        f'CHAR = {imposed}\nGUIDE = AFFE_CHAR_MECA(MODELE=MOD, DDL_IMPO=_F(GROUP_NO="P3", DY=0.0))',
    ).replace("CHARGE=CHAR, NUME_DDL", "CHARGE=GUIDE, NUME_DDL")
    deck = deck.replace(
        "EXCIT=_F(CHARGE=CHAR, COEF_MULT=0.5)", f"EXCIT=_F(CHARGE=CHAR, COEF_MULT={coefficient})"
    )
    assembled = "".join(
        f"{name} = ASSE_MATRICE(NUME_DDL=NUME, CHAR_CINE=CHAR, MATR_ELEM=CALC_MATR_ELEM(\n"
        f'    MODELE=MOD, CARA_ELEM=CARA, CHARGE=GUIDE, OPTION="{option}"))\n'
        for name, option in (("RIGI", "RIGI_MECA"), ("MASSE", "MASS_MECA"))
    )
    deck = deck.replace("DYNA = DYNA_VIBRA(", assembled + "DYNA = DYNA_VIBRA(")
    (tmp_path / "d.comm").write_text(deck)
    (tmp_path / "d.mail").write_text(MESH)
    (tmp_path / "d.export").write_text("F comm d.comm D 1\nF mail d.mail D 20\nF libr f.txt R 30\n")
    report = run_deck(tmp_path / "d.export", tmp_path / "out")
    rows = [
        line.split()
        for line in (tmp_path / "out" / "f.txt").read_text().splitlines()
        if line.strip() and line.split()[0][0] in "-0123456789"
    ]
    values = np.array(rows, dtype=float)
    return report, values[:361, 0], values[:361, 1], values[361:, 1]


def test_transient_support_motion_by_affe_char_cine_f(tmp_path):
    report, times, d1, d3 = _kinematic_oscillator(
        tmp_path,
        'AFFE_CHAR_CINE_F(MODELE=MOD, MECA_IMPO=_F(GROUP_NO="P1", DX=MOTION, DY=ZERO))',
        0.5,
    )
    np.testing.assert_allclose(d1, np.sin(2.0 * times), atol=1e-6)
    assert np.abs(d3 - (2.0 * np.sin(times) - np.sin(2.0 * times)) / 3.0).max() < 1.0e-3
    assert report.status == "PASS", report.message


def test_transient_constant_imposed_value_is_scaled_by_coef_mult(tmp_path):
    _, _, d1, _ = _kinematic_oscillator(
        tmp_path, 'AFFE_CHAR_CINE(MODELE=MOD, MECA_IMPO=_F(GROUP_NO="P1", DX=0.25, DY=0.0))', 2.0
    )
    np.testing.assert_allclose(d1, 0.5, atol=1e-6)


def test_a_value_of_freq_is_refused_outside_a_harmonic_response():
    """A value of FREQ is kept for DYNA_VIBRA HARM (tests/test_viscoelastic.py);
    a static solve and CALC_CHAR_CINE, which evaluate no frequency, refuse it."""
    session = FakeSession()
    model, field, cara = beam_model(session, line_mesh(N_EL, LENGTH))
    of_freq = run(session, "FORMULE", NOM_PARA="FREQ", VALE="1.0/FREQ")
    load = run(session, "AFFE_CHAR_CINE_F", MODELE=model, MECA_IMPO={"TOUT": "OUI", "DZ": of_freq})
    assert any(relation.rhs_in_frequency is not None for relation in load.relations)
    with pytest.raises(UnsupportedError, match="FREQ"):
        _static(session, model, field, cara, [load])
    numbering = run(session, "NUME_DDL", MODELE=model)
    with pytest.raises(UnsupportedError, match="FREQ"):
        run(session, "CALC_CHAR_CINE", NUME_DDL=numbering, CHAR_CINE=load)


def test_resoudre_with_cham_cine_lifts_the_eliminated_dofs():
    from asterlite.concepts.assembly import NodalField

    session = FakeSession()
    model, field, cara = beam_model(session, line_mesh(N_EL, LENGTH))
    kinematic = run(session, "AFFE_CHAR_CINE", MODELE=model, MECA_IMPO=[
        {"GROUP_NO": "A", "DX": 0.0, "DY": 0.0, "DZ": 0.0, "DRX": 0.0, "DRY": 0.0, "DRZ": 0.0},
        {"GROUP_NO": "B", "DY": LIFT}])  # fmt: skip
    elementary = run(session, "CALC_MATR_ELEM", OPTION="RIGI_MECA", MODELE=model,
                     CHAM_MATER=field, CARA_ELEM=cara)  # fmt: skip
    numbering = run(session, "NUME_DDL", MATR_RIGI=elementary)
    stiffness = run(session, "ASSE_MATRICE", MATR_ELEM=elementary, NUME_DDL=numbering,
                    CHAR_CINE=kinematic)  # fmt: skip
    stiffness = run(session, "FACTORISER", MATR_ASSE=stiffness)
    values = run(session, "CALC_CHAR_CINE", NUME_DDL=numbering, CHAR_CINE=kinematic)
    zero = NodalField(numbering=numbering, values=np.zeros(numbering.n_dofs))
    lifted = run(session, "RESOUDRE", MATR=stiffness, CHAM_NO=zero, CHAM_CINE=values)
    middle, tip = numbering.dof_indices([N_EL // 2, N_EL], "DY")
    assert lifted.values[tip] == pytest.approx(LIFT, rel=1e-12)
    assert lifted.values[middle] == pytest.approx(LIFT * 5.0 / 16.0, rel=1e-9)
    # without CHAM_CINE the eliminated DOFs are zero, as in code_aster
    rest = run(session, "RESOUDRE", MATR=stiffness, CHAM_NO=zero)
    assert not np.any(rest.values)


def test_a_component_the_nodes_do_not_carry_is_passed_over():
    # as code_aster's AFFE_CHAR_CINE (sslp113b imposes DRZ on a plane model)
    session = FakeSession()
    model, _, _ = beam_model(session, line_mesh(N_EL, LENGTH))
    load = run(
        session, "AFFE_CHAR_CINE", MODELE=model, MECA_IMPO={"GROUP_NO": "A", "GRX": 0.0, "DX": 0.0}
    )
    assert [r.terms[0][1] for r in load.relations] == ["DX"]
