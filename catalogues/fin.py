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
    # arguments of code_aster's FIN wrapper (CA.close), taken before its syntax
    # is checked (the language data's "supervisor"): exit=True leaves Python
    # after FIN, as asterlite's FIN always does (it ends the deck); atexit
    # only says how the database is closed
    exit=SIMP(statut="f", typ="L", no_effect="asterlite's FIN always ends the deck"),
    atexit=SIMP(statut="f", typ="L", no_effect=NO_EFFECT_DATABASE),
)
