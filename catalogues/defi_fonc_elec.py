"""DEFI_FONC_ELEC: the intensity in time of a Laplace force between two
conductors carrying short-circuit currents (the FONC_MULT of a FORCE_ELEC
load).

Not here, so refused by ``check`` and ``run`` alike: ``COUR_PRIN`` with
``COUR_SECO`` (code_aster 17's macro-command ends in an IndexError for any
input of that form: its list of values holds one value for every instant it
lists) and ``INTC_CC_1``/``INTC_CC_2`` (it computes the currents with
``PHI_CC_*`` only, and fails without them)."""

from asterlite.catalog import FACT, MACRO, SIMP


def _current(index: int) -> dict:
    """INTE_CC_i (RMS), TAU_CC_i (time constant of the offset), PHI_CC_i
    (phase at the start, degrees) of conductor i."""
    return {
        f"INTE_CC_{index}": SIMP(statut="o", typ="R"),
        f"TAU_CC_{index}": SIMP(statut="o", typ="R"),
        f"PHI_CC_{index}": SIMP(statut="o", typ="R"),
    }


DEFI_FONC_ELEC = MACRO(
    nom="DEFI_FONC_ELEC",
    sd_prod="fonction_sdaster",
    reentrant="n",
    fr="Intensity in time of the Laplace force between two short-circuit currents",
    FREQ=SIMP(statut="f", typ="R", defaut=50.0),
    SIGNAL=SIMP(statut="f", typ="TXM", defaut="COMPLET", into=("COMPLET", "CONTINU")),
    COUR=FACT(
        statut="o",
        max="**",
        fr="One interval of short-circuit currents in the two conductors",
        **_current(1),
        **_current(2),
        INST_CC_INIT=SIMP(statut="o", typ="R"),
        INST_CC_FIN=SIMP(statut="o", typ="R"),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
