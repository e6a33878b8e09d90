"""FIN: end of the study."""

from asterlite.catalogues.common import NO_EFFECT_DATABASE, NO_EFFECT_LOG, OUI_NON

from asterlite.catalog import PROC, SIMP

FIN = PROC(
    nom="FIN",
    fr="End the study",
    RETASSAGE=SIMP(statut="f", typ="TXM", defaut="NON", into=OUI_NON, no_effect=NO_EFFECT_DATABASE),
    INFO_RESU=SIMP(statut="f", typ="TXM", defaut="NON", into=OUI_NON, no_effect=NO_EFFECT_LOG),
    PROC0=SIMP(statut="f", typ="TXM", defaut="OUI", into=OUI_NON, no_effect=NO_EFFECT_DATABASE),
    FORMAT_HDF=SIMP(statut="f", typ="TXM", into=OUI_NON, no_effect="deprecated by code_aster"),
)
