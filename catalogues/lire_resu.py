"""LIRE_RESU: fields read from a file into a result (MED; the I-DEAS formats are refused)."""

from asterlite.catalogues.common_post import NOM_CHAM, precision_blocs

from asterlite.catalog import (
    BLOC,
    ENSEMBLE,
    FACT,
    OPER,
    PRESENT_PRESENT,
    SIMP,
    UN_PARMI,
    equal_to,
    exists,
    is_in,
)

_TYPES = {
    "EVOL_THER": "evol_ther",
    "EVOL_ELAS": "evol_elas",
    "EVOL_NOLI": "evol_noli",
    "MODE_MECA": "mode_meca",
    "MODE_MECA_C": "mode_meca_c",
    "DYNA_TRANS": "dyna_trans",
    "DYNA_HARMO": "dyna_harmo",
    "EVOL_CHAR": "evol_char",
    "EVOL_VARC": "evol_varc",
    "MODE_EMPI": "mode_empi",
    "EVOL_SECH": "evol_sech",
}


def lire_resu_type(kw) -> str:
    return _TYPES.get(kw.get("TYPE_RESU"), "dyna_trans")


def _time_given():
    return exists("INST") | exists("LIST_INST") | exists("FREQ") | exists("LIST_FREQ")


LIRE_RESU = OPER(
    nom="LIRE_RESU",
    sd_prod=lire_resu_type,
    reentrant="f",
    fr="Read fields from a file (MED) into a result",
    regles=(
        UN_PARMI("MAILLAGE", "MODELE"),
        UN_PARMI(
            "TOUT_ORDRE", "NUME_ORDRE", "LIST_ORDRE", "INST", "LIST_INST", "FREQ", "LIST_FREQ"
        ),
    ),
    TYPE_RESU=SIMP(statut="o", typ="TXM", into=tuple(_TYPES)),
    FORMAT=SIMP(statut="o", typ="TXM", into=("IDEAS", "IDEAS_DS58", "MED")),
    INFO=SIMP(statut="f", typ="I", into=(1, 2)),
    TITRE=SIMP(statut="f", typ="TXM"),
    RESULTAT=SIMP(statut="f", typ=tuple(_TYPES.values())),
    MAILLAGE=SIMP(statut="f", typ="maillage_sdaster"),
    MODELE=SIMP(statut="f", typ="modele_sdaster"),
    CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
    CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
    TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
    NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
    INST=SIMP(statut="f", typ="R", max="**"),
    LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
    LIST_ORDRE=SIMP(statut="f", typ="listis_sdaster"),
    FREQ=SIMP(statut="f", typ="R", max="**"),
    LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
    b_acce_reel=BLOC(condition=_time_given(), **precision_blocs()),
    b_evol_elas=BLOC(
        condition=equal_to("TYPE_RESU", "EVOL_ELAS"),
        EXCIT=FACT(
            statut="f",
            max="**",
            CHARGE=SIMP(statut="o", typ=("char_meca", "char_cine_meca")),
            FONC_MULT=SIMP(statut="f", typ=("fonction_sdaster", "nappe_sdaster", "formule")),
            TYPE_CHARGE=SIMP(statut="f", typ="TXM", defaut="FIXE_CSTE", into=("FIXE_CSTE",)),
        ),
    ),
    b_mode_meca=BLOC(
        condition=is_in("TYPE_RESU", ("MODE_MECA", "MODE_MECA_C")),
        MATR_RIGI=SIMP(statut="f", typ="matr_asse_depl_r", max=1),
        MATR_MASS=SIMP(statut="f", typ="matr_asse_depl_r", max=1),
    ),
    b_mode_empi=BLOC(
        condition=equal_to("TYPE_RESU", "MODE_EMPI"),
        NUME_PLAN=SIMP(statut="f", typ="I", defaut=0),
    ),
    b_data58=BLOC(
        condition=equal_to("FORMAT", "IDEAS_DS58"),
        UNITE=SIMP(statut="f", typ="I", defaut=19),
    ),
    b_data58b=BLOC(
        condition=equal_to("FORMAT", "IDEAS_DS58")
        & is_in("TYPE_RESU", ("DYNA_TRANS", "DYNA_HARMO")),
        NOM_CHAM=SIMP(
            statut="o",
            typ="TXM",
            into=("DEPL", "VITE", "ACCE", "EPSI_NOEU", "SIEF_NOEU"),
            max="**",
        ),
        REDEFI_ORIENT=FACT(
            statut="f",
            max="**",
            regles=(PRESENT_PRESENT("CODE_DIR", "DIRECTION", "NOEUD"),),
            CODE_DIR=SIMP(statut="f", typ="I", into=(1, 2, 3)),
            DIRECTION=SIMP(statut="f", typ="R", min=3, max=3),
            NOEUD=SIMP(statut="f", typ="no", max="**"),
        ),
    ),
    b_ideas=BLOC(
        condition=equal_to("FORMAT", "IDEAS"),
        NB_VARI=SIMP(statut="f", typ="I"),
        UNITE=SIMP(statut="f", typ="I", defaut=19),
        NOM_CHAM=SIMP(statut="o", typ="TXM", max="**", into=NOM_CHAM),
        FORMAT_IDEAS=FACT(
            statut="f",
            max="**",
            regles=(UN_PARMI("POSI_INST", "POSI_FREQ"),),
            NOM_CHAM=SIMP(statut="o", typ="TXM", into=NOM_CHAM),
            NUME_DATASET=SIMP(statut="f", typ="I", into=(55, 57, 2414)),
            RECORD_3=SIMP(statut="f", typ="I", max=10),
            RECORD_6=SIMP(statut="f", typ="I", max=10),
            RECORD_9=SIMP(statut="f", typ="I", max=10),
            POSI_ORDRE=SIMP(statut="o", typ="I", min=2, max=2),
            POSI_NUME_MODE=SIMP(statut="f", typ="I", min=2, max=2),
            POSI_MASS_GENE=SIMP(statut="f", typ="I", min=2, max=2),
            POSI_AMOR_GENE=SIMP(statut="f", typ="I", min=2, max=2),
            POSI_INST=SIMP(statut="f", typ="I", min=2, max=2),
            POSI_FREQ=SIMP(statut="f", typ="I", min=2, max=2),
            NOM_CMP=SIMP(statut="o", typ="TXM", max="**"),
        ),
    ),
    b_med=BLOC(
        condition=equal_to("FORMAT", "MED"),
        UNITE=SIMP(statut="f", typ="I", defaut=81),
        FORMAT_MED=FACT(
            statut="o",
            max="**",
            regles=(ENSEMBLE("NOM_CMP", "NOM_CMP_MED"), UN_PARMI("NOM_CHAM_MED", "NOM_RESU")),
            NOM_CHAM=SIMP(statut="o", typ="TXM", max=1, into=NOM_CHAM),
            NOM_CHAM_MED=SIMP(statut="f", typ="TXM", max=1),
            NOM_RESU=SIMP(statut="f", typ="TXM", max=1),
            NOM_CMP=SIMP(statut="f", typ="TXM", max="**"),
            NOM_CMP_MED=SIMP(statut="f", typ="TXM", max="**"),
        ),
        PROL_ZERO=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
    ),
)
