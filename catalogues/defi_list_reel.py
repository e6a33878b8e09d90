"""DEFI_LIST_REEL: a strictly increasing list of reals (instants, frequencies...)."""

from asterlite.catalog import ENSEMBLE, EXCLUS, FACT, OPER, SIMP, UN_PARMI

DEFI_LIST_REEL = OPER(
    nom="DEFI_LIST_REEL",
    sd_prod="listr8_sdaster",
    reentrant="n",
    fr="Define a strictly increasing list of reals",
    regles=(
        UN_PARMI("VALE", "DEBUT"),
        EXCLUS("VALE", "INTERVALLE"),
        ENSEMBLE("DEBUT", "INTERVALLE"),
    ),
    VALE=SIMP(statut="f", typ="R", max="**"),
    DEBUT=SIMP(statut="f", typ="R"),
    INTERVALLE=FACT(
        statut="f",
        max="**",
        fr="Interval up to JUSQU_A, cut by a step PAS or a number of steps NOMBRE",
        regles=(UN_PARMI("NOMBRE", "PAS"),),
        JUSQU_A=SIMP(statut="o", typ="R"),
        NOMBRE=SIMP(statut="f", typ="I"),
        PAS=SIMP(statut="f", typ="R"),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    TITRE=SIMP(statut="f", typ="TXM"),
)
