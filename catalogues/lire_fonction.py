"""LIRE_FONCTION: read a function (or a nappe) from columns of a text file."""

from asterlite.catalogues.common_post import INTERPOLATION, PARA_FONCTION, PROLONGEMENT

from asterlite.catalog import BLOC, FACT, MACRO, SIMP, equal_to

_TYPES = {"FONCTION": "fonction_sdaster", "FONCTION_C": "fonction_c", "NAPPE": "nappe_sdaster"}


def lire_fonction_type(kw) -> str:
    return _TYPES.get(kw.get("TYPE"), "fonction_sdaster")


LIRE_FONCTION = MACRO(
    nom="LIRE_FONCTION",
    sd_prod=lire_fonction_type,
    reentrant="n",
    fr="Read a function or a nappe from a text file of columns",
    FORMAT=SIMP(statut="f", typ="TXM", defaut="LIBRE", into=("LIBRE", "NUMPY")),
    TYPE=SIMP(statut="f", typ="TXM", defaut="FONCTION", into=("FONCTION", "FONCTION_C", "NAPPE")),
    SEPARATEUR=SIMP(statut="f", typ="TXM", defaut="None"),
    INDIC_PARA=SIMP(statut="f", typ="I", min=2, max=2, defaut=(1, 1)),
    b_fonction=BLOC(
        condition=equal_to("TYPE", "FONCTION"),
        INDIC_RESU=SIMP(statut="f", typ="I", min=2, max=2, defaut=(1, 2)),
    ),
    b_fonction_c=BLOC(
        condition=equal_to("TYPE", "FONCTION_C"),
        FORMAT_C=SIMP(
            statut="f", typ="TXM", defaut="REEL_IMAG", into=("REEL_IMAG", "MODULE_PHASE")
        ),
        b_reel_imag=BLOC(
            condition=equal_to("FORMAT_C", "REEL_IMAG"),
            INDIC_REEL=SIMP(statut="f", typ="I", min=2, max=2, defaut=(1, 2)),
            INDIC_IMAG=SIMP(statut="f", typ="I", min=2, max=2, defaut=(1, 3)),
        ),
        b_modu_phas=BLOC(
            condition=equal_to("FORMAT_C", "MODULE_PHASE"),
            INDIC_MODU=SIMP(statut="f", typ="I", min=2, max=2, defaut=(1, 2)),
            INDIC_PHAS=SIMP(statut="f", typ="I", min=2, max=2, defaut=(1, 3)),
        ),
    ),
    b_nappe=BLOC(
        condition=equal_to("TYPE", "NAPPE"),
        NOM_PARA_FONC=SIMP(statut="o", typ="TXM", into=PARA_FONCTION),
        INDIC_ABSCISSE=SIMP(statut="o", typ="I", min=2, max=2),
        INTERPOL_FONC=SIMP(statut="f", typ="TXM", max=2, defaut="LIN", into=INTERPOLATION),
        PROL_DROITE_FONC=SIMP(statut="f", typ="TXM", defaut="EXCLU", into=PROLONGEMENT),
        PROL_GAUCHE_FONC=SIMP(statut="f", typ="TXM", defaut="EXCLU", into=PROLONGEMENT),
        DEFI_FONCTION=FACT(
            statut="f", max="**", INDIC_RESU=SIMP(statut="o", typ="I", min=2, max=2)
        ),
    ),
    UNITE=SIMP(statut="o", typ="I", fr="Logical unit of the file to read"),
    NOM_PARA=SIMP(statut="o", typ="TXM", into=PARA_FONCTION),
    NOM_RESU=SIMP(statut="f", typ="TXM", defaut="TOUTRESU"),
    INTERPOL=SIMP(statut="f", typ="TXM", max=2, defaut="LIN", into=INTERPOLATION),
    PROL_DROITE=SIMP(statut="f", typ="TXM", defaut="EXCLU", into=PROLONGEMENT),
    PROL_GAUCHE=SIMP(statut="f", typ="TXM", defaut="EXCLU", into=PROLONGEMENT),
    VERIF=SIMP(statut="f", typ="TXM", defaut="CROISSANT", into=("CROISSANT", "NON")),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    TITRE=SIMP(statut="f", typ="TXM"),
)
