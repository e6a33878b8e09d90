"""Complex nodal fields and the numpy views of matrices and vectors, as
code_aster gives them: CREA_CHAMP ASSE/R2C/C2R on complex fields, toNumpy()
and EXTR_MATR(sparse=True) of a matrix with kinematic loads (imposed DOFs'
rows and columns zero, diagonal one: code_aster's toNumpy), FACTORISER and
RESOUDRE of a complex system, EXTR_VECT_GENE/RECU_VECT_GENE, TEST_RESU
OBJET's check sum, MODI_MAILLAGE ALEA's generator and the frequency of a
complex-stiffness eigenproblem."""

from __future__ import annotations

import numpy as np
import pytest
from asterlite.commands.modi_maillage import lehmer_uniform

from asterlite.concepts.assembly import NodalField
from asterlite.concepts.modes import GeneralizedNumbering, GeneralizedVector
from asterlite.errors import CommandError, DeckRuntimeError, UnsupportedError
from asterlite.modal.quadratic import modal_quantities
from tests.test_fem_structures import E, R, beam_model, line_mesh
from tests.test_fem_support import FakeSession, run

N_EL = 4


def _clamp_cine(session, model):
    return run(session, "AFFE_CHAR_CINE", MODELE=model,
               MECA_IMPO={"GROUP_NO": "A", "DX": 0.0, "DY": 0.0, "DZ": 0.0,
                          "DRX": 0.0, "DRY": 0.0, "DRZ": 0.0})  # fmt: skip


def _kinematic_matrices():
    """A clamped (AFFE_CHAR_CINE) beam's stiffness and mass, CHAR_CINE given."""
    session = FakeSession()
    model, field, cara = beam_model(session, line_mesh(N_EL, 2.0))
    clamp = _clamp_cine(session, model)
    options = {"MODELE": model, "CHAM_MATER": field, "CARA_ELEM": cara}
    rigi = run(session, "CALC_MATR_ELEM", OPTION="RIGI_MECA", **options)
    mass = run(session, "CALC_MATR_ELEM", OPTION="MASS_MECA", **options)
    numbering = run(session, "NUME_DDL", MATR_RIGI=rigi)
    k = run(session, "ASSE_MATRICE", MATR_ELEM=rigi, NUME_DDL=numbering, CHAR_CINE=clamp)
    m = run(session, "ASSE_MATRICE", MATR_ELEM=mass, NUME_DDL=numbering, CHAR_CINE=clamp)
    return session, model, clamp, k, m


def test_to_numpy_eliminates_kinematic_dofs_as_code_aster():
    session, model, clamp, k, _ = _kinematic_matrices()
    dense = k.toNumpy()
    full = k.matrix.toarray()
    imposed = np.array([k.numbering.index[(0, c)] for c in ("DX", "DY", "DZ", "DRX", "DRY", "DRZ")])
    free = np.setdiff1d(np.arange(full.shape[0]), imposed)
    assert np.array_equal(dense[np.ix_(imposed, imposed)], np.eye(6))
    assert not dense[np.ix_(imposed, free)].any() and not dense[np.ix_(free, imposed)].any()
    np.testing.assert_array_equal(dense[np.ix_(free, free)], full[np.ix_(free, free)])
    data, rows, cols, dim = k.EXTR_MATR(sparse=True)
    rebuilt = np.zeros((dim, dim))
    rebuilt[rows, cols] = data
    np.testing.assert_array_equal(rebuilt, dense)
    assert np.array_equal(rows[:6], imposed) and np.all(data[:6] == 1.0)
    # the eliminated matrix solves the clamped problem: the tip deflection under
    # a unit tip force is L^3 / (3 E I)
    force = np.zeros(dim)
    force[k.numbering.index[(N_EL, "DY")]] = 1.0
    u = np.linalg.solve(dense, force)
    inertia = np.pi * R**4 / 4.0
    assert u[k.numbering.index[(N_EL, "DY")]] == pytest.approx(2.0**3 / (3 * E * inertia), 1e-10)


def test_dualised_constraints_give_lagrange_rows_and_unknown_field_values():
    session = FakeSession()
    model, field, cara = beam_model(session, line_mesh(N_EL, 2.0))
    clamp = run(session, "AFFE_CHAR_MECA", MODELE=model,
                DDL_IMPO={"GROUP_NO": "A", "LIAISON": "ENCASTRE"})  # fmt: skip
    rigi = run(session, "CALC_MATR_ELEM", OPTION="RIGI_MECA", MODELE=model, CHAM_MATER=field,
               CARA_ELEM=cara, CHARGE=clamp)  # fmt: skip
    numbering = run(session, "NUME_DDL", MATR_RIGI=rigi)
    k = run(session, "ASSE_MATRICE", MATR_ELEM=rigi, NUME_DDL=numbering)
    # code_aster's layout: two multipliers per constraint (tests/test_lagrange_layout.py)
    assert k.toNumpy().shape == (numbering.n_dofs + 12,) * 2
    # a field's multiplier values are unknown without its reactions: refused
    with pytest.raises(UnsupportedError, match="Lagrange"):
        NodalField(numbering=numbering, values=np.zeros(numbering.n_dofs)).getValues()


def test_complex_factorisation_solves_the_eliminated_system():
    session, model, clamp, k, m = _kinematic_matrices()
    kc = run(session, "COMB_MATR_ASSE",
             COMB_C=[{"MATR_ASSE": k, "COEF_C": complex(1.0, 0.02)},
                     {"MATR_ASSE": m, "COEF_C": complex(-4.0e3, 0.0)}])  # fmt: skip
    factored = run(session, "FACTORISER", MATR_ASSE=kc, METHODE="LDLT")
    load = np.zeros(kc.numbering.n_dofs, dtype=complex)
    load[kc.numbering.index[(N_EL, "DY")]] = 1.0 - 0.5j
    field = NodalField(numbering=kc.numbering, values=load)
    u = run(session, "RESOUDRE", MATR=factored, CHAM_NO=field)
    reference = np.linalg.solve(kc.toNumpy(), load)
    np.testing.assert_allclose(u.getValues(), reference, rtol=1e-10, atol=1e-18)
    with pytest.raises(CommandError, match="real CHAM_NO"):
        run(session, "RESOUDRE", MATR=factored,
            CHAM_NO=NodalField(numbering=kc.numbering, values=load.real))  # fmt: skip


def _field(numbering, values):
    return NodalField(numbering=numbering, values=np.asarray(values))


def test_crea_champ_asse_of_complex_fields():
    session, model, _, k, _ = _kinematic_matrices()
    numbering = k.numbering
    n = numbering.n_dofs
    real = _field(numbering, np.arange(1.0, n + 1.0))
    as_complex = run(session, "CREA_CHAMP", OPERATION="R2C", TYPE_CHAM="NOEU_DEPL_C",
                     CHAM_GD=real)  # fmt: skip
    assert np.iscomplexobj(as_complex.values)
    coef = complex(1.0, 0.5)
    out = run(session, "CREA_CHAMP", OPERATION="ASSE", MODELE=model, TYPE_CHAM="NOEU_DEPL_C",
              NUME_DDL=numbering,
              ASSE=[{"CHAM_GD": as_complex, "TOUT": "OUI", "CUMUL": "NON", "COEF_C": coef},
                    {"CHAM_GD": as_complex, "TOUT": "OUI", "CUMUL": "OUI", "COEF_R": 2.0,
                     "NOM_CMP": ("DX",)}])  # fmt: skip
    expected = coef * real.values.astype(complex)
    dx = numbering.dof_indices(np.arange(N_EL + 1), "DX")
    expected[dx] += 2.0 * real.values[dx]
    np.testing.assert_allclose(out.values, expected, rtol=0, atol=0)
    back = run(session, "CREA_CHAMP", OPERATION="C2R", TYPE_CHAM="NOEU_DEPL_R",
               CHAM_GD=out, PARTIE="IMAG")  # fmt: skip
    np.testing.assert_allclose(back.values, expected.imag)
    with pytest.raises(CommandError, match="real field"):  # a real piece for a complex field
        run(session, "CREA_CHAMP", OPERATION="ASSE", MODELE=model, TYPE_CHAM="NOEU_DEPL_C",
            ASSE={"CHAM_GD": real, "TOUT": "OUI"})  # fmt: skip
    with pytest.raises(CommandError, match="COEF_C"):
        run(session, "CREA_CHAMP", OPERATION="ASSE", MODELE=model, TYPE_CHAM="NOEU_DEPL_R",
            ASSE={"CHAM_GD": real, "TOUT": "OUI", "COEF_C": coef})  # fmt: skip
    with pytest.raises(CommandError, match="complex"):  # chcore: R2C of a complex field
        run(session, "CREA_CHAMP", OPERATION="R2C", TYPE_CHAM="NOEU_DEPL_C", CHAM_GD=out)
    with pytest.raises(CommandError, match="real"):  # chreco: C2R of a real field
        run(session, "CREA_CHAMP", OPERATION="C2R", TYPE_CHAM="NOEU_DEPL_R", CHAM_GD=real,
            PARTIE="REEL")  # fmt: skip


def test_generalized_vector_numpy_round_trip():
    numbering = GeneralizedNumbering(basis=None)
    vector = GeneralizedVector(numbering=numbering, values=np.array([1.0 + 2j, -1.0j]))
    values = vector.EXTR_VECT_GENE()
    values[0] = 0.0  # a copy: the vector is unchanged
    assert vector.values[0] == 1.0 + 2j
    vector.RECU_VECT_GENE(np.array([3.0, 4.0 - 1j]))
    np.testing.assert_array_equal(vector.values, [3.0, 4.0 - 1j])
    with pytest.raises(DeckRuntimeError, match="3 values"):
        vector.RECU_VECT_GENE([1.0, 2.0, 3.0])
    real = GeneralizedVector(numbering=numbering, values=np.zeros(2))
    with pytest.raises(DeckRuntimeError, match="real vector"):
        real.RECU_VECT_GENE([1j, 0.0])


def test_lehmer_generator_is_the_minimal_standard():
    # Park & Miller's check: from seed 1, the 10000th state is 1043618065
    draws = lehmer_uniform(10000, seed=1)
    assert draws[0] * 2147483648.0 == 16807.0
    assert draws[-1] * 2147483648.0 == 1043618065.0
    assert np.all((draws > 0.0) & (draws < 1.0))


def test_modi_maillage_alea_moves_within_the_extent():
    session = FakeSession()
    mesh = line_mesh(N_EL, 2.0)
    before = mesh.coords.copy()
    run(session, "MODI_MAILLAGE", MAILLAGE=mesh, DEFORME={"OPTION": "TRAN", "ALEA": 1e-3})
    shift = mesh.coords - before
    draws = lehmer_uniform(3 * mesh.n_nodes, seed=24331).reshape(-1, 3)
    np.testing.assert_allclose(shift[:, 0], 2.0 * (draws[:, 0] - 0.5) * 1e-3 * 2.0, rtol=1e-9)
    assert not shift[:, 1:].any()  # no extent along y and z: no move


def test_complex_stiffness_frequency_is_code_aster_gep_one():
    # K (1 + i eta) phi = sigma M phi: sigma = w0^2 (1 + i eta), lambda = i sqrt(sigma)
    w0, eta = 2 * np.pi * 100.0, 0.01
    root = np.sqrt(w0**2 * (1 + 1j * eta))
    lam = np.array([1j * root])
    gep = modal_quantities(lam, complex_stiffness_only=True)
    assert gep["FREQ"][0] == pytest.approx(w0 * (1 + eta**2) ** 0.25 / (2 * np.pi), rel=1e-14)
    assert gep["AMOR_REDUIT"][0] == pytest.approx(np.sin(np.arctan(eta) / 2), rel=1e-12)
    assert gep["OMEGA2"][0] == pytest.approx(w0**2, rel=1e-14)
    quadratic = modal_quantities(lam)
    assert quadratic["FREQ"][0] == pytest.approx(root.real / (2 * np.pi), rel=1e-14)


def test_crea_champ_neut_fields_on_the_affected_nodes_and_their_assembly():
    # NOEU_NEUT_R: components X1... on the nodes of the AFFE groups only (the
    # model's DOFs are no template), assembled with CUMUL
    session, model, _, _, _ = _kinematic_matrices()
    phi = run(session, "CREA_CHAMP", OPERATION="AFFE", TYPE_CHAM="NOEU_NEUT_R", MODELE=model,
              AFFE={"GROUP_NO": "B", "NOM_CMP": "X1", "VALE": 33.2})  # fmt: skip
    assert phi.numbering.dofs == [(N_EL, "X1")] and phi.values.tolist() == [33.2]
    cohesion = run(session, "CREA_CHAMP", OPERATION="AFFE", TYPE_CHAM="NOEU_NEUT_R",
                   MODELE=model, AFFE={"TOUT": "OUI", "NOM_CMP": "X2", "VALE": 4.0})  # fmt: skip
    assert len(cohesion.numbering.dofs) == N_EL + 1
    both = run(session, "CREA_CHAMP", OPERATION="ASSE", TYPE_CHAM="NOEU_NEUT_R", MODELE=model,
               ASSE=[{"CHAM_GD": phi, "TOUT": "OUI", "CUMUL": "OUI", "COEF_R": 1.0},
                     {"CHAM_GD": phi, "TOUT": "OUI", "CUMUL": "OUI", "COEF_R": 1.0},
                     {"CHAM_GD": cohesion, "GROUP_NO": "A", "CUMUL": "OUI"}])  # fmt: skip
    values = dict(zip(both.numbering.dofs, both.values, strict=True))
    assert values == {(0, "X2"): 4.0, (N_EL, "X1"): 66.4}
    with pytest.raises(CommandError, match="NEUT_R"):
        run(session, "CREA_CHAMP", OPERATION="AFFE", TYPE_CHAM="NOEU_NEUT_R", MODELE=model,
            AFFE={"TOUT": "OUI", "NOM_CMP": "DX", "VALE": 1.0})  # fmt: skip
