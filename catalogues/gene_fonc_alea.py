"""GENE_FONC_ALEA: random time signals drawn from a spectral matrix."""

from asterlite.catalog import BLOC, OPER, SIMP, equal_to

GENE_FONC_ALEA = OPER(
    nom="GENE_FONC_ALEA",
    sd_prod="interspectre",
    reentrant="n",
    fr="Generate time signals from a spectral matrix",
    INTE_SPEC=SIMP(statut="o", typ="interspectre"),
    NUME_VITE_FLUI=SIMP(statut="f", typ="I"),
    INTERPOL=SIMP(statut="f", typ="TXM", defaut="OUI", into=("NON", "OUI")),
    b_interpol_oui=BLOC(
        condition=equal_to("INTERPOL", "OUI"),
        DUREE_TIRAGE=SIMP(statut="f", typ="R"),
        FREQ_INIT=SIMP(statut="f", typ="R"),
        FREQ_FIN=SIMP(statut="f", typ="R"),
    ),
    NB_POIN=SIMP(statut="f", typ="I"),
    NB_TIRAGE=SIMP(statut="f", typ="I", defaut=1),
    INIT_ALEA=SIMP(statut="f", typ="I"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    TITRE=SIMP(statut="f", typ="TXM"),
)
