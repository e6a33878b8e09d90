"""DEFI_CONSTANTE: a function with the same value everywhere."""

from asterlite.catalog import OPER, SIMP

DEFI_CONSTANTE = OPER(
    nom="DEFI_CONSTANTE",
    sd_prod="fonction_sdaster",
    reentrant="n",
    fr="Define a constant function",
    NOM_RESU=SIMP(statut="f", typ="TXM", defaut="TOUTRESU"),
    VALE=SIMP(statut="o", typ="R"),
    TITRE=SIMP(statut="f", typ="TXM"),
)
