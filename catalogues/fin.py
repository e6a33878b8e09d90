"""FIN: end of the study."""

from asterlite.catalogues.common import OUI_NON

from asterlite.catalog import PROC, SIMP

FIN = PROC(
    nom="FIN",
    fr="End the study",
    RETASSAGE=SIMP(statut="f", typ="TXM", defaut="NON", into=OUI_NON),
    INFO_RESU=SIMP(statut="f", typ="TXM", defaut="NON", into=OUI_NON),
    PROC0=SIMP(statut="f", typ="TXM", defaut="OUI", into=OUI_NON),
    FORMAT_HDF=SIMP(statut="f", typ="TXM", into=OUI_NON),  # deprecated, ignored
)
