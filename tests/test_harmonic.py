"""DYNA_VIBRA TYPE_CALCUL='HARM' (asterlite.harmonic): the solvers against the
exact response of damped one- and two-degree-of-freedom systems (viscous and
hysteretic), the load coefficients, and a deck exercising each keyword
family on the physical and the generalized basis."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp

from asterlite.fem.constraints import eliminate
from asterlite.harmonic import HarmonicLoad, derived_fields, load_matrix, modal, physical
from asterlite.io.export import describe_run
from asterlite.runtime.session import Session

TWO_PI = 2.0 * np.pi


def exact(mass, stiffness, damping, f, force):
    """(K + iωC - ω²M)⁻¹ F, one frequency at a time."""
    out = []
    for freq in np.atleast_1d(f):
        w = TWO_PI * freq
        a = np.asarray(stiffness, dtype=complex) - w * w * np.asarray(mass)
        if damping is not None:
            a = a + 1j * w * np.asarray(damping)
        out.append(np.linalg.solve(a, force))
    return np.array(out)


# ----------------------------------------------------------------------------- one DOF


def test_sdof_viscous_is_the_textbook_receptance():
    m, k, xi = 2.0, 8.0e4, 0.03
    c = 2.0 * xi * np.sqrt(k * m)
    f = np.linspace(1.0, 60.0, 200)
    q, info = modal.solve([[m]], [[k]], [[c]], f, np.ones((f.size, 1)))
    w, wn = TWO_PI * f, np.sqrt(k / m)
    r = w / wn
    expected = (1.0 / k) / (1.0 - r**2 + 2j * xi * r)
    assert info.method == "diagonal"
    np.testing.assert_allclose(q[:, 0], expected, rtol=1e-12)
    # the peak of |q| is at ω_n sqrt(1 - 2ξ²), its height 1 / (2ξ sqrt(1 - ξ²)) / k
    fine = np.linspace(0.95, 1.05, 20001) * wn / TWO_PI
    amplitude = np.abs(modal.solve([[m]], [[k]], [[c]], fine, np.ones((fine.size, 1)))[0][:, 0])
    peak = fine[np.argmax(amplitude)] * TWO_PI
    assert peak == pytest.approx(wn * np.sqrt(1 - 2 * xi**2), rel=1e-5)
    assert amplitude.max() * k == pytest.approx(1 / (2 * xi * np.sqrt(1 - xi**2)), rel=1e-6)


def test_sdof_hysteretic_phase_lag_is_constant_below_resonance():
    m, k, eta = 1.0, 1.0e4, 0.05
    f = np.array([0.0, 1.0, 5.0, 15.0])
    q, _ = modal.solve([[m]], [[k * (1 + 1j * eta)]], None, f, np.ones((4, 1)))
    expected = 1.0 / (k * (1 + 1j * eta) - (TWO_PI * f) ** 2 * m)
    np.testing.assert_allclose(q[:, 0], expected, rtol=1e-13)
    assert np.angle(q[0, 0]) == pytest.approx(-np.arctan(eta), rel=1e-12)


# ----------------------------------------------------------------------------- several DOFs


def two_dof():
    mass = np.array([[3.0, 0.0], [0.0, 1.5]])
    stiffness = np.array([[3.0e4, -1.0e4], [-1.0e4, 1.0e4]])
    damping = np.array([[12.0, -4.0], [-4.0, 4.0]])  # not proportional
    return mass, stiffness, damping


@pytest.mark.parametrize("method", ["direct", "state-space"])
def test_mdof_dense_solvers_match_the_exact_response(method):
    mass, stiffness, damping = two_dof()
    f = np.linspace(0.5, 40.0, 157)
    force = np.array([1.0, -2.0])
    q, info = modal.solve(mass, stiffness, damping, f, np.tile(force, (f.size, 1)), method=method)
    np.testing.assert_allclose(q, exact(mass, stiffness, damping, f, force), rtol=1e-11)
    assert info.method == method


def test_mdof_hysteretic_state_space_on_a_larger_basis():
    rng = np.random.default_rng(3)
    n = 40
    a = rng.normal(size=(n, n))
    mass = a @ a.T + n * np.eye(n)
    b = rng.normal(size=(n, n))
    stiffness = (b @ b.T + n * np.eye(n)) * 1e3 * (1 + 0.02j)
    f = np.linspace(0.1, 20.0, 600)
    rhs = rng.normal(size=(f.size, n)) + 1j * rng.normal(size=(f.size, n))
    q, info = modal.solve(mass, stiffness, None, f, rhs)
    assert info.method == "state-space"
    reference = np.linalg.solve(modal.dynamic_matrices(mass, stiffness, None, f), rhs[..., None])
    np.testing.assert_allclose(q, reference[..., 0], rtol=1e-9, atol=1e-14 * np.abs(q).max())


def test_undamped_resonance_is_a_numerical_error():
    with pytest.raises(modal.SingularSystem) as raised:
        modal.solve([[1.0]], [[(TWO_PI * 5.0) ** 2]], None, [4.0, 5.0], np.ones((2, 1)))
    assert raised.value.frequency == 5.0


def test_constrained_generalized_coordinates():
    """q restricted to {B q = 0} (a coupled generalized model's interface)."""
    mass, stiffness, damping = two_dof()
    basis = np.array([[1.0], [1.0]]) / np.sqrt(2.0)  # q1 = q2
    f = np.array([3.0, 7.0])
    force = np.array([1.0, 0.5])
    q, _ = modal.solve(mass, stiffness, damping, f, np.tile(force, (2, 1)), basis)
    t = basis
    r = exact(t.T @ mass @ t, t.T @ stiffness @ t, t.T @ damping @ t, f, t.T @ force)
    np.testing.assert_allclose(q, r @ t.T, rtol=1e-13)
    np.testing.assert_allclose(q[:, 0], q[:, 1], rtol=1e-14)


def test_physical_sweep_under_a_fixed_dof_equals_the_reduced_exact_response(monkeypatch):
    """A 3-DOF chain with DOF 0 fixed (DDL_IMPO): the sparse solve on the
    eliminated system gives the 2-DOF exact response and 0 on the fixed DOF."""
    k, m = 2.0e4, 1.5
    stiffness = sp.csr_matrix(k * np.array([[1.0, -1.0, 0.0], [-1.0, 2.0, -1.0], [0.0, -1.0, 1.0]]))
    mass = sp.csr_matrix(m * np.eye(3))
    damping = 1e-4 * stiffness
    b_matrix = sp.csr_matrix(([1.0], ([0], [0])), shape=(1, 3))
    elimination = eliminate(b_matrix, np.zeros(1), 3)
    sweep = physical.prepare(elimination, stiffness, mass, damping)
    f = np.array([1.0, 10.0, 25.0])
    assert sweep.symmetric
    monkeypatch.setattr(physical, "LDL_MIN_SIZE", 1)  # the LDLT path on a small system
    force = np.array([0.0, 0.0, 3.0])
    u, info = physical.solve(sweep, f, force[None, :], np.ones((3, 1), dtype=complex))
    reduced = exact(
        mass.toarray()[1:, 1:], stiffness.toarray()[1:, 1:], damping.toarray()[1:, 1:], f, force[1:]
    )
    np.testing.assert_allclose(u[:, 1:], reduced, rtol=1e-12)
    assert np.all(u[:, 0] == 0)
    assert info["n_free"] == 2 and info["ldl"] == 3


# ----------------------------------------------------------------------------- loads and fields


class Linear:
    """A multiplier g(f) = a + b f (stands for a deck function)."""

    def evaluate(self, f):
        return 2.0 + 0.5 * np.asarray(f)


def test_load_coefficient_phase_and_power_of_omega():
    f = np.array([1.0, 3.0])
    load = HarmonicLoad(np.array([1.0, 2.0]), 1.5 - 0.5j, phase_deg=30.0, power=2)
    expected = (1.5 - 0.5j) * np.exp(1j * np.pi / 6) * (TWO_PI * f) ** 2
    np.testing.assert_allclose(load.coefficients(f), expected, rtol=1e-15)
    function = HarmonicLoad(np.array([1.0, 0.0]), Linear(), phase_deg=-90.0)
    np.testing.assert_allclose(function.coefficients(f), -1j * (2.0 + 0.5 * f), atol=1e-15)
    rhs = load_matrix([load, function], f, 2)
    np.testing.assert_allclose(rhs[:, 1], 2 * expected, rtol=1e-15)


def test_velocity_and_acceleration_are_i_omega_and_minus_omega_squared():
    depl = np.array([[1.0 + 2.0j], [0.5 - 1.0j]])
    f = np.array([2.0, -3.0])
    fields = derived_fields(depl, f, ("DEPL", "VITE", "ACCE"))
    np.testing.assert_allclose(fields["VITE"][:, 0], 1j * TWO_PI * f * depl[:, 0])
    # code_aster's omega2(f) keeps the sign of f
    np.testing.assert_allclose(fields["ACCE"][:, 0], -np.sign(f) * (TWO_PI * f) ** 2 * depl[:, 0])


# ----------------------------------------------------------------------------- deck

MESH = (
    " TITRE\n HARM TEST\n FINSF\n %\n COOR_3D\n"
    " N1 0.0 0.0 0.0\n N2 1.0 0.0 0.0\n N3 2.0 0.0 0.0\n FINSF\n %\n"
    " POI1\n P2 N2\n P3 N3\n FINSF\n %\n"
    " SEG2\n S12 N1 N2\n S23 N2 N3\n FINSF\n %\n"
    + "".join(
        f" GROUP_{kind}\n {name}\n {name}\n FINSF\n %\n"
        for kind, name in (
            ("NO", "N1"),
            ("NO", "N2"),
            ("NO", "N3"),
            ("MA", "P2"),
            ("MA", "P3"),
            ("MA", "S12"),
            ("MA", "S23"),
        )
    )  # fmt: skip
    + " FIN\n"
)
M2, M3, K1, K2, C1, C2, ETA = 3.0, 1.5, 2.0e4, 1.0e4, 12.0, 4.0, 0.04
FREQS = (2.0, 9.5, 17.0, 31.0)
DECK = f"""DEBUT(CODE="OUI")
MAIL = LIRE_MAILLAGE(FORMAT="ASTER")
MODELE = AFFE_MODELE(MAILLAGE=MAIL, AFFE=_F(TOUT="OUI", PHENOMENE="MECANIQUE",
                     MODELISATION="DIS_T"))
CARA = AFFE_CARA_ELEM(MODELE=MODELE, DISCRET=(
    _F(GROUP_MA="P2", CARA="M_T_D_N", VALE={M2}),
    _F(GROUP_MA="P3", CARA="M_T_D_N", VALE={M3}),
    _F(GROUP_MA="S12", CARA="K_T_D_L", VALE=({K1}, 1.0, 1.0), AMOR_HYST={ETA}),
    _F(GROUP_MA="S23", CARA="K_T_D_L", VALE=({K2}, 1.0, 1.0), AMOR_HYST={ETA}),
    _F(GROUP_MA="S12", CARA="A_T_D_L", VALE=({C1}, 0.0, 0.0)),
    _F(GROUP_MA="S23", CARA="A_T_D_L", VALE=({C2}, 0.0, 0.0)),
))
BLOCAGE = AFFE_CHAR_MECA(MODELE=MODELE, DDL_IMPO=(
    _F(GROUP_NO="N1", DX=0.0, DY=0.0, DZ=0.0),
    _F(GROUP_NO=("N2", "N3"), DY=0.0, DZ=0.0),
))
FORCE = AFFE_CHAR_MECA(MODELE=MODELE, FORCE_NODALE=_F(GROUP_NO="N3", FX=10.0))
ASSEMBLAGE(MODELE=MODELE, CARA_ELEM=CARA, CHARGE=BLOCAGE, NUME_DDL=CO("NUM"),
    MATR_ASSE=(_F(MATRICE=CO("RIGI"), OPTION="RIGI_MECA"),
               _F(MATRICE=CO("MASS"), OPTION="MASS_MECA"),
               _F(MATRICE=CO("AMOR"), OPTION="AMOR_MECA")),
    VECT_ASSE=_F(VECTEUR=CO("F3"), OPTION="CHAR_MECA", CHARGE=FORCE))
RIGEL = CALC_MATR_ELEM(MODELE=MODELE, OPTION="RIGI_MECA", CARA_ELEM=CARA, CHARGE=BLOCAGE)
HYSEL = CALC_MATR_ELEM(MODELE=MODELE, OPTION="RIGI_MECA_HYST", RIGI_MECA=RIGEL, CARA_ELEM=CARA,
                       CHARGE=BLOCAGE)
RIGH = ASSE_MATRICE(MATR_ELEM=HYSEL, NUME_DDL=NUM)
LF = DEFI_LIST_REEL(VALE={FREQS})
GAIN = DEFI_FONCTION(NOM_PARA="FREQ", VALE_C=(0.0, 1.0, 0.5, 40.0, 3.0, -1.0))
VISC = DYNA_VIBRA(TYPE_CALCUL="HARM", BASE_CALCUL="PHYS", MATR_MASS=MASS, MATR_RIGI=RIGI,
    MATR_AMOR=AMOR, LIST_FREQ=LF, TOUT_CHAM="OUI",
    EXCIT=(_F(VECT_ASSE=F3, COEF_MULT=1.0),
           _F(CHARGE=FORCE, COEF_MULT_C=0.5 - 0.25j, PHAS_DEG=30.0, PUIS_PULS=1)))
HYST = DYNA_VIBRA(TYPE_CALCUL="HARM", BASE_CALCUL="PHYS", MATR_MASS=MASS, MATR_RIGI=RIGH,
    FREQ={FREQS[:2]}, NOM_CHAM="DEPL", EXCIT=_F(VECT_ASSE=F3, FONC_MULT_C=GAIN))
MODES = CALC_MODES(MATR_RIGI=RIGI, MATR_MASS=MASS, CALC_FREQ=_F(NMAX_FREQ=2))
NUMG = NUME_DDL_GENE(BASE=MODES, STOCKAGE="PLEIN")
MG = PROJ_MATR_BASE(BASE=MODES, NUME_DDL_GENE=NUMG, MATR_ASSE=MASS)
KG = PROJ_MATR_BASE(BASE=MODES, NUME_DDL_GENE=NUMG, MATR_ASSE=RIGI)
CG = PROJ_MATR_BASE(BASE=MODES, NUME_DDL_GENE=NUMG, MATR_ASSE=AMOR)
FG = PROJ_VECT_BASE(BASE=MODES, NUME_DDL_GENE=NUMG, VECT_ASSE=F3, TYPE_VECT="FORC")
GVISC = DYNA_VIBRA(TYPE_CALCUL="HARM", BASE_CALCUL="GENE", MATR_MASS=MG, MATR_RIGI=KG,
    MATR_AMOR=CG, LIST_FREQ=LF, EXCIT=_F(VECT_ASSE_GENE=FG, COEF_MULT=1.0))
GMODAL = DYNA_VIBRA(TYPE_CALCUL="HARM", BASE_CALCUL="GENE", MATR_MASS=MG, MATR_RIGI=KG,
    AMOR_MODAL=_F(AMOR_REDUIT=0.02), LIST_FREQ=LF, NOM_CHAM=("DEPL", "ACCE"),
    EXCIT=_F(VECT_ASSE_GENE=FG, COEF_MULT=1.0))
PVISC = REST_GENE_PHYS(RESU_GENE=GVISC, TOUT_CHAM="OUI")
U3 = RECU_FONCTION(RESULTAT=VISC, NOM_CHAM="DEPL", GROUP_NO="N3", NOM_CMP="DX")
Q1 = RECU_FONCTION(RESU_GENE=GMODAL, NOM_CHAM="ACCE", NUME_CMP_GENE=1)
MOD3 = CALC_FONCTION(EXTRACTION=_F(FONCTION=U3, PARTIE="MODULE"))
TEST_RESU(RESU=_F(RESULTAT=VISC, NOM_CHAM="DEPL", GROUP_NO="N3", NOM_CMP="DX", FREQ={FREQS[1]},
                  VALE_CALC_C=1.0 + 1.0j))
FIN()
"""


@pytest.fixture(scope="module")
def deck_run(tmp_path_factory):
    folder = tmp_path_factory.mktemp("harm")
    (folder / "d.mail").write_text(MESH)
    (folder / "d.comm").write_text(DECK)
    export = folder / "d.export"
    export.write_text("P time_limit 300\nF comm d.comm D 1\nF mail d.mail D 20\n")
    session = Session(describe_run(export), output_dir=folder / "out")
    session.run_all()
    return session


def chain_matrices(complex_stiffness=False):
    factor = 1 + 1j * ETA if complex_stiffness else 1.0
    stiffness = np.array([[K1 + K2, -K2], [-K2, K2]]) * factor
    return np.diag([M2, M3]), stiffness, np.array([[C1 + C2, -C2], [-C2, C2]])


def dx(result, node):
    mesh = result.numbering.mesh
    return result.numbering.dof_index(mesh.node_index[node], "DX")


def test_deck_physical_viscous_with_every_coefficient(deck_run):
    mass, stiffness, damping = chain_matrices()
    f = np.array(FREQS)
    force = np.array([0.0, 10.0])
    coef = 1.0 + (0.5 - 0.25j) * np.exp(1j * np.pi / 6) * TWO_PI * f  # COEF_MULT + COEF_MULT_C...
    expected = exact(mass, stiffness, damping, f, force) * coef[:, None]
    visc = deck_run.namespace["VISC"]
    rows = [dx(visc, "N2"), dx(visc, "N3")]
    np.testing.assert_allclose(visc.fields["DEPL"][:, rows], expected, rtol=1e-11)
    np.testing.assert_allclose(
        visc.fields["ACCE"][:, rows], -((TWO_PI * f) ** 2)[:, None] * expected, rtol=1e-11
    )
    np.testing.assert_allclose(visc.frequencies, f)
    u3 = deck_run.namespace["U3"]
    assert u3.aster_type == "fonction_c" and u3.NOM_PARA == "FREQ"
    np.testing.assert_allclose(u3.ordinates, expected[:, 1], rtol=1e-11)
    np.testing.assert_allclose(deck_run.namespace["MOD3"].ordinates, np.abs(expected[:, 1]))
    # the deck's TEST_RESU compares a complex value (VALE_CALC_C)
    record = deck_run.tests[-1]
    assert record.value == pytest.approx(expected[1, 1], rel=1e-11)


def test_deck_physical_hysteretic_with_a_complex_function(deck_run):
    mass, stiffness, _ = chain_matrices(complex_stiffness=True)
    f = np.array(FREQS[:2])
    gain = np.interp(f, [0.0, 40.0], [1.0, 3.0]) + 1j * np.interp(f, [0.0, 40.0], [0.5, -1.0])
    expected = exact(mass, stiffness, None, f, np.array([0.0, 10.0])) * gain[:, None]
    hyst = deck_run.namespace["HYST"]
    assert set(hyst.fields) == {"DEPL"}
    np.testing.assert_allclose(
        hyst.fields["DEPL"][:, [dx(hyst, "N2"), dx(hyst, "N3")]], expected, rtol=1e-11
    )


def test_deck_generalized_complete_basis_equals_physical(deck_run):
    """Two modes span the chain: GENE with the projected damping restores
    the physical response exactly."""
    visc, gene = deck_run.namespace["VISC"], deck_run.namespace["PVISC"]
    f = np.array(FREQS)
    mass, stiffness, damping = chain_matrices()
    expected = exact(mass, stiffness, damping, f, np.array([0.0, 10.0]))
    for name in ("DEPL", "VITE", "ACCE"):
        values = gene.fields[name][:, [dx(gene, "N2"), dx(gene, "N3")]]
        factor = {"DEPL": 1.0, "VITE": 1j * TWO_PI * f, "ACCE": -((TWO_PI * f) ** 2)}[name]
        np.testing.assert_allclose(values, expected * np.reshape(factor, (-1, 1)), rtol=1e-9)
    assert visc.fields["DEPL"].shape == gene.fields["DEPL"].shape


def test_deck_modal_damping_is_two_xi_sqrt_km(deck_run):
    modes, result = deck_run.namespace["MODES"], deck_run.namespace["GMODAL"]
    mg = np.diag(deck_run.namespace["MG"].matrix)
    kg = np.diag(deck_run.namespace["KG"].matrix)
    fg = deck_run.namespace["FG"].values
    f = np.array(FREQS)
    w = TWO_PI * f
    q = fg[None, :] / (kg - w[:, None] ** 2 * mg + 1j * w[:, None] * 2 * 0.02 * np.sqrt(kg * mg))
    assert set(result.fields) == {"DEPL", "ACCE"}
    np.testing.assert_allclose(result.fields["DEPL"], q, rtol=1e-8)
    q1 = deck_run.namespace["Q1"]
    np.testing.assert_allclose(q1.ordinates, -(w**2) * q[:, 0], rtol=1e-8)
    assert modes.n_modes == 2


def test_an_unread_keyword_stops_the_run_by_name(tmp_path):
    (tmp_path / "d.mail").write_text(MESH)
    deck = DECK.replace(
        'MATR_AMOR=AMOR, LIST_FREQ=LF, TOUT_CHAM="OUI",',
        'MATR_AMOR=AMOR, LIST_FREQ=LF, TOUT_CHAM="OUI", MATR_IMPE_PHI=RIGI,',
    )
    (tmp_path / "d.comm").write_text(deck)
    export = tmp_path / "d.export"
    export.write_text("F comm d.comm D 1\nF mail d.mail D 20\n")
    from asterlite.runtime.runner import run_deck

    report = run_deck(export, output_dir=tmp_path / "out")
    assert report.status == "UNSUPPORTED"
    assert "MATR_IMPE_PHI" in report.message


def test_bar_axial_force_from_complex_displacements():
    """EFGE_ELNO of a bar (te0185): N = E A / L (u2 - u1)·e at both nodes,
    complex for a harmonic state."""
    from asterlite.concepts.assembly import (
        DofNumbering,
        ElementCharacteristics,
        Material,
        MaterialField,
        Model,
    )
    from asterlite.concepts.mesh import Mesh
    from asterlite.fem.element_fields import bar_element_fields

    mesh = Mesh(
        coords=np.array([[0.0, 0.0, 0.0], [3.0, 4.0, 0.0]]),
        node_names=["A", "B"],
        cell_names=["AB"],
        cell_types=["SEG2"],
        cell_nodes=[(0, 1)],
    )
    model = Model(mesh=mesh, cell_modelisation={0: "BARRE"})
    cara = ElementCharacteristics(model=model, sections={0: {"A": 2.0e-4}})
    steel = Material(behaviours={"ELAS": {"E": 2.0e11}})
    materials = MaterialField(mesh=mesh, cell_material={0: steel})
    numbering = DofNumbering(mesh, [(n, c) for n in (0, 1) for c in ("DX", "DY", "DZ")])
    u = np.zeros((2, 6), dtype=complex)
    u[0, 3:5] = (3e-5 + 1e-6j, 4e-5)  # node B moves along the bar
    u[1, 0] = 1e-5j  # node A moves along x
    fields = bar_element_fields(model, cara, materials, numbering, [0], u, ["EFGE_ELNO"])
    n = fields["EFGE_ELNO"].values[:, 0, :, 0]
    stiffness = 2.0e11 * 2.0e-4 / 5.0
    expected = stiffness * np.array([(0.6 * (3e-5 + 1e-6j) + 0.8 * 4e-5), -0.6 * 1e-5j])
    np.testing.assert_allclose(n, np.column_stack([expected, expected]), rtol=1e-13)


def test_physical_sweep_falls_back_to_pivoting(monkeypatch):
    """A zero pivot (K = [[0, 1], [1, 0]] at 0 Hz) and a non-symmetric damping
    are factorised by SuperLU with pivoting; the answers stay exact."""
    eye = eliminate(sp.csr_matrix((0, 2)), np.zeros(0), 2)
    stiffness = sp.csr_matrix(np.array([[0.0, 1.0], [1.0, 0.0]]))
    mass = sp.csr_matrix(np.eye(2))
    force = np.array([[1.0, 2.0]])
    sweep = physical.prepare(eye, stiffness, mass)
    monkeypatch.setattr(physical, "LDL_MIN_SIZE", 1)
    u, info = physical.solve(sweep, [0.0], force, np.ones((1, 1)))
    np.testing.assert_allclose(u[0], [2.0, 1.0], rtol=1e-14)
    assert info["superlu"] == 1 and info["ldl"] == 0
    gyro = sp.csr_matrix(np.array([[1.0, 3.0], [-3.0, 1.0]]))
    sweep = physical.prepare(eye, 1e3 * sp.csr_matrix(np.eye(2)), mass, gyro)
    assert not sweep.symmetric
    u, info = physical.solve(sweep, [2.0], force, np.ones((1, 1)))
    expected = exact(np.eye(2), 1e3 * np.eye(2), gyro.toarray(), [2.0], force[0])
    np.testing.assert_allclose(u, expected, rtol=1e-13)
    assert info["superlu"] == 1


def test_discrete_segment_forces_in_the_element_frame():
    """EFGE_ELNO of a DIS_T segment (ef0042): f = K_local P u, first node's
    sign reversed: N = k_N (u2 - u1)·x at both nodes, shear along y."""
    from asterlite.concepts.assembly import (
        DiscreteAssignment,
        DofNumbering,
        ElementCharacteristics,
        Model,
    )
    from asterlite.concepts.mesh import Mesh
    from asterlite.fem.element_fields import discrete_element_fields

    mesh = Mesh(
        coords=np.array([[0.0, 0.0, 0.0], [0.0, 2.0, 0.0]]),  # along global Y
        node_names=["A", "B"],
        cell_names=["AB"],
        cell_types=["SEG2"],
        cell_nodes=[(0, 1)],
    )
    model = Model(mesh=mesh, cell_modelisation={0: "DIS_T"})
    spring = DiscreteAssignment("K", "K_T_D_L", np.array([100.0, 7.0, 3.0]), repere="LOCAL")
    cara = ElementCharacteristics(model=model, discrete={0: {"K": spring}})
    numbering = DofNumbering(mesh, [(n, c) for n in (0, 1) for c in ("DX", "DY", "DZ")])
    u = np.array([[0.0, 0.0, 0.0, 0.5, 2.0 + 1.0j, 0.0]])  # B: DX 0.5, DY 2 + i
    forces = discrete_element_fields(model, cara, numbering, [0], u, ["EFGE_ELNO"])
    values = forces["EFGE_ELNO"].values[0, 0]  # (2 nodes, N VY VZ)
    np.testing.assert_allclose(values[:, 0], [100.0 * (2.0 + 1.0j)] * 2, rtol=1e-14)
    # local y is -X for a segment along +Y: the shear is -7 x 0.5 at both ends
    np.testing.assert_allclose(np.abs(values[:, 1]), [3.5, 3.5], rtol=1e-14)
    assert values[0, 1] == pytest.approx(values[1, 1])


def test_ideas_dataset_55_round_trip(tmp_path):
    """A complex nodal field written as code_aster's dataset 55 (1PE13.5,
    six slots per node) reads back to 6 significant digits."""
    from asterlite.concepts.assembly import DofNumbering
    from asterlite.concepts.mesh import Mesh
    from asterlite.io.ideas_result import field_lines, fortran_e, read_datasets_55, record_field

    assert fortran_e(1.0237e-4) == "  1.02370E-04"
    assert fortran_e(-2.5e-300, 3) == "-2.50000E-300"  # 13 characters, no blank
    mesh = Mesh(
        coords=np.zeros((2, 3)),
        node_names=["N1", "N2"],
        cell_names=[],
        cell_types=[],
        cell_nodes=[],
    )
    numbering = DofNumbering(mesh, [(0, "DX"), (1, "DX"), (1, "DY")])
    values = np.array([1.0237e-4 - 8.5187e-6j, -2.5e-6 + 1j * 3.3e-7, 7.0])
    lines = field_lines(numbering, values, "DEPL", 5, (2, 1, 1, 3), (12.5,), "T", "S")
    path = tmp_path / "fort.38"
    path.write_text("\n".join(lines) + "\n")
    (dataset,) = read_datasets_55(path)
    assert dataset["records"][5].split() == ["1", "5", "3", "8", "5", "6"]
    assert record_field(dataset["records"], 7, 4) == "3"
    assert float(record_field(dataset["records"], 8, 1)) == 12.5
    np.testing.assert_array_equal(dataset["labels"], [1, 2])
    np.testing.assert_allclose(dataset["values"][1, :2], values[1:], rtol=5e-6)
    assert dataset["values"][0, 1] == 0
