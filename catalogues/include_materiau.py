"""INCLUDE_MATERIAU: a material from a material data file (code_aster's
catalogue of materials, NOM_AFNOR..., or a file of the study, FICHIER)."""

from asterlite.catalog import ENSEMBLE, FACT, MACRO, SIMP, UN_PARMI

INCLUDE_MATERIAU = MACRO(
    nom="INCLUDE_MATERIAU",
    sd_prod="mater_sdaster",
    reentrant="n",
    fr="Read a material from a material data file",
    regles=(
        UN_PARMI("NOM_AFNOR", "FICHIER"),
        ENSEMBLE("NOM_AFNOR", "TYPE_MODELE", "VARIANTE", "TYPE_VALE"),
    ),
    NOM_AFNOR=SIMP(statut="f", typ="TXM"),
    TYPE_MODELE=SIMP(statut="f", typ="TXM", into=("REF", "PAR")),
    VARIANTE=SIMP(statut="f", typ="TXM", into=tuple("ABCDEFGHIJKLMNOPQRSTUVWXYZ")),
    TYPE_VALE=SIMP(statut="f", typ="TXM", into=("NOMI", "MINI", "MAXI")),
    FICHIER=SIMP(statut="f", typ="TXM", fr="Name of the data file (given in the export)"),
    EXTRACTION=FACT(
        statut="f",
        COMPOR=SIMP(statut="o", typ="TXM", max="**"),
        TEMP_EVAL=SIMP(statut="o", typ="R"),
    ),
    UNITE_LONGUEUR=SIMP(statut="f", typ="TXM", into=("M", "MM"), defaut="M"),
    COEF_MULT=SIMP(statut="c", typ="R", defaut=1.0),
    PROL_DROITE=SIMP(statut="f", typ="TXM", defaut="EXCLU", into=("CONSTANT", "LINEAIRE", "EXCLU")),
    PROL_GAUCHE=SIMP(statut="f", typ="TXM", defaut="EXCLU", into=("CONSTANT", "LINEAIRE", "EXCLU")),
    OPTION=SIMP(statut="c", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
