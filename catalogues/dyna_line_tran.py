"""DYNA_LINE_TRAN (code_aster 10 to 12): a linear transient response on the physical basis.

Legacy command: code_aster 11's own DYNA_VIBRA ran it with DYNA_VIBRA's keywords
(less TYPE_CALCUL and BASE_CALCUL), so asterlite runs it as that DYNA_VIBRA call
(its legacy form in asterlite.legacy.forms: asterlite.legacy.dyna_line_v11), checked by today's
DYNA_VIBRA catalogue. Its own keywords are those of code_aster 11's language
data (catalogues/language/v11.json), which ``asterlite check`` validates first.
"""

from asterlite.catalog import MACRO

DYNA_LINE_TRAN = MACRO(
    nom="DYNA_LINE_TRAN",
    extra_keywords=True,  # every keyword goes to DYNA_VIBRA, whose catalogue judges it
    fr="A linear transient response on the physical basis (legacy: DYNA_VIBRA)",
)
