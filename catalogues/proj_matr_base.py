"""PROJ_MATR_BASE: project an assembled matrix on a modal basis."""

from asterlite.catalog import OPER, SIMP, UN_PARMI


def _sdprod(kw) -> str:
    for key in ("MATR_ASSE", "MATR_ASSE_GENE"):
        matrix = kw.get(key)
        satisfies = getattr(matrix, "satisfies", lambda _t: False)
        if satisfies("matr_asse_depl_c") or satisfies("matr_asse_gene_c"):
            return "matr_asse_gene_c"
    return "matr_asse_gene_r"


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
