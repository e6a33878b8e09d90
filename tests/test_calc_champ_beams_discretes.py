"""CALC_CHAMP EFGE_ELNO on a model of beams and discrete elements: code_aster
computes it on every cell that has the option, the beams' section forces and
the springs' forces together. A bar NA-NB (POU_D_E) and a spring NB-NC
(DIS_TR, K_TR_D_L) in series between two clamps, pulled by F along x at NB:
u_B = F / (EA/L + k), the beam in traction E A u_B / L, the spring in
compression -k u_B, at both ends of each."""

from __future__ import annotations

import numpy as np

import asterlite

E, A, L, K, F = 2.0e11, 1.0e-3, 1.0, 5.0e7, 1.0e5

MESH = """COOR_3D
NA 0.0 0.0 0.0
NB 1.0 0.0 0.0
NC 2.0 0.0 0.0
FINSF
SEG2
S1 NA NB
S2 NB NC
FINSF
GROUP_MA
POUTRE S1
FINSF
GROUP_MA
RESSORT S2
FINSF
GROUP_NO
GB NB
FINSF
GROUP_NO
BOUTS NA NC
FINSF
FIN
"""

DECK = f"""DEBUT(CODE="OUI")
MAIL = LIRE_MAILLAGE(FORMAT="ASTER")
MODELE = AFFE_MODELE(MAILLAGE=MAIL, AFFE=(
    _F(GROUP_MA="POUTRE", PHENOMENE="MECANIQUE", MODELISATION="POU_D_E"),
    _F(GROUP_MA="RESSORT", PHENOMENE="MECANIQUE", MODELISATION="DIS_TR")))
ACIER = DEFI_MATERIAU(ELAS=_F(E={E}, NU=0.3, RHO=7800.0))
CHMAT = AFFE_MATERIAU(MAILLAGE=MAIL, AFFE=_F(GROUP_MA="POUTRE", MATER=ACIER))
CARA = AFFE_CARA_ELEM(MODELE=MODELE,
    POUTRE=_F(GROUP_MA="POUTRE", SECTION="GENERALE", CARA=("A", "IY", "IZ", "JX"),
              VALE=({A}, 1.0e-6, 1.0e-6, 2.0e-6)),
    DISCRET=(_F(GROUP_MA="RESSORT", CARA="K_TR_D_L", VALE=({K}, {K}, {K}, 1.0e3, 1.0e3, 1.0e3)),
             _F(GROUP_MA="RESSORT", CARA="M_TR_D_L", VALE=(0.0, 0.0, 0.0, 0.0))))
BLOC = AFFE_CHAR_MECA(MODELE=MODELE, DDL_IMPO=(
    _F(GROUP_NO="BOUTS", DX=0.0, DY=0.0, DZ=0.0, DRX=0.0, DRY=0.0, DRZ=0.0),
    _F(GROUP_NO="GB", DY=0.0, DZ=0.0, DRX=0.0, DRY=0.0, DRZ=0.0)))
TIRE = AFFE_CHAR_MECA(MODELE=MODELE, FORCE_NODALE=_F(GROUP_NO="GB", FX={F}))
STAT = MECA_STATIQUE(MODELE=MODELE, CHAM_MATER=CHMAT, CARA_ELEM=CARA,
                     EXCIT=(_F(CHARGE=BLOC), _F(CHARGE=TIRE)))
STAT = CALC_CHAMP(reuse=STAT, RESULTAT=STAT, CONTRAINTE="EFGE_ELNO")
FIN()
"""


def test_efge_elno_of_beams_and_springs_together(tmp_path):
    (tmp_path / "mixed.comm").write_text(DECK)
    (tmp_path / "mixed.mail").write_text(MESH)
    (tmp_path / "mixed.export").write_text(
        "P time_limit 300\nP memory_limit 2048\nP ncpus 1\n"
        "F comm mixed.comm D 1\nF mail mixed.mail D 20\n"
    )
    done = asterlite.run(tmp_path / "mixed.export", tmp_path / "out")
    assert done.status == "DONE", done
    result = done.concepts.raw["STAT"]
    u_b = F / (E * A / L + K)
    depl = np.asarray(result.fields["DEPL"])[-1]
    assert np.isclose(depl[result.numbering.dof_index("NB", "DX")], u_b, rtol=1e-12)
    field = result.element_fields["EFGE_ELNO"]
    mesh = result.numbering.mesh
    names = [mesh.cell_names[int(c)] for c in field.cells]
    assert sorted(names) == ["S1", "S2"]
    normal = field.values[-1, :, :, field.components.index("N")]
    np.testing.assert_allclose(normal[names.index("S1")], E * A / L * u_b, rtol=1e-10)
    np.testing.assert_allclose(normal[names.index("S2")], -K * u_b, rtol=1e-10)
