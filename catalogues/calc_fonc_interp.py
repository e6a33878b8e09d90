"""CALC_FONC_INTERP: tabulate a formula (or re-tabulate a function) on given abscissas."""

from asterlite.catalogues.common_post import INTERPOLATION, PROLONGEMENT, concept_is

from asterlite.catalog import BLOC, OPER, SIMP, UN_PARMI, exists


def calc_fonc_interp_type(kw) -> str:
    """Same kind as the input; a two-variable formula with NOM_PARA_FONC gives a nappe."""
    fonction = kw.get("FONCTION")
    if concept_is(fonction, "nappe_sdaster"):
        return "nappe_sdaster"
    if concept_is(fonction, "fonction_c", "formule_c"):
        return "fonction_c"
    if kw.get("NOM_PARA_FONC") is not None:
        return "nappe_sdaster"
    return "fonction_sdaster"


CALC_FONC_INTERP = OPER(
    nom="CALC_FONC_INTERP",
    sd_prod=calc_fonc_interp_type,
    reentrant="n",
    fr="Tabulate a formula of one or two variables as a function or a nappe",
    regles=(UN_PARMI("VALE_PARA", "LIST_PARA"),),
    FONCTION=SIMP(statut="o", typ=("formule", "fonction_sdaster", "nappe_sdaster", "fonction_c")),
    VALE_PARA=SIMP(statut="f", typ="R", max="**"),
    LIST_PARA=SIMP(statut="f", typ="listr8_sdaster"),
    NOM_RESU=SIMP(statut="f", typ="TXM"),
    NOM_PARA=SIMP(statut="f", typ="TXM"),
    INTERPOL=SIMP(statut="f", typ="TXM", max=2, into=INTERPOLATION),
    PROL_DROITE=SIMP(statut="f", typ="TXM", into=PROLONGEMENT),
    PROL_GAUCHE=SIMP(statut="f", typ="TXM", into=PROLONGEMENT),
    NOM_PARA_FONC=SIMP(statut="f", typ="TXM"),
    b_eval_nappe=BLOC(
        condition=exists("NOM_PARA_FONC"),
        regles=(UN_PARMI("VALE_PARA_FONC", "LIST_PARA_FONC"),),
        VALE_PARA_FONC=SIMP(statut="f", typ="R", max="**"),
        LIST_PARA_FONC=SIMP(statut="f", typ="listr8_sdaster"),
        INTERPOL_FONC=SIMP(statut="f", typ="TXM", max=2, into=INTERPOLATION),
        PROL_DROITE_FONC=SIMP(statut="f", typ="TXM", into=PROLONGEMENT),
        PROL_GAUCHE_FONC=SIMP(statut="f", typ="TXM", into=PROLONGEMENT),
    ),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
