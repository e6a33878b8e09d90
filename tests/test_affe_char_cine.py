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
    lift_cine = run(session, "AFFE_CHAR_CINE", MODELE=model, MECA_IMPO={"GROUP_NO": "B", "DY": LIFT})
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
