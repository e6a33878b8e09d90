"""DETRUIRE: remove concepts from the deck namespace."""

from asterlite.catalogues.common import ANY_CONCEPT

from asterlite.catalog import MACRO, SIMP

DETRUIRE = MACRO(
    nom="DETRUIRE",
    sd_prod=None,
    fr="Delete concepts",
    NOM=SIMP(statut="o", typ=ANY_CONCEPT, max="**"),
    INFO=SIMP(statut="f", typ="I", into=(1, 2), defaut=1),
)
