"""Decks on a 3D solid cantilever (HEXA20 + QUAD8 skin): ORIE_PEAU,
INCLUDE_MATERIAU, face loads, FACTORISER / RESOUDRE, CREA_RESU MULT_ELAS,
POST_ELEM MASS_INER, CALC_MODES, MODE_STATIQUE SOLVEUR/NB_RHS and setMesh,
checked against beam theory."""

from __future__ import annotations

import json

import numpy as np
import pytest

from asterlite.runtime.runner import run_deck
from tests.solid_meshes import aster_mesh_text, box_mesh, with_side_faces

LENGTH, SIDE, E, NU, RHO = 1.0, 0.1, 2.0e11, 0.3, 7800.0
INERTIA = SIDE**4 / 12

MATERIAL_FILE = """
# a material file as code_aster's catalogue writes them
_E = DEFI_FONCTION(
    NOM_PARA="TEMP", VALE=(0.0, 2.0e11 * coef_unit(-6), 100.0, 1.8e11 * coef_unit(-6))
)
_NU = DEFI_CONSTANTE(VALE=0.3)
motscles = defi_motscles(
    ELAS=_F(extraction=True, E=temp_eval(_E), NU=0.3, RHO=7800.0 * coef_unit(-9)),
    ELAS_FO=_F(extraction=False, E=_E, NU=_NU),
)
"""

DECK = """
DEBUT(CODE="OUI")
mesh = LIRE_MAILLAGE(FORMAT="ASTER", UNITE=20)
mesh = MODI_MAILLAGE(reuse=mesh, MAILLAGE=mesh, ORIE_PEAU=_F(GROUP_MA_PEAU=("TIP", "CLAMP")))
model = AFFE_MODELE(
    MAILLAGE=mesh, AFFE=_F(TOUT="OUI", PHENOMENE="MECANIQUE", MODELISATION="3D")
)
steel = INCLUDE_MATERIAU(FICHIER="steel.data", EXTRACTION=_F(COMPOR="ELAS", TEMP_EVAL=0.0))
chmat = AFFE_MATERIAU(MAILLAGE=mesh, AFFE=_F(TOUT="OUI", MATER=steel))
clamp = AFFE_CHAR_MECA(MODELE=model, DDL_IMPO=_F(GROUP_MA="CLAMP", BLOCAGE="DEPLACEMENT"))
pull = AFFE_CHAR_MECA(MODELE=model, PRES_REP=_F(GROUP_MA="TIP", PRES=-1.0e6))
shear = AFFE_CHAR_MECA(MODELE=model, FORCE_FACE=_F(GROUP_MA="TIP", FZ=1.0e5))
ASSEMBLAGE(
    MODELE=model,
    CHAM_MATER=chmat,
    CHARGE=clamp,
    NUME_DDL=CO("nume"),
    MATR_ASSE=(
        _F(MATRICE=CO("rigi"), OPTION="RIGI_MECA"),
        _F(MATRICE=CO("mass"), OPTION="MASS_MECA"),
    ),
)
epull = CALC_VECT_ELEM(OPTION="CHAR_MECA", CHARGE=pull, CHAM_MATER=chmat)
vpull = ASSE_VECTEUR(NUME_DDL=nume, VECT_ELEM=epull)
eshear = CALC_VECT_ELEM(OPTION="CHAR_MECA", CHARGE=shear, CHAM_MATER=chmat)
vshear = ASSE_VECTEUR(NUME_DDL=nume, VECT_ELEM=eshear)
rigi = FACTORISER(reuse=rigi, MATR_ASSE=rigi, METHODE="MULT_FRONT")
upull = RESOUDRE(MATR=rigi, CHAM_NO=vpull)
ushear = RESOUDRE(MATR=rigi, CHAM_NO=vshear, POSTTRAITEMENTS="MINI")
cases = CREA_RESU(
    OPERATION="AFFE",
    TYPE_RESU="MULT_ELAS",
    AFFE=(
        _F(NOM_CHAM="DEPL", CHAM_GD=upull, NOM_CAS="PULL", MODELE=model, CHAM_MATER=chmat,
           CHARGE=(clamp, pull)),
        _F(NOM_CHAM="DEPL", CHAM_GD=ushear, NOM_CAS="SHEAR", MODELE=model, CHAM_MATER=chmat,
           CHARGE=(clamp, shear)),
    ),
)
TEST_RESU(
    RESU=(
        _F(RESULTAT=cases, NOM_CAS="PULL", NOM_CHAM="DEPL", GROUP_NO="AXIS", NOM_CMP="DX",
           REFERENCE="ANALYTIQUE", VALE_REFE=PULL_REFE, VALE_CALC=PULL_CALC, PRECISION=0.01),
        _F(RESULTAT=cases, NOM_CAS="SHEAR", NOM_CHAM="DEPL", GROUP_NO="AXIS", NOM_CMP="DZ",
           REFERENCE="ANALYTIQUE", VALE_REFE=SHEAR_REFE, VALE_CALC=SHEAR_CALC, PRECISION=0.02),
    )
)
inertia = POST_ELEM(MASS_INER=_F(TOUT="OUI"), MODELE=model, CHAM_MATER=chmat)
TEST_TABLE(TABLE=inertia, NOM_PARA="MASSE", REFERENCE="ANALYTIQUE",
           VALE_REFE=MASS_REFE, VALE_CALC=MASS_REFE, PRECISION=1e-9)
TEST_TABLE(TABLE=inertia, NOM_PARA="CDG_X", REFERENCE="ANALYTIQUE",
           VALE_REFE=0.5, VALE_CALC=0.5, PRECISION=1e-9)
modes = CALC_MODES(MATR_RIGI=rigi, MATR_MASS=mass, OPTION="PLUS_PETITE",
                   CALC_FREQ=_F(NMAX_FREQ=2))
modes.setMesh(mesh)
TEST_RESU(RESU=_F(RESULTAT=modes, NUME_ORDRE=1, PARA="FREQ", REFERENCE="ANALYTIQUE",
                  VALE_REFE=FREQ_REFE, VALE_CALC=FREQ_CALC, PRECISION=0.01))
stat = MODE_STATIQUE(MATR_RIGI=rigi, MATR_MASS=mass, SOLVEUR=_F(NB_RHS=4),
                     MODE_STAT=_F(GROUP_NO="AXIS0", AVEC_CMP="DX"))
FIN()
"""

EXPORT = """P time_limit 120
F comm solid.comm D 1
F mail solid.mail D 20
F nom steel.data D 0
"""


def _references():
    pull = 1.0e6 / E  # sigma L / E with sigma = 1 MPa
    force = 1.0e5 * SIDE**2
    shear = force * LENGTH**3 / (3 * E * INERTIA)
    bending = 1.875104**2 / (2 * np.pi) * np.sqrt(E * INERTIA / (RHO * SIDE**2 * LENGTH**4))
    return {
        "PULL_REFE": pull,
        "SHEAR_REFE": shear,
        "FREQ_REFE": bending,
        "MASS_REFE": RHO * SIDE**2 * LENGTH,
    }


# asterlite's own values (non-regression), within the analytic PRECISION above
CALC = {
    "PULL_CALC": 4.976287897155743e-06,
    "SHEAR_CALC": 0.00019851278090451333,
    "FREQ_CALC": 81.98167180890509,
}


def _write_study(folder, deck_text, material=MATERIAL_FILE, values=None):
    folder.mkdir(parents=True, exist_ok=True)
    mesh = with_side_faces(
        box_mesh("HEXA20", (10, 2, 2), (LENGTH, SIDE, SIDE)),
        {"CLAMP": (0, 0.0), "TIP": (0, LENGTH)},
    )
    # the beam's axis at the tip and at the clamp (centre of the section)
    centre = np.array([SIDE / 2, SIDE / 2])
    axis = np.nonzero(np.all(np.isclose(mesh.coords[:, 1:], centre), axis=1))[0]
    tip = axis[np.isclose(mesh.coords[axis, 0], LENGTH)]
    root = axis[np.isclose(mesh.coords[axis, 0], 0.0)]
    mesh.node_groups["AXIS"] = tip
    mesh.node_groups["AXIS0"] = root
    # the skin comes with faces turned both ways: ORIE_PEAU must fix them
    for k, cell in enumerate(mesh.cell_groups["TIP"]):
        if k % 2:
            nodes = mesh.cell_nodes[cell]
            mesh.cell_nodes[cell] = tuple(nodes[i] for i in (0, 3, 2, 1, 7, 6, 5, 4))
    (folder / "solid.mail").write_text(aster_mesh_text(mesh))
    (folder / "steel.data").write_text(material)
    text = deck_text
    for name, value in (values or {}).items():
        text = text.replace(name, repr(float(value)))
    (folder / "solid.comm").write_text(text)
    (folder / "solid.export").write_text(EXPORT)
    return folder / "solid.export"


def test_solid_cantilever_deck_against_beam_theory(tmp_path):
    export = _write_study(tmp_path, DECK, values={**_references(), **CALC})
    report = run_deck(export, tmp_path / "out")
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert report.status == "PASS", (report.message, summary.get("errors"))
    assert summary["checks_ok"] == summary["checks_total"] == 5
    log = (tmp_path / "out" / "message.log").read_text()
    # half the tip faces came inward: the pull would cancel without ORIE_PEAU
    assert "ORIE_PEAU:" in log and "faces reversed" in log
    assert "factorised:" in log and "relative residual" in log


def test_a_temperature_dependent_material_is_refused_where_it_is_used(tmp_path):
    deck = DECK.replace(', EXTRACTION=_F(COMPOR="ELAS", TEMP_EVAL=0.0)', "")
    export = _write_study(tmp_path, deck, values={**_references(), **CALC})
    report = run_deck(export, tmp_path / "out")
    assert report.status == "ERROR"
    assert "varies with TEMP" in report.message


def test_include_materiau_without_the_file_in_the_export(tmp_path):
    export = _write_study(tmp_path, DECK, values={**_references(), **CALC})
    export.write_text(EXPORT.replace("F nom steel.data D 0\n", ""))
    report = run_deck(export, tmp_path / "out")
    assert report.status == "ERROR"
    assert "steel.data" in report.message and "F nom" in report.message


def test_include_materiau_from_code_aster_catalogue_is_refused(tmp_path):
    deck = DECK.replace(
        'FICHIER="steel.data", EXTRACTION=_F(COMPOR="ELAS", TEMP_EVAL=0.0)',
        'NOM_AFNOR="Z2CN1810", TYPE_MODELE="REF", VARIANTE="A", TYPE_VALE="NOMI"',
    )
    export = _write_study(tmp_path, deck, values={**_references(), **CALC})
    report = run_deck(export, tmp_path / "out")
    assert report.status == "UNSUPPORTED"
    assert "NOM_AFNOR" in report.message


def test_resoudre_needs_a_factorised_matrix(tmp_path):
    deck = DECK.replace('rigi = FACTORISER(reuse=rigi, MATR_ASSE=rigi, METHODE="MULT_FRONT")\n', "")
    export = _write_study(tmp_path, deck, values={**_references(), **CALC})
    report = run_deck(export, tmp_path / "out")
    assert report.status == "ERROR" and "FACTORISER" in report.message


def test_factoriser_stops_on_a_singular_matrix(tmp_path):
    # one blocked DOF: the bar keeps five rigid-body motions
    deck = DECK.replace(
        'DDL_IMPO=_F(GROUP_MA="CLAMP", BLOCAGE="DEPLACEMENT")',
        'DDL_IMPO=_F(GROUP_NO="AXIS0", DX=0.0)',
    )
    export = _write_study(tmp_path, deck, values={**_references(), **CALC})
    report = run_deck(export, tmp_path / "out")
    assert report.status == "ERROR" and "singular" in report.message


def test_set_mesh_refuses_another_mesh():
    from asterlite.errors import CommandError
    from asterlite.post.deck_api import set_result_mesh

    class Result:
        numbering = type("N", (), {"mesh": box_mesh("HEXA8", (1, 1, 1))})()

    set_result_mesh(Result, Result.numbering.mesh)
    with pytest.raises(CommandError, match="incompatible meshes"):
        set_result_mesh(Result, box_mesh("HEXA8", (1, 1, 1)))


def test_pressure_on_inward_faces_is_refused_unless_veri_norm_is_off(tmp_path):
    """Without ORIE_PEAU half the tip faces point into the bar: code_aster's
    VERI_NORM check stops the deck; VERI_NORM='NON' takes them as they are."""
    orientation = DECK.splitlines()[3]
    assert "ORIE_PEAU" in orientation
    deck = DECK.replace(orientation + "\n", "")
    export = _write_study(tmp_path / "a", deck, values={**_references(), **CALC})
    report = run_deck(export, tmp_path / "a" / "out")
    assert report.status == "ERROR" and "ORIE_PEAU" in report.message
    unchecked = deck.replace("PRES_REP=_F(", 'VERI_NORM="NON", PRES_REP=_F(')
    export = _write_study(tmp_path / "b", unchecked, values={**_references(), **CALC})
    report = run_deck(export, tmp_path / "b" / "out")
    assert report.status == "NOOK"  # the inward faces push back: the pull is wrong
