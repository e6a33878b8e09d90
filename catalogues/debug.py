"""DEBUG: development switches of code_aster (data-structure checks, logs).

They switch code_aster's own checks and traces: none changes a result.
"""

from asterlite.catalog import PROC, SIMP

_DEBUG_AID = "code_aster's debugging aids"

DEBUG = PROC(
    nom="DEBUG",
    fr="Switch code_aster's debugging aids (no effect on results)",
    SDVERI=SIMP(statut="f", typ="TXM", into=("OUI", "NON"), no_effect=_DEBUG_AID),
    JEVEUX=SIMP(statut="f", typ="TXM", into=("OUI", "NON"), no_effect=_DEBUG_AID),
    JXVERI=SIMP(statut="f", typ="TXM", into=("OUI", "NON"), no_effect=_DEBUG_AID),
    IMPR_MACRO=SIMP(statut="f", typ="TXM", into=("OUI", "NON"), no_effect=_DEBUG_AID),
)
