"""PROJ_MESU_MODAL: generalized coordinates of measured data on a modal basis
(least squares, optionally regularised), see asterlite.modal.measured_projection."""

from asterlite.catalog import BLOC, FACT, OPER, PRESENT_ABSENT, PRESENT_PRESENT, SIMP, equal_to

FONCTION = ("fonction_sdaster", "nappe_sdaster", "formule")
MEASURED = ("dyna_trans", "dyna_harmo", "mode_meca", "mode_meca_c")
_PRODUCT = {
    "dyna_trans": "tran_gene",
    "dyna_harmo": "harm_gene",
    "mode_meca_c": "mode_gene",
    "mode_meca": "mode_gene",
}


def _sdprod(kw) -> str:
    """tran_gene, harm_gene or mode_gene after the measured result's type."""
    occurrences = kw.get("MODELE_MESURE") or ()
    measured = occurrences[0].get("MESURE") if occurrences else None
    for name, product in _PRODUCT.items():
        if getattr(measured, "satisfies", lambda _t: False)(name):
            return product
    return "mode_gene"


PROJ_MESU_MODAL = OPER(
    nom="PROJ_MESU_MODAL",
    sd_prod=_sdprod,
    reentrant="n",
    fr="Generalized coordinates of measured data on a projection basis",
    MODELE_CALCUL=FACT(
        statut="o",
        MODELE=SIMP(statut="o", typ="modele_sdaster"),
        BASE=SIMP(statut="o", typ="mode_meca"),
    ),
    MODELE_MESURE=FACT(
        statut="o",
        MODELE=SIMP(statut="o", typ="modele_sdaster"),
        MESURE=SIMP(statut="o", typ=MEASURED),
        NOM_CHAM=SIMP(
            statut="f",
            typ="TXM",
            defaut="DEPL",
            into=("DEPL", "VITE", "ACCE", "SIEF_NOEU", "EPSI_NOEU"),
            max="**",
        ),
    ),
    CORR_MANU=FACT(
        statut="f",
        max="**",
        regles=(PRESENT_PRESENT("NOEU_CALCUL", "NOEU_MESURE"),),
        NOEU_CALCUL=SIMP(statut="f", typ="no"),
        NOEU_MESURE=SIMP(statut="f", typ="no"),
    ),
    NOM_PARA=SIMP(statut="f", typ="TXM", max="**"),
    RESOLUTION=FACT(
        statut="f",
        METHODE=SIMP(statut="f", typ="TXM", defaut="LU", into=("LU", "SVD")),
        b_svd=BLOC(condition=equal_to("METHODE", "SVD"), EPS=SIMP(statut="f", typ="R", defaut=0.0)),
        REGUL=SIMP(statut="f", typ="TXM", defaut="NON", into=("NON", "NORM_MIN", "TIK_RELA")),
        b_regul=BLOC(
            condition=equal_to("REGUL", ("NORM_MIN", "TIK_RELA")),
            regles=(PRESENT_ABSENT("COEF_PONDER", "COEF_PONDER_F"),),
            COEF_PONDER=SIMP(statut="f", typ="R", max="**"),
            COEF_PONDER_F=SIMP(statut="f", typ=FONCTION, max="**"),
        ),
    ),
)
