"""CREA_TABLE: build a table from lists, from a function, or from a result's field values."""

from asterlite.catalogues.common_post import NOM_CHAM, precision_blocs

from asterlite.catalog import (
    AU_MOINS_UN,
    BLOC,
    EXCLUS,
    FACT,
    OPER,
    PRESENT_ABSENT,
    SIMP,
    UN_PARMI,
    absent,
    exists,
)

_TYPES = {"TABLE_FONCTION": "table_fonction", "TABLE_CONTAINER": "table_container"}


def crea_table_type(kw) -> str:
    return _TYPES.get(kw.get("TYPE_TABLE"), "table_sdaster")


CREA_TABLE = OPER(
    nom="CREA_TABLE",
    sd_prod=crea_table_type,
    reentrant="n",
    fr="Create a table from lists, a function or a result",
    regles=(EXCLUS("FONCTION", "LISTE", "RESU"),),
    LISTE=FACT(
        statut="f",
        max="**",
        fr="One column given as a list",
        regles=(UN_PARMI("LISTE_I", "LISTE_R", "LISTE_K", "LISTE_CO"),),
        b_liste_irk=BLOC(condition=absent("LISTE_CO"), PARA=SIMP(statut="o", typ="TXM")),
        TYPE_K=SIMP(statut="f", typ="TXM", defaut="K8", into=("K8", "K16", "K24")),
        NUME_LIGN=SIMP(statut="f", typ="I", max="**"),
        LISTE_I=SIMP(statut="f", typ="I", max="**"),
        LISTE_R=SIMP(statut="f", typ="R", max="**"),
        LISTE_K=SIMP(statut="f", typ="TXM", max="**"),
        LISTE_CO=SIMP(
            statut="f",
            typ=(
                "matr_asse_gene_r",
                "matr_elem_depl_r",
                "vect_elem_depl_r",
                "matr_elem_temp_r",
                "vect_elem_temp_r",
                "cham_gd_sdaster",
                "cham_no_sdaster",
                "carte_sdaster",
                "cham_elem",
                "mode_meca",
                "table_sdaster",
                "fonction_sdaster",
                "fonction_c",
                "nappe_sdaster",
            ),
            max="**",
        ),
    ),
    FONCTION=FACT(
        statut="f",
        fr="Table of the points of a function",
        FONCTION=SIMP(statut="o", typ=("fonction_c", "fonction_sdaster")),
        PARA=SIMP(statut="f", typ="TXM", min=2, max=2),
    ),
    RESU=FACT(
        statut="f",
        max=1,
        fr="Table of the values of a result or a field",
        regles=(
            UN_PARMI("CHAM_GD", "RESULTAT"),
            UN_PARMI("TOUT_CMP", "NOM_CMP", "NOM_VARI"),
            PRESENT_ABSENT("TOUT", "GROUP_MA", "GROUP_NO", "MAILLE", "NOEUD"),
            AU_MOINS_UN("TOUT", "GROUP_MA", "GROUP_NO", "MAILLE", "NOEUD"),
        ),
        CHAM_GD=SIMP(statut="f", typ="cham_gd_sdaster"),
        RESULTAT=SIMP(statut="f", typ="resultat_sdaster"),
        INTITULE=SIMP(statut="f", typ="TXM", defaut=" "),
        b_resultat=BLOC(
            condition=exists("RESULTAT"),
            regles=(
                EXCLUS(
                    "TOUT_ORDRE",
                    "NUME_ORDRE",
                    "LIST_ORDRE",
                    "INST",
                    "LIST_INST",
                    "MODE",
                    "LIST_MODE",
                    "FREQ",
                    "LIST_FREQ",
                ),
            ),
            NOM_CHAM=SIMP(statut="o", typ="TXM", into=NOM_CHAM),
            TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
            NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
            LIST_ORDRE=SIMP(statut="f", typ="listis_sdaster"),
            INST=SIMP(statut="f", typ="R", max="**"),
            LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
            MODE=SIMP(statut="f", typ="I", max="**"),
            LIST_MODE=SIMP(statut="f", typ="listis_sdaster"),
            FREQ=SIMP(statut="f", typ="R", max="**"),
            LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
            **precision_blocs(),
        ),
        b_cham_gd=BLOC(condition=exists("CHAM_GD"), CARA_ELEM=SIMP(statut="f", typ="cara_elem")),
        TOUT_CMP=SIMP(statut="f", typ="TXM", into=("OUI",)),
        NOM_CMP=SIMP(statut="f", typ="TXM", max="**"),
        NOM_VARI=SIMP(statut="f", typ="TXM", max="**"),
        TOUT=SIMP(statut="f", typ="TXM", into=("OUI",)),
        GROUP_MA=SIMP(statut="f", typ="grma", max="**"),
        GROUP_NO=SIMP(statut="f", typ="grno", max="**"),
        MAILLE=SIMP(statut="c", typ="ma", max="**"),
        NOEUD=SIMP(statut="c", typ="no", max="**"),
    ),
    TYPE_TABLE=SIMP(
        statut="f", typ="TXM", defaut="TABLE", into=("TABLE", "TABLE_FONCTION", "TABLE_CONTAINER")
    ),
    TITRE=SIMP(statut="f", typ="TXM"),
)
