"""EXTR_MODE: select modes from one or several modal results."""

from asterlite.catalogues.common import NO_EFFECT_LOG

from asterlite.catalog import AU_MOINS_UN, BLOC, FACT, OPER, SIMP, UN_PARMI, exists

MODE_TYPES = ("mode_meca", "mode_meca_c", "mode_gene")
CRIT_EXTR = ("MASS_EFFE_UN", "MASS_GENE", "MASS_EFFE")


def _sdprod(kw) -> str:
    filters = kw.get("FILTRE_MODE") or ()
    mode = filters[0].get("MODE") if filters else None
    for name in ("mode_meca_c", "mode_gene"):
        if getattr(mode, "satisfies", lambda _t: False)(name):
            return name
    return "mode_meca"


EXTR_MODE = OPER(
    nom="EXTR_MODE",
    sd_prod=_sdprod,
    reentrant="n",
    fr="Extract selected modes from modal results",
    FILTRE_MODE=FACT(
        statut="o",
        max="**",
        regles=(
            UN_PARMI(
                "TOUT_ORDRE", "NUME_ORDRE", "NUME_MODE", "NUME_MODE_EXCLU", "FREQ_MIN", "CRIT_EXTR"
            ),
        ),
        MODE=SIMP(statut="o", typ=MODE_TYPES),
        TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
        NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
        NUME_MODE=SIMP(statut="f", typ="I", max="**"),
        NUME_MODE_EXCLU=SIMP(statut="f", typ="I", max="**"),
        FREQ_MIN=SIMP(statut="f", typ="R"),
        CRIT_EXTR=SIMP(statut="f", typ="TXM", into=CRIT_EXTR),
        b_freq_min=BLOC(
            condition=exists("FREQ_MIN"),
            FREQ_MAX=SIMP(statut="o", typ="R"),
            PRECISION=SIMP(statut="f", typ="R", defaut=1.0e-3),
        ),
        b_crit_extr=BLOC(
            condition=exists("CRIT_EXTR"),
            regles=(AU_MOINS_UN("SEUIL", "SEUIL_X", "SEUIL_Y", "SEUIL_Z"),),
            SEUIL=SIMP(statut="f", typ="R"),
            SEUIL_X=SIMP(statut="f", typ="R"),
            SEUIL_Y=SIMP(statut="f", typ="R"),
            SEUIL_Z=SIMP(statut="f", typ="R"),
        ),
    ),
    TITRE=SIMP(statut="f", typ="TXM"),
    IMPRESSION=FACT(
        statut="f",
        no_effect=NO_EFFECT_LOG,
        CUMUL=SIMP(statut="f", typ="TXM", defaut="NON", into=("OUI", "NON")),
        CRIT_EXTR=SIMP(statut="f", typ="TXM", defaut="MASS_EFFE_UN", into=CRIT_EXTR),
    ),
)
