"""DEBUG: development switches of code_aster (data-structure checks, logs).

asterlite accepts them for compatibility; they do not change results.
"""

from asterlite.catalog import PROC, SIMP

DEBUG = PROC(
    nom="DEBUG",
    fr="Switch code_aster's debugging aids (no effect on results)",
    SDVERI=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
    JEVEUX=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
    JXVERI=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
    IMPR_MACRO=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
)
