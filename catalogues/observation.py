"""OBSERVATION: a computed result seen as a test would measure it.

The fields of a result (DEPL, VITE, ACCE, EPSI_NOEU) carried onto the
sensor mesh of MODELE_2 (PROJECTION), averaged over a strain gauge's cells
(EPSI_MOYENNE), turned into the sensors' frames (MODI_REPERE) and reduced
to the measured components (FILTRE); code_aster's observation_ops macro.
"""

from asterlite.catalogues.common import NO_EFFECT_LOG, group_ma, group_no, noeud, tout
from asterlite.catalogues.common_post import NOM_CHAM, concept_is

from asterlite.catalog import AU_MOINS_UN, BLOC, FACT, OPER, SIMP, UN_PARMI, equal_to

RESULTS = ("mode_meca", "evol_elas", "dyna_harmo", "dyna_trans")


def _sd_prod(kw) -> str:
    """The observed result has the type of RESULTAT."""
    for name in RESULTS:
        if concept_is(kw.get("RESULTAT"), name):
            return name
    return "dyna_harmo"  # check mode without the concept


def _frame_block(condition, **keywords):
    return BLOC(condition=equal_to("REPERE", condition), **keywords)


OBSERVATION = OPER(
    nom="OBSERVATION",
    sd_prod=_sd_prod,
    fr="Fields of a result observed at the sensors of an experimental mesh",
    MODELE_1=SIMP(statut="o", typ="modele_sdaster"),
    MODELE_2=SIMP(statut="o", typ="modele_sdaster"),
    RESULTAT=SIMP(statut="o", typ=RESULTS),
    NOM_CHAM=SIMP(statut="o", typ="TXM", max="**", into=NOM_CHAM),
    regles=(
        UN_PARMI("TOUT_ORDRE", "NUME_ORDRE", "FREQ", "LIST_FREQ", "NUME_MODE", "INST", "LIST_INST"),
    ),
    TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
    NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
    FREQ=SIMP(statut="f", typ="R", max="**"),
    LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
    NUME_MODE=SIMP(statut="f", typ="I", max="**"),
    LIST_ORDRE=SIMP(statut="f", typ="listis_sdaster"),
    INST=SIMP(statut="f", typ="R", max="**"),
    LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
    NOEUD_CMP=SIMP(statut="f", typ="TXM", max="**"),
    # what PROJ_CHAMP receives
    PROJECTION=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
    CAS_FIGURE=SIMP(statut="f", typ="TXM", into=("2D", "3D", "2.5D", "1.5D")),
    DISTANCE_MAX=SIMP(statut="f", typ="R"),
    DISTANCE_ALARME=SIMP(statut="f", typ="R"),
    ALARME=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON"), no_effect=NO_EFFECT_LOG),
    TYPE_CHAM=SIMP(
        statut="f",
        typ="TXM",
        into=("NOEU",),
        no_effect="observed fields are nodal fields anyway",
    ),
    MATR_RIGI=SIMP(statut="f", typ="matr_asse_depl_r"),
    MATR_MASS=SIMP(statut="f", typ="matr_asse_depl_r"),
    VIS_A_VIS=FACT(
        statut="f",
        max="**",
        regles=(
            AU_MOINS_UN("TOUT_1", "GROUP_MA_1", "GROUP_NO_1"),
            AU_MOINS_UN("TOUT_2", "GROUP_MA_2", "GROUP_NO_2"),
        ),
        TOUT_1=tout(),
        GROUP_MA_1=group_ma(),
        GROUP_NO_1=group_no(),
        TOUT_2=tout(),
        GROUP_MA_2=group_ma(),
        GROUP_NO_2=group_no(),
        CAS_FIGURE=SIMP(statut="f", typ="TXM", into=("2D", "3D", "2.5D", "1.5D")),
    ),
    MODI_REPERE=FACT(
        statut="f",
        max="**",
        regles=(UN_PARMI("REPERE"), AU_MOINS_UN("TOUT", "GROUP_MA", "GROUP_NO", "NOEUD")),
        GROUP_MA=group_ma(),
        GROUP_NO=group_no(),
        NOEUD=noeud(),
        TOUT=tout(),
        TYPE_CHAM=SIMP(
            statut="f",
            typ="TXM",
            into=("VECT_2D", "VECT_3D", "TENS_2D", "TENS_3D"),
            defaut="VECT_3D",
        ),
        b_vect_2d=BLOC(
            condition=equal_to("TYPE_CHAM", "VECT_2D"),
            NOM_CMP=SIMP(statut="o", typ="TXM", min=2, max=2),
        ),
        b_vect_3d=BLOC(
            condition=equal_to("TYPE_CHAM", "VECT_3D"),
            NOM_CMP=SIMP(statut="f", typ="TXM", min=3, max=3, defaut=("DX", "DY", "DZ")),
        ),
        b_tens_2d=BLOC(
            condition=equal_to("TYPE_CHAM", "TENS_2D"),
            NOM_CMP=SIMP(
                statut="f", typ="TXM", min=4, max=4, defaut=("EPXX", "EPYY", "EPZZ", "EPXY")
            ),
        ),
        b_tens_3d=BLOC(
            condition=equal_to("TYPE_CHAM", "TENS_3D"),
            NOM_CMP=SIMP(
                statut="f",
                typ="TXM",
                min=6,
                max=6,
                defaut=("EPXX", "EPYY", "EPZZ", "EPXY", "EPXZ", "EPYZ"),
            ),
        ),
        REPERE=SIMP(
            statut="o", typ="TXM", into=("UTILISATEUR", "CYLINDRIQUE", "NORMALE", "DIR_JAUGE")
        ),
        b_normale=_frame_block(
            "NORMALE",
            regles=(UN_PARMI("VECT_X", "VECT_Y"),),
            VECT_X=SIMP(statut="f", typ="R", min=3, max=3),
            VECT_Y=SIMP(statut="f", typ="R", min=3, max=3),
        ),
        b_utilisateur=_frame_block("UTILISATEUR", ANGL_NAUT=SIMP(statut="o", typ="R", max=3)),
        b_cylindrique=_frame_block(
            "CYLINDRIQUE",
            ORIGINE=SIMP(statut="o", typ="R", min=2, max=3),
            AXE_Z=SIMP(statut="o", typ="R", min=3, max=3),
        ),
        b_dir_jauge=_frame_block(
            "DIR_JAUGE",
            VECT_X=SIMP(statut="f", typ="R", min=3, max=3),
            VECT_Y=SIMP(statut="f", typ="R", min=3, max=3),
        ),
    ),
    EPSI_MOYENNE=FACT(
        statut="f",
        max="**",
        regles=(AU_MOINS_UN("GROUP_MA", "GROUP_NO", "NOEUD"),),
        NOEUD=noeud(),
        GROUP_NO=group_no(),
        GROUP_MA=group_ma(),
        SEUIL_VARI=SIMP(statut="f", typ="R", defaut=0.1),
        MASQUE=SIMP(statut="f", typ="TXM", max=6),
    ),
    FILTRE=FACT(
        statut="f",
        max="**",
        regles=(UN_PARMI("DDL_ACTIF"), AU_MOINS_UN("TOUT", "GROUP_MA", "GROUP_NO", "NOEUD")),
        GROUP_MA=group_ma(),
        GROUP_NO=group_no(),
        NOEUD=noeud(),
        TOUT=tout(),
        NOM_CHAM=SIMP(statut="o", typ="TXM", into=NOM_CHAM),
        DDL_ACTIF=SIMP(statut="f", typ="TXM", max=6),
    ),
    TITRE=SIMP(statut="f", typ="TXM", no_effect=NO_EFFECT_LOG),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2), no_effect=NO_EFFECT_LOG),
)
