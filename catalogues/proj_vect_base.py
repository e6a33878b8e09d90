"""PROJ_VECT_BASE: project an assembled vector on a modal basis."""

from asterlite.catalog import OPER, SIMP, UN_PARMI

PROJ_VECT_BASE = OPER(
    nom="PROJ_VECT_BASE",
    sd_prod="vect_asse_gene",
    reentrant="n",
    fr="Project an assembled vector on a modal or Ritz basis",
    regles=(UN_PARMI("VECT_ASSE", "VECT_ASSE_GENE"),),
    BASE=SIMP(statut="o", typ=("mode_meca", "mode_gene")),
    NUME_DDL_GENE=SIMP(statut="o", typ="nume_ddl_gene"),
    TYPE_VECT=SIMP(statut="o", typ="TXM", into=("FORC", "DEPL", "VITE", "ACCE")),
    VECT_ASSE=SIMP(statut="f", typ="cham_no_sdaster"),
    VECT_ASSE_GENE=SIMP(statut="f", typ="vect_asse_gene"),
)
