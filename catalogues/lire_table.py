"""LIRE_TABLE: a table read from a text file (code_aster 17's catalogue)."""

from asterlite.catalog import MACRO, SIMP

LIRE_TABLE = MACRO(
    nom="LIRE_TABLE",
    sd_prod="table_sdaster",
    reentrant="n",
    fr="Read a table from a text file",
    UNITE=SIMP(statut="o", typ="I", fr="Logical unit of the file to read"),
    FORMAT=SIMP(statut="f", typ="TXM", into=("ASTER", "LIBRE", "TABLEAU"), defaut="TABLEAU"),
    NUME_TABLE=SIMP(statut="f", typ="I", defaut=1),
    SEPARATEUR=SIMP(statut="f", typ="TXM", defaut=" "),
    RENOMME_PARA=SIMP(statut="f", typ="TXM", into=("UNIQUE",)),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", into=(1, 2)),
)
