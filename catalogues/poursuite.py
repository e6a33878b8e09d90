"""POURSUITE: continue a study saved by a previous run."""

from asterlite.catalogues.debut import starting_keywords

from asterlite.catalog import MACRO
from asterlite.legacy import forms

POURSUITE = MACRO(
    nom="POURSUITE",
    compat_syntax=forms.START,  # CODE=_F(NOM=...) of older versions
    fr="Continue a study from its saved database",
    **starting_keywords(poursuite=True),
)
