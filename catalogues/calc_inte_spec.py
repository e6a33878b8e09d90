"""CALC_INTE_SPEC: the spectral matrix of time functions (averaged periodograms)."""

from asterlite.catalog import OPER, SIMP

CALC_INTE_SPEC = OPER(
    nom="CALC_INTE_SPEC",
    sd_prod="interspectre",
    reentrant="n",
    fr="Spectral matrix of time functions",
    INST_INIT=SIMP(statut="f", typ="R", defaut=0.0),
    INST_FIN=SIMP(statut="o", typ="R"),
    DUREE_ANALYSE=SIMP(statut="f", typ="R"),
    DUREE_DECALAGE=SIMP(statut="f", typ="R"),
    NB_POIN=SIMP(statut="o", typ="I"),
    FONCTION=SIMP(statut="o", typ=("fonction_sdaster", "nappe_sdaster", "formule"), max="**"),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
