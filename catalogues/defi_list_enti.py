"""DEFI_LIST_ENTI: a list of integers, given or extracted from a result's order numbers."""

from asterlite.catalog import BLOC, EXCLUS, FACT, OPER, SIMP, UN_PARMI, equal_to

DEFI_LIST_ENTI = OPER(
    nom="DEFI_LIST_ENTI",
    sd_prod="listis_sdaster",
    reentrant="n",
    fr="Define a strictly increasing list of integers",
    OPERATION=SIMP(statut="f", typ="TXM", defaut="DEFI", into=("DEFI", "NUME_ORDRE")),
    b_defi=BLOC(
        condition=equal_to("OPERATION", "DEFI"),
        regles=(UN_PARMI("VALE", "DEBUT"), EXCLUS("VALE", "INTERVALLE")),
        VALE=SIMP(statut="f", typ="I", max="**"),
        DEBUT=SIMP(statut="f", typ="I"),
        INTERVALLE=FACT(
            statut="f",
            max="**",
            regles=(UN_PARMI("NOMBRE", "PAS"),),
            JUSQU_A=SIMP(statut="o", typ="I"),
            NOMBRE=SIMP(statut="f", typ="I", val_min=1),
            PAS=SIMP(statut="f", typ="I", val_min=1),
        ),
    ),
    b_extr=BLOC(
        condition=equal_to("OPERATION", "NUME_ORDRE"),
        fr="Order numbers of a result whose parameter lies in given intervals",
        RESULTAT=SIMP(statut="o", typ="resultat_sdaster"),
        PARAMETRE=SIMP(statut="o", typ="TXM"),
        INTERVALLE=FACT(
            statut="o",
            max="**",
            VALE=SIMP(statut="o", typ="R", min=2, max=2),
        ),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    TITRE=SIMP(statut="f", typ="TXM"),
)
