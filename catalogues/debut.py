"""DEBUT: start a study (code_aster 17 keywords; most only tune the run)."""

from asterlite.catalogues.common import NO_EFFECT_DATABASE, NO_EFFECT_LOG, OUI_NON

from asterlite.catalog import EXCLUS, FACT, MACRO, SIMP


def starting_keywords(poursuite: bool = False) -> dict:
    """Keywords shared by DEBUT and POURSUITE."""
    return dict(
        IMPR_MACRO=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="NON", no_effect=NO_EFFECT_LOG),
        BASE=FACT(
            statut="f",
            no_effect=NO_EFFECT_DATABASE,
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
            no_effect="element catalogues of a code_aster build",
            min=1,
            max=10,
            FICHIER=SIMP(statut="o", typ="TXM"),
            UNITE=SIMP(statut="f", typ="I"),
        ),
        CODE=SIMP(
            statut="f",
            typ="TXM",
            into=OUI_NON,
            fr="Reserved for test cases",
            no_effect="test-case mode of code_aster's run (messages only)",
        ),
        ERREUR=FACT(
            statut="f",
            no_effect="asterlite stops at the first error whatever the mode",
            min=1,
            max=1,
            fr="Behaviour on errors and alarms",
            ERREUR_F=SIMP(statut="f", typ="TXM", into=("ABORT", "EXCEPTION")),
            ALARME=SIMP(statut="f", typ="TXM", into=("ALARME", "EXCEPTION")),
        ),
        DEBUG=FACT(
            statut="d",
            no_effect="code_aster's own developer checks",
            min=1,
            max=1,
            fr="Developer checks",
            JXVERI=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="NON"),
            SDVERI=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="NON"),
            JEVEUX=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="NON"),
            ENVIMA=SIMP(statut="f", typ="TXM", into=("TEST",)),
            VERI_BASE=SIMP(statut="f", typ="TXM", into=("GLOBALE", "VOLATILE")),
            VERI_BASE_NB=SIMP(statut="f", typ="I", defaut=125),
            HIST_ETAPE=SIMP(statut="f", typ="TXM", into=OUI_NON),
        ),
        MESURE_TEMPS=FACT(
            statut="d",
            no_effect=NO_EFFECT_LOG,
            min=1,
            max=1,
            fr="Timing of the main steps",
            NIVE_DETAIL=SIMP(statut="f", typ="I", into=(0, 1, 2, 3), defaut=1),
            MOYENNE=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="NON"),
        ),
        MEMOIRE=FACT(
            statut="d",
            no_effect=NO_EFFECT_DATABASE,
            min=1,
            max=1,
            TAILLE_BLOC=SIMP(statut="f", typ="R", defaut=800.0),
            TAILLE_GROUP_ELEM=SIMP(statut="f", typ="I", defaut=1000),
        ),
        RESERVE_CPU=FACT(
            statut="d",
            no_effect="time kept back by code_aster's batch runs",
            max=1,
            regles=(EXCLUS("VALE", "POURCENTAGE"),),
            VALE=SIMP(statut="f", typ="I", val_min=0),
            POURCENTAGE=SIMP(statut="f", typ="R", val_min=0.0, val_max=1.0),
        ),
        RESERVE_MEMOIRE=FACT(
            statut="d",
            no_effect=NO_EFFECT_DATABASE,
            max=1,
            regles=(EXCLUS("VALE", "POURCENTAGE"),),
            VALE=SIMP(statut="f", typ="I", val_min=0),
            POURCENTAGE=SIMP(statut="f", typ="R", val_min=0.0, val_max=1.0),
        ),
        IGNORE_ALARM=SIMP(
            statut="f", typ="TXM", max="**", fr="Alarms to ignore", no_effect=NO_EFFECT_LOG
        ),
        LANG=SIMP(statut="f", typ="TXM", no_effect=NO_EFFECT_LOG),
        INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
        # deprecated in code_aster 17 (removed by its compat_syntax)
        PAR_LOT=SIMP(statut="f", typ="TXM", into=OUI_NON, no_effect="deprecated by code_aster"),
        FORMAT_HDF=SIMP(statut="f", typ="TXM", into=OUI_NON, no_effect="deprecated by code_aster"),
    )


DEBUT = MACRO(
    nom="DEBUT",
    fr="Start a study: resources and error behaviour",
    MODE=SIMP(statut="f", typ="TXM", defaut="AUTO", into=("AUTO", "DEBUT", "POURSUITE")),
    **starting_keywords(),
)
