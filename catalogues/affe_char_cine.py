"""AFFE_CHAR_CINE: imposed values of DOFs, eliminated from the assembled
system (kinematic loads, no Lagrange multipliers).

``kinematic_loads(value_type)`` builds the keywords shared with
AFFE_CHAR_CINE_F, where the values are functions instead of reals. The
thermal and acoustic forms (THER_IMPO, ACOU_IMPO) are not in asterlite's
catalogue; EVOL_IMPO is, and refused by the command.
"""

from asterlite.catalogues.affe_char_meca import DDL_MECANIQUE
from asterlite.catalogues.common import group_ma, group_no, noeud, tout

from asterlite.catalog import AU_MOINS_UN, FACT, OPER, SIMP, UN_PARMI


def kinematic_loads(value_type) -> dict:
    components = {c: SIMP(statut="f", typ=value_type) for c in DDL_MECANIQUE}
    return dict(
        MODELE=SIMP(statut="o", typ="modele_sdaster"),
        SYNTAXE=SIMP(statut="c", typ="TXM", into=("OUI", "NON"), defaut="NON"),
        MECA_IMPO=FACT(
            statut="f",
            max="**",
            regles=(
                UN_PARMI("TOUT", "GROUP_MA", "GROUP_NO", "NOEUD"),
                AU_MOINS_UN(*DDL_MECANIQUE),
            ),
            TOUT=tout(),
            GROUP_MA=group_ma(),
            GROUP_NO=group_no(),
            NOEUD=noeud(),
            **components,
        ),
        INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    )


AFFE_CHAR_CINE = OPER(
    nom="AFFE_CHAR_CINE",
    sd_prod="char_cine_meca",
    reentrant="n",
    fr="Imposed DOF values eliminated from the assembled system",
    regles=(UN_PARMI("MECA_IMPO", "EVOL_IMPO"),),
    EVOL_IMPO=SIMP(statut="f", typ=("evol_elas", "evol_noli")),
    NOM_CMP=SIMP(statut="f", typ="TXM", max="**"),
    **kinematic_loads("R"),
)
