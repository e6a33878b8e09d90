"""NUME_DDL_GENE: numbering of generalised coordinates."""

from asterlite.catalog import BLOC, OPER, SIMP, UN_PARMI, exists

NUME_DDL_GENE = OPER(
    nom="NUME_DDL_GENE",
    sd_prod="nume_ddl_gene",
    reentrant="n",
    fr="Number the generalised degrees of freedom",
    regles=(UN_PARMI("MODELE_GENE", "BASE"),),
    MODELE_GENE=SIMP(statut="f", typ="modele_gene"),
    b_modele_gene=BLOC(
        condition=exists("MODELE_GENE"),
        STOCKAGE=SIMP(statut="f", typ="TXM", defaut="LIGN_CIEL", into=("LIGN_CIEL", "PLEIN")),
        METHODE=SIMP(
            statut="f", typ="TXM", defaut="CLASSIQUE", into=("INITIAL", "CLASSIQUE", "ELIMINE")
        ),
    ),
    BASE=SIMP(statut="f", typ=("mode_meca", "mode_gene")),
    b_base=BLOC(
        condition=exists("BASE"),
        STOCKAGE=SIMP(statut="f", typ="TXM", defaut="PLEIN", into=("DIAG", "PLEIN")),
        NB_VECT=SIMP(statut="f", typ="I"),
    ),
)
