"""DEFI_FONC_ELEC: the intensity in time of a Laplace force between two
conductors carrying short-circuit currents (the FONC_MULT of a FORCE_ELEC
load)."""

from asterlite.catalog import EXCLUS, FACT, MACRO, SIMP, UN_PARMI


def _current(index: int, mandatory: bool) -> dict:
    """INTE_CC_i, TAU_CC_i, PHI_CC_i / INTC_CC_i of conductor i."""
    statut = "o" if mandatory else "f"
    return {
        f"INTE_CC_{index}": SIMP(statut=statut, typ="R"),
        f"TAU_CC_{index}": SIMP(statut=statut, typ="R"),
        f"PHI_CC_{index}": SIMP(statut="f", typ="R"),
        f"INTC_CC_{index}": SIMP(statut="f", typ="R"),
    }


def _reclosing(index: int) -> dict:
    """INTE_RENC_i, TAU_RENC_i, PHI_RENC_i: the current after reclosing."""
    return {
        f"INTE_RENC_{index}": SIMP(statut="f", typ="R"),
        f"TAU_RENC_{index}": SIMP(statut="f", typ="R"),
        f"PHI_RENC_{index}": SIMP(statut="f", typ="R"),
    }


DEFI_FONC_ELEC = MACRO(
    nom="DEFI_FONC_ELEC",
    sd_prod="fonction_sdaster",
    reentrant="n",
    fr="Intensity in time of the Laplace force between two short-circuit currents",
    regles=(UN_PARMI("COUR_PRIN", "COUR"), EXCLUS("COUR", "COUR_SECO")),
    FREQ=SIMP(statut="f", typ="R", defaut=50.0),
    SIGNAL=SIMP(statut="f", typ="TXM", defaut="COMPLET", into=("COMPLET", "CONTINU")),
    COUR=FACT(
        statut="f",
        max="**",
        fr="One interval of short-circuit currents in the two conductors",
        regles=(UN_PARMI("PHI_CC_1", "INTC_CC_1"), UN_PARMI("PHI_CC_2", "INTC_CC_2")),
        **_current(1, True),
        **_current(2, True),
        INST_CC_INIT=SIMP(statut="o", typ="R"),
        INST_CC_FIN=SIMP(statut="o", typ="R"),
    ),
    COUR_PRIN=FACT(
        statut="f",
        fr="Current of the main conductor, with reclosing",
        regles=(UN_PARMI("PHI_CC_1", "INTC_CC_1"),),
        **_current(1, True),
        **_reclosing(1),
        INST_CC_INIT=SIMP(statut="o", typ="R"),
        INST_CC_FIN=SIMP(statut="o", typ="R"),
        INST_RENC_INIT=SIMP(statut="f", typ="R", defaut=0.0),
        INST_RENC_FIN=SIMP(statut="f", typ="R", defaut=0.0),
    ),
    COUR_SECO=FACT(
        statut="f",
        max="**",
        fr="Currents of secondary conductors over the interval of COUR_PRIN",
        regles=(UN_PARMI("PHI_CC_2", "INTC_CC_2"),),
        **_current(2, True),
        **_reclosing(2),
        DIST=SIMP(statut="f", typ="R", defaut=1.0),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
