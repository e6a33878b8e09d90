"""LIRE_MAILLAGE: read a mesh file (ASTER or MED format)."""

from asterlite.catalogues.common import OUI_NON

from asterlite.catalog import BLOC, FACT, OPER, SIMP, equal_to

LIRE_MAILLAGE = OPER(
    nom="LIRE_MAILLAGE",
    sd_prod="maillage_sdaster",
    reentrant="n",
    fr="Read a mesh from a file",
    FORMAT=SIMP(
        statut="f", typ="TXM", defaut="MED", into=("ASTER", "GIBI", "GMSH", "IDEAS", "MED")
    ),
    VERI_MAIL=FACT(
        statut="d",
        VERIF=SIMP(statut="f", typ="TXM", defaut="OUI", into=OUI_NON),
        APLAT=SIMP(statut="f", typ="R", defaut=1.0e-3),
    ),
    b_format_autre=BLOC(
        condition=~equal_to("FORMAT", "MED"),
        UNITE=SIMP(statut="f", typ="I", defaut=20),
    ),
    b_format_med=BLOC(
        condition=equal_to("FORMAT", "MED"),
        UNITE=SIMP(statut="f", typ="I", defaut=20),
        NOM_MED=SIMP(statut="f", typ="TXM", fr="Mesh name in the MED file"),
        INFO_MED=SIMP(statut="f", typ="I", defaut=1, into=(0, 1, 2, 3)),
        PARTITIONNEUR=SIMP(statut="f", typ="TXM", defaut="SANS", into=("SANS", "PTSCOTCH")),
    ),
    b_format_ideas=BLOC(
        condition=equal_to("FORMAT", "IDEAS"),
        CREA_GROUP_COUL=SIMP(statut="f", typ="TXM", defaut="NON", into=OUI_NON),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(0, 1, 2)),
)
