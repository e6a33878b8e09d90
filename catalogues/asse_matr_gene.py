"""ASSE_MATR_GENE: assemble the macro-elements' generalized matrices."""

from asterlite.catalog import BLOC, OPER, SIMP, equal_to


def _sdprod(kw) -> str:
    return "matr_asse_gene_c" if kw.get("OPTION") == "RIGI_GENE_C" else "matr_asse_gene_r"


ASSE_MATR_GENE = OPER(
    nom="ASSE_MATR_GENE",
    sd_prod=_sdprod,
    reentrant="n",
    fr="Assemble the generalized matrices of the macro-elements of a generalized model",
    NUME_DDL_GENE=SIMP(statut="o", typ="nume_ddl_gene"),
    METHODE=SIMP(statut="f", typ="TXM", defaut="CLASSIQUE", into=("CLASSIQUE", "INITIAL")),
    b_option=BLOC(
        condition=equal_to("METHODE", "CLASSIQUE"),
        OPTION=SIMP(
            statut="o", typ="TXM", into=("RIGI_GENE", "RIGI_GENE_C", "MASS_GENE", "AMOR_GENE")
        ),
    ),
)
