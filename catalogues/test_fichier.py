"""TEST_FICHIER: non-regression of a file a run wrote (its numbers and text)."""

from asterlite.catalogues.common_post import test_reference

from asterlite.catalog import PROC, SIMP

TEST_FICHIER = PROC(
    nom="TEST_FICHIER",
    fr="Count the reals of a file, check their sum (or extreme) and its text",
    FICHIER=SIMP(statut="o", typ="TXM"),
    EXPR_IGNORE=SIMP(statut="f", typ="TXM", max="**"),
    NB_VALE=SIMP(statut="o", typ="I"),
    NB_VALE_I=SIMP(statut="f", typ="I"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    **test_reference("FICHIER", max=1),
)
