"""DEFI_LIST_FREQ: a list of frequencies, refined around given resonances."""

from asterlite.catalog import BLOC, ENSEMBLE, EXCLUS, FACT, MACRO, SIMP, UN_PARMI, is_in

DEFI_LIST_FREQ = MACRO(
    nom="DEFI_LIST_FREQ",
    sd_prod="listr8_sdaster",
    reentrant="n",
    fr="Define a strictly increasing list of frequencies, refined around resonances",
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
        regles=(UN_PARMI("NOMBRE", "PAS"),),
        JUSQU_A=SIMP(statut="o", typ="R"),
        NOMBRE=SIMP(statut="f", typ="I"),
        PAS=SIMP(statut="f", typ="R"),
    ),
    RAFFINEMENT=FACT(
        statut="f",
        LIST_RAFFINE=SIMP(statut="o", typ="R", max="**"),
        NB_POINTS=SIMP(statut="f", typ="I", defaut=5),
        PAS_MINI=SIMP(statut="f", typ="R", defaut=0.001),
        CRITERE=SIMP(
            statut="f", typ="TXM", defaut="RELATIF", into=("RELATIF", "ABSOLU", "LARGEUR_3DB")
        ),
        b_crit_rela_abs=BLOC(
            condition=is_in("CRITERE", ("RELATIF", "ABSOLU")),
            DISPERSION=SIMP(statut="f", typ="R", defaut=0.01),
        ),
        b_crit_larg=BLOC(
            condition=is_in("CRITERE", ("LARGEUR_3DB",)),
            regles=(UN_PARMI("AMOR_REDUIT", "LIST_AMOR"),),
            AMOR_REDUIT=SIMP(statut="f", typ="R", max="**"),
            LIST_AMOR=SIMP(statut="f", typ="listr8_sdaster"),
        ),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    TITRE=SIMP(statut="f", typ="TXM"),
)
