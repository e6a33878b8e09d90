"""Viscoelastic materials (DEFI_MATERIAU ELAS_VISCO: complex G and NU) in
the 3D and plane solids, and imposed values given as functions of FREQ
(AFFE_CHAR_CINE_F) in a harmonic response: the complex stiffness against
the linearity of the Hooke matrix in the Lamé coefficients, and a
base-driven bar with a complex modulus against its closed-form response."""

from __future__ import annotations

import numpy as np
import pytest

from asterlite.concepts.assembly import DofNumbering, Material, MaterialField, Model
from asterlite.fem.assemble import assemble_blocks, build_numbering_dofs
from asterlite.fem.element_errors import ElementError
from asterlite.fem.element_materials import elastic_values
from asterlite.fem.options import option_blocks
from asterlite.io.export import describe_run
from asterlite.runtime.session import Session
from tests.solid_meshes import box_mesh

TWO_PI = 2.0 * np.pi


def _assembled(mesh, modelisation, material, option):
    model = Model(mesh=mesh, cell_modelisation={c: modelisation for c in range(mesh.n_cells)})
    field = MaterialField(mesh=mesh, cell_material={c: material for c in range(mesh.n_cells)})
    numbering = DofNumbering(mesh=mesh, dofs=build_numbering_dofs(model.node_components()))
    blocks = option_blocks(model, None, option, materials=field)
    return assemble_blocks(blocks, numbering).toarray()


def _elastic(lam, mu):
    """An ELAS material of Lamé coefficients (lam, mu)."""
    young = mu * (3.0 * lam + 2.0 * mu) / (lam + mu)
    return Material(behaviours={"ELAS": {"E": young, "NU": lam / (2.0 * (lam + mu)), "RHO": 1.0}})


@pytest.mark.parametrize("kind", ["HEXA8", "HEXA20", "TETRA10"])
def test_hyst_stiffness_is_that_of_the_complex_lame_coefficients(kind):
    """K is linear in (lambda, mu): RIGI_MECA_HYST of ELAS_VISCO must be
    K(Re lambda, Re mu) + i K(Im lambda, Im mu), and RIGI_MECA its real part."""
    mesh = box_mesh(kind, n=(2, 1, 1), size=(2.0, 1.0, 0.5), jitter=0.0)
    shear, poisson = 3.0e6 + 1.1e6j, 0.45 - 0.01j
    lam = 2.0 * shear * poisson / (1.0 - 2.0 * poisson)
    visco = Material(behaviours={"ELAS_VISCO": {"G": shear, "NU": poisson, "RHO": 1400.0}})
    hyst = _assembled(mesh, "3D", visco, "RIGI_MECA_HYST")
    real = _assembled(mesh, "3D", _elastic(lam.real, shear.real), "RIGI_MECA")
    imag = _assembled(mesh, "3D", _elastic(lam.imag, shear.imag), "RIGI_MECA")
    scale = np.abs(hyst).max()
    np.testing.assert_allclose(hyst.real, real, atol=1e-12 * scale)
    np.testing.assert_allclose(hyst.imag, imag, atol=1e-12 * scale)
    rigi = _assembled(mesh, "3D", visco, "RIGI_MECA")
    assert not np.iscomplexobj(rigi)
    np.testing.assert_allclose(rigi, real, atol=1e-12 * scale)
    # the density of ELAS_VISCO makes the mass
    mass = _assembled(mesh, "3D", visco, "MASS_MECA")
    assert mass.sum() / 3.0 == pytest.approx(1400.0 * 2.0 * 1.0 * 0.5, rel=1e-12)


def test_hyst_of_elas_visco_equals_amor_hyst_for_a_proportional_modulus():
    """G (1 + i eta) with a real NU is ELAS with AMOR_HYST = eta."""
    mesh = box_mesh("HEXA8", n=(2, 2, 1))
    eta, shear, poisson = 0.07, 8.0e10, 0.3
    visco = Material(behaviours={"ELAS_VISCO": {"G": shear * (1 + 1j * eta), "NU": poisson}})
    elastic = Material(
        behaviours={"ELAS": {"E": 2.0 * shear * (1 + poisson), "NU": poisson, "AMOR_HYST": eta}}
    )
    a = _assembled(mesh, "3D", visco, "RIGI_MECA_HYST")
    b = _assembled(mesh, "3D", elastic, "RIGI_MECA_HYST")
    np.testing.assert_allclose(a, b, atol=1e-12 * np.abs(b).max())


def test_plane_stress_hooke_matrix_is_complex_in_e_and_nu():
    """C_PLAN: D = E/(1-nu^2) [...] with E = 2 G (1 + nu) complex (code_aster's
    separ_RI_elas_cp: 2 G / (1 - nu), 2 G nu / (1 - nu), G)."""
    from asterlite.fem.plane_elements import elasticity

    shear, poisson = 2.0e6 + 0.5e6j, 0.4 + 0.02j
    d = elasticity("C_PLAN", [2.0 * shear * (1.0 + poisson)], [poisson])[0]
    assert d[0, 0] == pytest.approx(2.0 * shear / (1.0 - poisson), rel=1e-14)
    assert d[0, 1] == pytest.approx(2.0 * shear * poisson / (1.0 - poisson), rel=1e-14)
    assert d[3, 3] == pytest.approx(shear, rel=1e-14)


def test_families_without_viscoelasticity_refuse_it_by_name():
    mesh = box_mesh("HEXA8", n=(1, 1, 1))
    visco = Material(behaviours={"ELAS_VISCO": {"G": 1.0 + 0.1j, "NU": 0.3 + 0j}})
    field = MaterialField(mesh=mesh, cell_material={0: visco})
    with pytest.raises(ElementError, match="ELAS_VISCO"):
        elastic_values(field, [0], mesh, "DKT", need_density=False)


# ----------------------------------------------------------------------------- a deck

LENGTH, SIDE, N_CELLS = 1.0, 0.1, 24
G0, ETA, RHO = 4.0e6, 0.2, 1200.0
FREQS = (3.0, 7.5, 12.0)


def bar_mesh() -> str:
    """A bar of HEXA8 cells along x; groups BASE (x = 0 face) and END (x = L)."""
    xs = np.linspace(0.0, LENGTH, N_CELLS + 1)
    corners = [(0.0, 0.0), (SIDE, 0.0), (SIDE, SIDE), (0.0, SIDE)]
    lines = [" TITRE", " BAR", " FINSF", " %", " COOR_3D"]
    for i, x in enumerate(xs):
        for j, (y, z) in enumerate(corners):
            lines.append(f" N{4 * i + j + 1} {x:.12g} {y:.12g} {z:.12g}")
    lines += [" FINSF", " %", " HEXA8"]
    for i in range(N_CELLS):
        a = [4 * i + j + 1 for j in range(4)]
        b = [4 * (i + 1) + j + 1 for j in range(4)]
        # code_aster's HEXA8: a face, then the facing one
        lines.append(f" H{i + 1} " + " ".join(f"N{n}" for n in a + b))
    lines += [" FINSF", " %", " QUAD4", " QB N1 N2 N3 N4", " FINSF", " %"]
    end = [4 * N_CELLS + j + 1 for j in range(4)]
    lines += [" GROUP_MA", " BASE", " QB", " FINSF", " %"]
    lines += [" GROUP_NO", " END"] + [f" N{n}" for n in end] + [" FINSF", " %", " FIN"]
    return "\n".join(lines) + "\n"


DECK = f"""DEBUT(CODE="OUI")
MAIL = LIRE_MAILLAGE(FORMAT="ASTER")
MODELE = AFFE_MODELE(MAILLAGE=MAIL, AFFE=_F(TOUT="OUI", PHENOMENE="MECANIQUE",
                     MODELISATION="3D"))
VISCO = DEFI_MATERIAU(ELAS_VISCO=_F(G={G0} * (1 + {ETA}j), NU=0.0 + 0.0j, RHO={RHO}))
HYST = DEFI_MATERIAU(ELAS=_F(E=2 * {G0}, NU=0.0, RHO={RHO}, AMOR_HYST={ETA}))
BASEU = FORMULE(VALE="1.e-3 * (1.0 + FREQ / 10.0)", NOM_PARA="FREQ")
ZERO = DEFI_CONSTANTE(VALE=0.0)
HALF = FORMULE(VALE="0.5 + 0.0 * FREQ", NOM_PARA="FREQ")
MOTION = AFFE_CHAR_CINE_F(MODELE=MODELE, MECA_IMPO=_F(GROUP_MA="BASE", DX=BASEU, DY=ZERO,
                          DZ=ZERO))
NUM = NUME_DDL(MODELE=MODELE)
LF = DEFI_LIST_REEL(VALE={FREQS})
for name, mater in (("V", VISCO), ("H", HYST)):
    CHMAT = AFFE_MATERIAU(MAILLAGE=MAIL, AFFE=_F(TOUT="OUI", MATER=mater))
    KEL = CALC_MATR_ELEM(OPTION="RIGI_MECA", MODELE=MODELE, CHAM_MATER=CHMAT)
    KHEL = CALC_MATR_ELEM(OPTION="RIGI_MECA_HYST", MODELE=MODELE, CHAM_MATER=CHMAT,
                          RIGI_MECA=KEL)
    MEL = CALC_MATR_ELEM(OPTION="MASS_MECA", MODELE=MODELE, CHAM_MATER=CHMAT)
    KH = ASSE_MATRICE(MATR_ELEM=KHEL, NUME_DDL=NUM, CHAR_CINE=MOTION)
    MM = ASSE_MATRICE(MATR_ELEM=MEL, NUME_DDL=NUM, CHAR_CINE=MOTION)
    RESU = DYNA_VIBRA(TYPE_CALCUL="HARM", BASE_CALCUL="PHYS", MATR_MASS=MM, MATR_RIGI=KH,
                      LIST_FREQ=LF, NOM_CHAM="DEPL",
                      EXCIT=_F(CHARGE=MOTION, FONC_MULT=HALF))
    if name == "V":
        RESU_V = RESU
    else:
        RESU_H = RESU
FIN()
"""


@pytest.fixture(scope="module")
def bar_run(tmp_path_factory):
    folder = tmp_path_factory.mktemp("visco")
    (folder / "d.mail").write_text(bar_mesh())
    (folder / "d.comm").write_text(DECK)
    export = folder / "d.export"
    export.write_text("P time_limit 300\nF comm d.comm D 1\nF mail d.mail D 20\n")
    session = Session(describe_run(export), output_dir=folder / "out")
    session.run_all()
    return session


def _end_dx(result):
    mesh = result.numbering.mesh
    rows = [result.numbering.dof_index(mesh.node_index[f"N{4 * N_CELLS + j + 1}"], "DX")
            for j in range(4)]  # fmt: skip
    return result.fields["DEPL"][:, rows]


def test_base_driven_bar_with_a_complex_modulus_has_the_closed_form_response(bar_run):
    """u(L) = U0(f) / cos(k L), k = omega sqrt(rho / E*), E* = 2 G0 (1 + i eta)
    (NU = 0: uniaxial stress); U0(f) the imposed function of FREQ times FONC_MULT."""
    f = np.array(FREQS)
    modulus = 2.0 * G0 * (1.0 + 1j * ETA)
    k = TWO_PI * f * np.sqrt(RHO / modulus)
    expected = 0.5 * 1.0e-3 * (1.0 + f / 10.0) / np.cos(k * LENGTH)
    end = _end_dx(bar_run.namespace["RESU_V"])
    np.testing.assert_allclose(end, np.repeat(expected[:, None], 4, axis=1), rtol=2e-3)
    # the imposed face moves as the function says
    base = bar_run.namespace["RESU_V"]
    mesh = base.numbering.mesh
    row = base.numbering.dof_index(mesh.node_index["N1"], "DX")
    np.testing.assert_allclose(base.fields["DEPL"][:, row], 0.5e-3 * (1.0 + f / 10.0), rtol=1e-12)


def test_elas_visco_and_amor_hyst_give_the_same_harmonic_response(bar_run):
    v = bar_run.namespace["RESU_V"].fields["DEPL"]
    h = bar_run.namespace["RESU_H"].fields["DEPL"]
    np.testing.assert_allclose(v, h, rtol=1e-10, atol=1e-12 * np.abs(h).max())
