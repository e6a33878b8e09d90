"""DEBUT: start a study (code_aster 17 keywords; most only tune the run)."""

from asterlite.catalogues.common import OUI_NON

from asterlite.catalog import EXCLUS, FACT, MACRO, SIMP
from asterlite.legacy import forms


def starting_keywords(poursuite: bool = False) -> dict:
    """Keywords shared by DEBUT and POURSUITE."""
    return dict(
        IMPR_MACRO=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="NON"),
        BASE=FACT(
            statut="f",
            min=1,
            max=2,
            fr="Parameters of the JEVEUX databases",
            FICHIER=SIMP(
                statut="o",
                typ="TXM",
                into=None if poursuite else ("GLOBALE", "VOLATILE"),
            ),
            TITRE=SIMP(statut="f", typ="TXM"),
            CAS=SIMP(statut="f", typ="TXM"),
            NMAX_ENRE=SIMP(statut="f", typ="I"),
            LONG_ENRE=SIMP(statut="f", typ="I"),
            LONG_REPE=SIMP(statut="f", typ="I"),
        ),
        CATALOGUE=FACT(
            statut="f",
            min=1,
            max=10,
            FICHIER=SIMP(statut="o", typ="TXM"),
            UNITE=SIMP(statut="f", typ="I"),
        ),
        CODE=SIMP(statut="f", typ="TXM", into=OUI_NON, fr="Reserved for test cases"),
        ERREUR=FACT(
            statut="f",
            min=1,
            max=1,
            fr="Behaviour on errors and alarms",
            ERREUR_F=SIMP(statut="f", typ="TXM", into=("ABORT", "EXCEPTION")),
            ALARME=SIMP(statut="f", typ="TXM", into=("ALARME", "EXCEPTION")),
        ),
        DEBUG=FACT(
            statut="d",
            min=1,
            max=1,
            fr="Developer checks",
            JXVERI=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="NON"),
            SDVERI=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="NON"),
            JEVEUX=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="NON"),
            ENVIMA=SIMP(statut="f", typ="TXM", into=("TEST",)),
            VERI_BASE=SIMP(statut="f", typ="TXM", into=("GLOBALE", "VOLATILE")),
            VERI_BASE_NB=SIMP(statut="f", typ="I", defaut=125),
            HIST_ETAPE=SIMP(statut="f", typ="TXM", into=OUI_NON),  # deprecated, ignored
        ),
        MESURE_TEMPS=FACT(
            statut="d",
            min=1,
            max=1,
            fr="Timing of the main steps",
            NIVE_DETAIL=SIMP(statut="f", typ="I", into=(0, 1, 2, 3), defaut=1),
            MOYENNE=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="NON"),
        ),
        MEMOIRE=FACT(
            statut="d",
            min=1,
            max=1,
            TAILLE_BLOC=SIMP(statut="f", typ="R", defaut=800.0),
            TAILLE_GROUP_ELEM=SIMP(statut="f", typ="I", defaut=1000),
        ),
        RESERVE_CPU=FACT(
            statut="d",
            max=1,
            regles=(EXCLUS("VALE", "POURCENTAGE"),),
            VALE=SIMP(statut="f", typ="I", val_min=0),
            POURCENTAGE=SIMP(statut="f", typ="R", val_min=0.0, val_max=1.0),
        ),
        RESERVE_MEMOIRE=FACT(
            statut="d",
            max=1,
            regles=(EXCLUS("VALE", "POURCENTAGE"),),
            VALE=SIMP(statut="f", typ="I", val_min=0),
            POURCENTAGE=SIMP(statut="f", typ="R", val_min=0.0, val_max=1.0),
        ),
        IGNORE_ALARM=SIMP(statut="f", typ="TXM", max="**", fr="Alarms to ignore"),
        LANG=SIMP(statut="f", typ="TXM"),
        INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
        # deprecated in code_aster 17 (removed by its compat_syntax), accepted and ignored
        PAR_LOT=SIMP(statut="f", typ="TXM", into=OUI_NON),
        FORMAT_HDF=SIMP(statut="f", typ="TXM", into=OUI_NON),
    )


DEBUT = MACRO(
    nom="DEBUT",
    compat_syntax=forms.START,  # CODE=_F(NOM=...) of older versions
    fr="Start a study: resources and error behaviour",
    MODE=SIMP(statut="f", typ="TXM", defaut="AUTO", into=("AUTO", "DEBUT", "POURSUITE")),
    **starting_keywords(),
)
