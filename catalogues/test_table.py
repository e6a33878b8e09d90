"""TEST_TABLE: check a cell (or a column summary) of a table against a reference."""

from asterlite.catalogues.common_post import TABLE, table_filter, test_reference

from asterlite.catalog import PROC, SIMP

TEST_TABLE = PROC(
    nom="TEST_TABLE",
    fr="Check a cell or a column of a table",
    TABLE=SIMP(statut="o", typ=TABLE),
    FILTRE=table_filter(crit_always=True),
    NOM_PARA=SIMP(statut="o", typ="TXM", fr="Column holding the tested value"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    **test_reference("TABLE"),
)
