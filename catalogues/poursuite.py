"""POURSUITE: continue a study saved by a previous run."""

from asterlite.catalogues.debut import starting_keywords

from asterlite.catalog import MACRO

POURSUITE = MACRO(
    nom="POURSUITE",
    fr="Continue a study from its saved database",
    **starting_keywords(poursuite=True),
)
