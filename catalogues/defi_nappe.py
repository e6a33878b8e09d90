"""DEFI_NAPPE: a function of two parameters, one function of NOM_PARA_FONC
per value of NOM_PARA (PARA), given as functions or as value lists."""

from asterlite.catalogues.common_post import INTERPOLATION, PARA_FONCTION, PROLONGEMENT

from asterlite.catalog import ENSEMBLE, EXCLUS, FACT, OPER, SIMP, UN_PARMI

DEFI_NAPPE = OPER(
    nom="DEFI_NAPPE",
    sd_prod="nappe_sdaster",
    reentrant="n",
    fr="A real function of two real parameters",
    regles=(
        UN_PARMI("FONCTION", "DEFI_FONCTION"),
        EXCLUS("FONCTION", "NOM_PARA_FONC"),
        ENSEMBLE("NOM_PARA_FONC", "DEFI_FONCTION"),
    ),
    NOM_PARA=SIMP(statut="o", typ="TXM", into=PARA_FONCTION),
    NOM_RESU=SIMP(statut="f", typ="TXM", defaut="TOUTRESU"),
    PARA=SIMP(statut="o", typ="R", max="**"),
    FONCTION=SIMP(statut="f", typ="fonction_sdaster", max="**"),
    NOM_PARA_FONC=SIMP(statut="f", typ="TXM", into=PARA_FONCTION),
    DEFI_FONCTION=FACT(
        statut="f",
        max="**",
        VALE=SIMP(statut="o", typ="R", max="**"),
        INTERPOL=SIMP(statut="f", typ="TXM", max=2, defaut="LIN", into=INTERPOLATION),
        PROL_DROITE=SIMP(statut="f", typ="TXM", defaut="EXCLU", into=PROLONGEMENT),
        PROL_GAUCHE=SIMP(statut="f", typ="TXM", defaut="EXCLU", into=PROLONGEMENT),
    ),
    INTERPOL=SIMP(statut="f", typ="TXM", max=2, defaut="LIN", into=INTERPOLATION),
    PROL_DROITE=SIMP(statut="f", typ="TXM", defaut="EXCLU", into=PROLONGEMENT),
    PROL_GAUCHE=SIMP(statut="f", typ="TXM", defaut="EXCLU", into=PROLONGEMENT),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    VERIF=SIMP(statut="f", typ="TXM", into=("CROISSANT",)),
    TITRE=SIMP(statut="f", typ="TXM"),
)
