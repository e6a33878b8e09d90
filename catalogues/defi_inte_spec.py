"""DEFI_INTE_SPEC: a spectral matrix from functions, Kanai-Tajimi or constant terms."""

from asterlite.catalog import BLOC, EXCLUS, FACT, OPER, SIMP, UN_PARMI, exists

PROLONGEMENT = ("CONSTANT", "LINEAIRE", "EXCLU")


def _term_keys():
    """The (i, j) designation of one term: order numbers or node/component pairs."""
    return dict(
        NUME_ORDRE_I=SIMP(statut="f", typ="I", max=1),
        NOEUD_I=SIMP(statut="f", typ="no", max=1),
        b_nume_ordre_i=BLOC(
            condition=exists("NUME_ORDRE_I"), NUME_ORDRE_J=SIMP(statut="o", typ="I", max=1)
        ),
        b_noeud_i=BLOC(
            condition=exists("NOEUD_I"),
            NOEUD_J=SIMP(statut="o", typ="no", max=1),
            NOM_CMP_I=SIMP(statut="o", typ="TXM", max=1),
            NOM_CMP_J=SIMP(statut="o", typ="TXM", max=1),
        ),
    )


def _analytic(**extra):
    return FACT(
        statut="f",
        max="**",
        regles=(EXCLUS("VALE_R", "VALE_C"), UN_PARMI("NUME_ORDRE_I", "NOEUD_I")),
        **_term_keys(),
        FREQ_MIN=SIMP(statut="f", typ="R", defaut=0.0),
        FREQ_MAX=SIMP(statut="f", typ="R", defaut=100.0),
        PAS=SIMP(statut="f", typ="R", defaut=1.0),
        **extra,
        VALE_R=SIMP(statut="f", typ="R"),
        VALE_C=SIMP(statut="f", typ="C"),
        INTERPOL=SIMP(statut="f", typ="TXM", max=2, defaut="LIN", into=("LIN", "LOG")),
        PROL_DROITE=SIMP(statut="f", typ="TXM", defaut="EXCLU", into=PROLONGEMENT),
        PROL_GAUCHE=SIMP(statut="f", typ="TXM", defaut="EXCLU", into=PROLONGEMENT),
    )


DEFI_INTE_SPEC = OPER(
    nom="DEFI_INTE_SPEC",
    sd_prod="interspectre",
    reentrant="n",
    fr="Define a spectral matrix",
    regles=(UN_PARMI("PAR_FONCTION", "KANAI_TAJIMI", "CONSTANT"),),
    DIMENSION=SIMP(statut="f", typ="I", defaut=1),
    PAR_FONCTION=FACT(
        statut="f",
        max="**",
        regles=(UN_PARMI("NUME_ORDRE_I", "NOEUD_I"),),
        **_term_keys(),
        FONCTION=SIMP(statut="o", typ=("fonction_sdaster", "fonction_c"), max=1),
    ),
    KANAI_TAJIMI=_analytic(
        AMOR_REDUIT=SIMP(statut="f", typ="R", defaut=0.6),
        FREQ_MOY=SIMP(statut="f", typ="R", defaut=5.0),
    ),
    CONSTANT=_analytic(),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
