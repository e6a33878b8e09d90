"""RESOUDRE: solve a linear system with a matrix factorised by FACTORISER."""

from asterlite.catalog import OPER, SIMP

MATRIX_TYPES = (
    "matr_asse_depl_r",
    "matr_asse_depl_c",
    "matr_asse_temp_r",
    "matr_asse_temp_c",
    "matr_asse_pres_r",
    "matr_asse_pres_c",
)

RESOUDRE = OPER(
    nom="RESOUDRE",
    sd_prod="cham_no_sdaster",
    reentrant="f",
    fr="Solve a linear system with a factorised matrix (or by preconditioned iterations)",
    MATR=SIMP(statut="o", typ=MATRIX_TYPES),
    CHAM_NO=SIMP(statut="o", typ="cham_no_sdaster"),
    CHAM_CINE=SIMP(statut="f", typ="cham_no_sdaster"),
    RESI_RELA=SIMP(statut="f", typ="R", defaut=1.0e-6),
    POSTTRAITEMENTS=SIMP(
        statut="f", typ="TXM", defaut="AUTO", into=("SANS", "AUTO", "FORCE", "MINI")
    ),
    NMAX_ITER=SIMP(statut="f", typ="I", defaut=0),
    MATR_PREC=SIMP(statut="f", typ=("matr_asse_depl_r", "matr_asse_temp_r", "matr_asse_pres_r")),
    ALGORITHME=SIMP(
        statut="f", typ="TXM", into=("CG", "CR", "GMRES", "GCR", "FGMRES"), defaut="FGMRES"
    ),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", into=(1, 2)),
)
