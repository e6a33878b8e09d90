"""PROJ_MATR_BASE: project an assembled matrix on a modal basis."""

from asterlite.catalog import OPER, SIMP, UN_PARMI

# exact type of the projected matrix -> type of the projection, in the order
# code_aster's matr_asse_gene_prod tries them (real first)
PROJECTED = (
    ("MATR_ASSE", "matr_asse_depl_r", "matr_asse_gene_r"),
    ("MATR_ASSE_GENE", "matr_asse_gene_r", "matr_asse_gene_r"),
    ("MATR_ASSE", "matr_asse_depl_c", "matr_asse_gene_c"),
    ("MATR_ASSE_GENE", "matr_asse_gene_c", "matr_asse_gene_c"),
)


def _sdprod(kw) -> str:
    for key, given, produced in PROJECTED:
        if getattr(kw.get(key), "aster_type", None) == given:
            return produced
    raise TypeError("PROJ_MATR_BASE: the type of the matrix to project is not known")


PROJ_MATR_BASE = OPER(
    nom="PROJ_MATR_BASE",
    sd_prod=_sdprod,
    reentrant="n",
    fr="Project an assembled matrix on a modal or Ritz basis",
    regles=(UN_PARMI("MATR_ASSE", "MATR_ASSE_GENE"),),
    BASE=SIMP(statut="o", typ=("mode_meca", "mode_gene")),
    NUME_DDL_GENE=SIMP(statut="o", typ="nume_ddl_gene"),
    MATR_ASSE=SIMP(statut="f", typ=("matr_asse_depl_r", "matr_asse_depl_c")),
    MATR_ASSE_GENE=SIMP(statut="f", typ=("matr_asse_gene_r", "matr_asse_gene_c")),
)
