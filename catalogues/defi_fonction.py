"""DEFI_FONCTION: a real (or complex) function of one variable given by its points."""

from asterlite.catalogues.common_post import INTERPOLATION, PARA_FONCTION, PROLONGEMENT

from asterlite.catalog import BLOC, OPER, SIMP, UN_PARMI, exists


def defi_fonction_type(kw) -> str:
    """fonction_c for VALE_C, fonction_sdaster otherwise."""
    return "fonction_c" if kw.get("VALE_C") is not None else "fonction_sdaster"


DEFI_FONCTION = OPER(
    nom="DEFI_FONCTION",
    sd_prod=defi_fonction_type,
    reentrant="n",
    fr="Define a real or complex function of one real variable",
    regles=(UN_PARMI("VALE", "VALE_C", "VALE_PARA", "NOEUD_PARA", "ABSCISSE"),),
    NOM_PARA=SIMP(statut="o", typ="TXM", into=PARA_FONCTION),
    NOM_RESU=SIMP(statut="f", typ="TXM", defaut="TOUTRESU"),
    VALE=SIMP(statut="f", typ="R", min=2, max="**", fr="(abscissa, ordinate) pairs, flattened"),
    ABSCISSE=SIMP(statut="f", typ="R", min=2, max="**", fr="Abscissas"),
    b_abscisse=BLOC(
        condition=exists("ABSCISSE"),
        ORDONNEE=SIMP(statut="o", typ="R", min=2, max="**", fr="Ordinates"),
    ),
    VALE_C=SIMP(
        statut="f", typ="R", min=2, max="**", fr="(abscissa, real, imaginary) triplets, flattened"
    ),
    VALE_PARA=SIMP(statut="f", typ="listr8_sdaster", fr="Abscissas as a list of reals"),
    b_vale_para=BLOC(
        condition=exists("VALE_PARA"),
        VALE_FONC=SIMP(statut="o", typ="listr8_sdaster", fr="Ordinates as a list of reals"),
    ),
    NOEUD_PARA=SIMP(statut="f", typ="no", max="**", fr="Nodes whose abscissas are the parameter"),
    b_noeud_para=BLOC(
        condition=exists("NOEUD_PARA"),
        MAILLAGE=SIMP(statut="o", typ="maillage_sdaster"),
        VALE_Y=SIMP(statut="o", typ="R", max="**"),
    ),
    INTERPOL=SIMP(statut="f", typ="TXM", max=2, defaut="LIN", into=INTERPOLATION),
    PROL_DROITE=SIMP(statut="f", typ="TXM", defaut="EXCLU", into=PROLONGEMENT),
    PROL_GAUCHE=SIMP(statut="f", typ="TXM", defaut="EXCLU", into=PROLONGEMENT),
    VERIF=SIMP(statut="f", typ="TXM", defaut="CROISSANT", into=("CROISSANT", "NON")),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    TITRE=SIMP(statut="f", typ="TXM"),
)
