"""DYNA_VIBRA on the physical basis with an ONDE_PLANE load (a history of
time and space on paraxial boundaries), end to end: a vertical P wave sent
up a 1D soil column (3D hexahedra, lateral motion blocked, 3D_ABSO base)
reaches the free top delayed by H/c_p and doubled, then leaves through the
absorbing base, which lets the top come back to rest."""

from __future__ import annotations

import numpy as np

E, NU, RHO = 3.0e10, 0.25, 2450.0
C_P = np.sqrt(E * (1 - NU) / ((1 + NU) * (1 - 2 * NU)) / RHO)
HEIGHT, CELLS = 200.0, 40


def _column_mesh() -> str:
    corners = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]

    def node(level, corner):
        return f"N{4 * level + corner + 1}"

    lines = ["COOR_3D"]
    for level in range(CELLS + 1):
        for corner, (x, y) in enumerate(corners):
            lines.append(f"{node(level, corner)} {x} {y} {level * HEIGHT / CELLS}")
    lines += ["FINSF", "HEXA8"]
    for level in range(CELLS):
        below = " ".join(node(level, c) for c in range(4))
        above = " ".join(node(level + 1, c) for c in range(4))
        lines.append(f"V{level + 1} {below} {above}")
    lines += ["FINSF", "QUAD4", "B1 " + " ".join(node(0, c) for c in range(4)), "FINSF"]
    lines += ["GROUP_MA", "VOL " + " ".join(f"V{k + 1}" for k in range(CELLS)), "FINSF"]
    lines += ["GROUP_MA", "BASE B1", "FINSF", "GROUP_NO", f"TOP {node(CELLS, 0)}", "FINSF"]
    return "\n".join(lines + ["FIN"]) + "\n"


DECK = f"""DEBUT(CODE="OUI")
mail = LIRE_MAILLAGE(FORMAT="ASTER")
mail = MODI_MAILLAGE(reuse=mail, MAILLAGE=mail,
                     ORIE_PEAU=_F(GROUP_MA_PEAU="BASE", GROUP_MA_INTERNE="VOL"))
sol = DEFI_MATERIAU(ELAS=_F(E={E}, NU={NU}, RHO={RHO}))
CHMAT = AFFE_MATERIAU(MAILLAGE=mail, AFFE=_F(TOUT="OUI", MATER=sol))
MODELE = AFFE_MODELE(MAILLAGE=mail, AFFE=(
    _F(GROUP_MA="VOL", PHENOMENE="MECANIQUE", MODELISATION="3D"),
    _F(GROUP_MA="BASE", PHENOMENE="MECANIQUE", MODELISATION="3D_ABSO")))
BLOC = AFFE_CHAR_MECA(MODELE=MODELE, DDL_IMPO=_F(TOUT="OUI", DX=0.0, DY=0.0))
ASSEMBLAGE(MODELE=MODELE, CHAM_MATER=CHMAT, CHARGE=BLOC, NUME_DDL=CO("NUME"),
           MATR_ASSE=(_F(MATRICE=CO("RIGI"), OPTION="RIGI_MECA"),
                      _F(MATRICE=CO("MASSE"), OPTION="MASS_MECA"),
                      _F(MATRICE=CO("AMOR"), OPTION="AMOR_MECA")))
VINC = FORMULE(NOM_PARA="INST", VALE="exp(-((INST-0.04)/0.01)**2)")
ONDE = AFFE_CHAR_MECA_F(MODELE=MODELE, ONDE_PLANE=_F(
    DIRECTION=(0.0, 0.0, 1.0), TYPE_ONDE="P", FONC_SIGNAL=VINC,
    COOR_SOURCE=(0.0, 0.0, 0.0), GROUP_MA="BASE"))
LINST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=0.25, PAS=0.0005))
RESU = DYNA_VIBRA(BASE_CALCUL="PHYS", TYPE_CALCUL="TRAN", MODELE=MODELE, CHAM_MATER=CHMAT,
                  MATR_MASS=MASSE, MATR_RIGI=RIGI, MATR_AMOR=AMOR,
                  SCHEMA_TEMPS=_F(SCHEMA="NEWMARK"), INCREMENT=_F(LIST_INST=LINST),
                  EXCIT=_F(CHARGE=ONDE))
VTOP = RECU_FONCTION(RESULTAT=RESU, NOM_CHAM="VITE", GROUP_NO="TOP", NOM_CMP="DZ")
IMPR_FONCTION(FORMAT="TABLEAU", UNITE=30, COURBE=_F(FONCTION=VTOP))
FIN()
"""


def _incident(t):
    return np.where(t >= 0.0, np.exp(-(((t - 0.04) / 0.01) ** 2)), 0.0)


def test_a_p_wave_crosses_a_column_and_leaves_through_its_absorbing_base(tmp_path):
    from asterlite.runtime.runner import run_deck

    (tmp_path / "col.comm").write_text(DECK)
    (tmp_path / "col.mail").write_text(_column_mesh())
    (tmp_path / "col.export").write_text(
        "F comm col.comm D 1\nF mail col.mail D 20\nF libr vtop.txt R 30\n"
    )
    report = run_deck(tmp_path / "col.export", tmp_path / "out")
    assert report.exit_code == 0, report.message
    rows = [
        line.split()
        for line in (tmp_path / "out" / "vtop.txt").read_text().splitlines()
        if line.strip() and line.split()[0][0] in "0123456789"
    ]
    times, velocity = np.array(rows, dtype=float).T
    assert times[-1] == 0.25 and times.size == 501
    # the free top moves with twice the incident velocity, H / c_p later
    expected = 2.0 * _incident(times - HEIGHT / C_P)
    assert np.abs(velocity - expected).max() < 0.02 * 2.0
    assert abs(times[np.argmax(velocity)] - (0.04 + HEIGHT / C_P)) <= 0.0005
    # the reflected wave went out through the base: nothing comes back
    assert np.abs(velocity[times > 0.04 + 3 * HEIGHT / C_P + 0.03]).max() < 0.005 * 2.0
