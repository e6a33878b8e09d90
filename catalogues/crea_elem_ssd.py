"""CREA_ELEM_SSD: a dynamic macro-element in one command (matrices,
numbering, modes, interfaces, classical basis, MACR_ELEM_DYNA)."""

from asterlite.catalogues.common import C_SOLVEUR, noeud

from asterlite.catalog import BLOC, ENSEMBLE, FACT, MACRO, SIMP, UN_PARMI, equal_to
from asterlite.lang.values import CO


def _sdprod(kw) -> str:
    given = kw.get("NUME_DDL")
    if isinstance(given, CO):
        given.produced_type = "nume_ddl_sdaster"
    return "macr_elem_dyna"


CREA_ELEM_SSD = MACRO(
    nom="CREA_ELEM_SSD",
    sd_prod=_sdprod,
    reentrant="n",
    fr="Build a dynamic macro-element: CALC_MATR_ELEM, NUME_DDL, ASSE_MATRICE, CALC_MODES,"
    " DEFI_INTERF_DYNA, DEFI_BASE_MODALE and MACR_ELEM_DYNA in sequence",
    MODELE=SIMP(statut="o", typ="modele_sdaster"),
    CHAM_MATER=SIMP(statut="o", typ="cham_mater"),
    CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
    NUME_DDL=SIMP(statut="f", typ="CO"),
    CHARGE=SIMP(statut="f", typ=("char_meca", "char_ther", "char_acou"), max="**"),
    INTERFACE=FACT(
        statut="o",
        max="**",
        regles=(ENSEMBLE("NOM", "TYPE"), UN_PARMI("NOEUD", "GROUP_NO")),
        NOM=SIMP(statut="o", typ="TXM"),
        TYPE=SIMP(statut="o", typ="TXM", into=("MNEAL", "CRAIGB", "CB_HARMO")),
        NOEUD=noeud(),
        GROUP_NO=SIMP(statut="f", typ="grno", max="**"),
        FREQ=SIMP(statut="f", typ="R", defaut=1.0),
        MASQUE=SIMP(statut="f", typ="TXM", max="**"),
    ),
    BASE_MODALE=FACT(
        statut="o",
        max=1,
        TYPE=SIMP(statut="o", typ="TXM", into=("CLASSIQUE", "RITZ")),
        b_ritz=BLOC(
            condition=equal_to("TYPE", "RITZ"),
            TYPE_MODE=SIMP(
                statut="f", typ="TXM", into=("STATIQUE", "INTERFACE"), defaut="INTERFACE"
            ),
            b_intf=BLOC(
                condition=equal_to("TYPE_MODE", "INTERFACE"),
                NMAX_MODE_INTF=SIMP(statut="f", typ="I", defaut=10, val_min=1),
            ),
        ),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    SOLVEUR=C_SOLVEUR("CREA_ELEM_SSD"),
    CALC_FREQ=FACT(
        statut="d",
        STOP_ERREUR=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
        OPTION=SIMP(
            statut="f",
            typ="TXM",
            defaut="PLUS_PETITE",
            into=("PLUS_PETITE", "BANDE", "CENTRE", "SANS"),
        ),
        b_plus_petite=BLOC(
            condition=equal_to("OPTION", "PLUS_PETITE"),
            NMAX_FREQ=SIMP(statut="f", typ="I", defaut=10, val_min=0),
        ),
        b_centre=BLOC(
            condition=equal_to("OPTION", "CENTRE"),
            FREQ=SIMP(statut="o", typ="R"),
            AMOR_REDUIT=SIMP(statut="f", typ="R"),
            NMAX_FREQ=SIMP(statut="f", typ="I", defaut=10, val_min=0),
        ),
        b_bande=BLOC(
            condition=equal_to("OPTION", "BANDE"),
            NMAX_FREQ=SIMP(statut="f", typ="I", defaut=9999, val_min=0),
            FREQ=SIMP(statut="o", typ="R", min=2, max="**"),
        ),
        APPROCHE=SIMP(statut="f", typ="TXM", defaut="REEL", into=("REEL", "IMAG", "COMPLEXE")),
        DIM_SOUS_ESPACE=SIMP(statut="f", typ="I"),
    ),
)
