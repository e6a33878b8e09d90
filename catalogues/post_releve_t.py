"""POST_RELEVE_T: extract components of fields (values, means, extrema) into a table."""

from asterlite.catalogues.common_post import NOM_CHAM, precision_blocs

from asterlite.catalog import (
    AU_MOINS_UN,
    BLOC,
    ENSEMBLE,
    EXCLUS,
    FACT,
    OPER,
    PRESENT_ABSENT,
    PRESENT_PRESENT,
    SIMP,
    UN_PARMI,
    equal_to,
    exists,
)


def _where(**extra) -> dict:
    return dict(
        TOUT=SIMP(statut="f", typ="TXM", into=("OUI",)),
        GROUP_MA=SIMP(statut="f", typ="grma", max="**"),
        MAILLE=SIMP(statut="c", typ="ma", max="**"),
        GROUP_NO=SIMP(statut="f", typ="grno", max="**"),
        NOEUD=SIMP(statut="c", typ="no", max="**"),
        TOUT_CMP=SIMP(statut="f", typ="TXM", into=("OUI",)),
        NOM_CMP=SIMP(statut="f", typ="TXM", max="**"),
        **extra,
    )


POST_RELEVE_T = OPER(
    nom="POST_RELEVE_T",
    sd_prod="table_sdaster",
    reentrant="n",
    fr="Extract field components (values, means, extrema) into a table",
    ACTION=FACT(
        statut="o",
        max="**",
        regles=(UN_PARMI("RESULTAT", "CHAM_GD"),),
        OPERATION=SIMP(
            statut="o",
            typ="TXM",
            max=2,
            into=("EXTRACTION", "MOYENNE", "MOYENNE_ARITH", "EXTREMA"),
        ),
        INTITULE=SIMP(statut="o", typ="TXM"),
        CHAM_GD=SIMP(statut="f", typ=("cham_no_sdaster", "cham_elem")),
        RESULTAT=SIMP(statut="f", typ="resultat_sdaster"),
        b_extrac=BLOC(
            condition=exists("RESULTAT"),
            regles=(
                EXCLUS(
                    "TOUT_ORDRE",
                    "NUME_ORDRE",
                    "LIST_ORDRE",
                    "NUME_MODE",
                    "LIST_MODE",
                    "INST",
                    "LIST_INST",
                    "FREQ",
                    "LIST_FREQ",
                    "NOEUD_CMP",
                    "NOM_CAS",
                ),
            ),
            NOM_CHAM=SIMP(statut="o", typ="TXM", into=NOM_CHAM),
            TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
            NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
            LIST_ORDRE=SIMP(statut="f", typ="listis_sdaster"),
            NUME_MODE=SIMP(statut="f", typ="I", max="**"),
            LIST_MODE=SIMP(statut="f", typ="listis_sdaster"),
            NOEUD_CMP=SIMP(statut="f", typ="TXM", max="**"),
            NOM_CAS=SIMP(statut="f", typ="TXM", max="**"),
            FREQ=SIMP(statut="f", typ="R", max="**"),
            LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
            INST=SIMP(statut="f", typ="R", max="**"),
            LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
            **precision_blocs(),
        ),
        b_extrema=BLOC(
            condition=equal_to("OPERATION", "EXTREMA"),
            regles=(EXCLUS("TOUT_CMP", "NOM_CMP"),),
            **_where(),
        ),
        b_moyenne_arith=BLOC(
            condition=equal_to("OPERATION", "MOYENNE_ARITH"),
            regles=(EXCLUS("TOUT_CMP", "NOM_CMP"),),
            **_where(),
        ),
        b_autre=BLOC(
            condition=~equal_to("OPERATION", ("EXTREMA", "MOYENNE_ARITH")),
            regles=(
                AU_MOINS_UN("GROUP_NO", "NOEUD"),
                UN_PARMI("TOUT_CMP", "NOM_CMP", "INVARIANT", "ELEM_PRINCIPAUX", "RESULTANTE"),
                PRESENT_PRESENT("TRAC_DIR", "DIRECTION"),
                ENSEMBLE("MOMENT", "POINT"),
                PRESENT_PRESENT("MOMENT", "RESULTANTE"),
                PRESENT_ABSENT("TOUT_CMP", "TRAC_DIR", "TRAC_NOR"),
                EXCLUS("TRAC_DIR", "TRAC_NOR"),
                PRESENT_PRESENT("ORIGINE", "AXE_Z"),
            ),
            **_where(
                INVARIANT=SIMP(statut="f", typ="TXM", into=("OUI",)),
                ELEM_PRINCIPAUX=SIMP(statut="f", typ="TXM", into=("OUI",)),
                RESULTANTE=SIMP(
                    statut="f",
                    typ="TXM",
                    max="**",
                    into=("DX", "DY", "DZ", "NXX", "NYY", "NXY", "PRE1", "PRE2", "TEMP"),
                ),
                MOMENT=SIMP(
                    statut="f",
                    typ="TXM",
                    max="**",
                    into=("DRX", "DRY", "DRZ", "MXX", "MYY", "MXY"),
                ),
                POINT=SIMP(statut="f", typ="R", max="**"),
                REPERE=SIMP(
                    statut="f",
                    typ="TXM",
                    defaut="GLOBAL",
                    into=("GLOBAL", "LOCAL", "POLAIRE", "UTILISATEUR", "CYLINDRIQUE"),
                ),
                ANGL_NAUT=SIMP(statut="f", typ="R", min=3, max=3),
                ORIGINE=SIMP(statut="f", typ="R", min=3, max=3),
                AXE_Z=SIMP(statut="f", typ="R", min=3, max=3),
                TRAC_NOR=SIMP(statut="f", typ="TXM", into=("OUI",)),
                TRAC_DIR=SIMP(statut="f", typ="TXM", into=("OUI",)),
                DIRECTION=SIMP(statut="f", typ="R", max="**"),
                VECT_Y=SIMP(statut="f", typ="R", max="**"),
                MOYE_NOEUD=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
            ),
        ),
        FORMAT_C=SIMP(statut="f", typ="TXM", defaut="MODULE", into=("MODULE", "REEL", "IMAG")),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    TITRE=SIMP(statut="f", typ="TXM"),
)
