"""PROD_MATR_CHAM: the product of an assembled matrix by a nodal field."""

from asterlite.catalog import OPER, SIMP

PROD_MATR_CHAM = OPER(
    nom="PROD_MATR_CHAM",
    sd_prod="cham_no_sdaster",
    reentrant="n",
    fr="Product of an assembled matrix by a nodal field",
    MATR_ASSE=SIMP(
        statut="o",
        typ=("matr_asse_depl_r", "matr_asse_depl_c", "matr_asse_temp_r", "matr_asse_pres_c"),
    ),
    CHAM_NO=SIMP(statut="o", typ="cham_no_sdaster"),
    TITRE=SIMP(statut="f", typ="TXM"),
)
