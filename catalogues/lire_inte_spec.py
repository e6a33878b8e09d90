"""LIRE_INTE_SPEC: a spectral matrix read from a file of complex functions."""

from asterlite.catalogues.common_post import PARA_FONCTION

from asterlite.catalog import MACRO, SIMP

LIRE_INTE_SPEC = MACRO(
    nom="LIRE_INTE_SPEC",
    sd_prod="interspectre",
    reentrant="n",
    fr="Read a spectral matrix from a file of complex functions",
    UNITE=SIMP(statut="o", typ="I"),
    FORMAT_C=SIMP(statut="f", typ="TXM", defaut="MODULE_PHASE", into=("REEL_IMAG", "MODULE_PHASE")),
    FORMAT=SIMP(statut="f", typ="TXM", defaut="ASTER", into=("ASTER", "IDEAS")),
    NOM_PARA=SIMP(statut="f", typ="TXM", defaut="FREQ", into=PARA_FONCTION),
    NOM_RESU=SIMP(statut="f", typ="TXM", defaut="DSP"),
    INTERPOL=SIMP(statut="f", typ="TXM", max=2, into=("LIN", "LOG")),
    PROL_DROITE=SIMP(statut="f", typ="TXM", into=("CONSTANT", "LINEAIRE", "EXCLU")),
    PROL_GAUCHE=SIMP(statut="f", typ="TXM", into=("CONSTANT", "LINEAIRE", "EXCLU")),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
