"""INFO_MODE: how many eigenvalues lie in given bands (Sturm counts)."""

from asterlite.catalogues.common import C_SOLVEUR

from asterlite.catalog import BLOC, FACT, OPER, SIMP, absent, equal_to

MATR_A_TYPES = (
    "matr_asse_depl_r", "matr_asse_temp_r", "matr_asse_pres_r", "matr_asse_gene_r",
    "matr_asse_depl_c", "matr_asse_gene_c",
)  # fmt: skip
MATR_B_TYPES = ("matr_asse_depl_r", "matr_asse_temp_r", "matr_asse_pres_r", "matr_asse_gene_r")
# code_aster factorises K - σ M once per bound: the solver changes cost, not the count
PARALLEL = "distribution of code_aster's factorisations over MPI processes"


def _sturm_counting(threshold: str, threshold_default: float) -> FACT:
    return FACT(
        statut="d",
        METHODE=SIMP(statut="f", typ="TXM", defaut="AUTO", into=("AUTO", "STURM")),
        **{threshold: SIMP(statut="f", typ="R", defaut=threshold_default)},
        PREC_SHIFT=SIMP(statut="f", typ="R", defaut=5.0e-2),
        NMAX_ITER_SHIFT=SIMP(statut="f", typ="I", defaut=3, val_min=0),
    )


INFO_MODE = OPER(
    nom="INFO_MODE",
    sd_prod="table_sdaster",
    fr="Count the eigenvalues of a pencil in frequency or critical-load bands",
    TYPE_MODE=SIMP(
        statut="f",
        typ="TXM",
        defaut="DYNAMIQUE",
        into=("MODE_COMPLEXE", "DYNAMIQUE", "MODE_FLAMB", "GENERAL"),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    b_dynamique=BLOC(
        condition=equal_to("TYPE_MODE", "DYNAMIQUE"),
        MATR_RIGI=SIMP(statut="o", typ=MATR_A_TYPES),
        MATR_MASS=SIMP(statut="o", typ=MATR_B_TYPES),
        FREQ=SIMP(statut="o", typ="R", min=2, max="**"),
        COMPTAGE=_sturm_counting("SEUIL_FREQ", 1.0e-2),
    ),
    b_flambement=BLOC(
        condition=equal_to("TYPE_MODE", "MODE_FLAMB"),
        MATR_RIGI=SIMP(statut="o", typ=MATR_A_TYPES),
        MATR_RIGI_GEOM=SIMP(statut="o", typ=MATR_B_TYPES),
        CHAR_CRIT=SIMP(statut="o", typ="R", min=2, max="**"),
        COMPTAGE=_sturm_counting("SEUIL_CHAR_CRIT", 1.0e-2),
    ),
    b_complexe=BLOC(
        condition=equal_to("TYPE_MODE", "MODE_COMPLEXE"),
        MATR_RIGI=SIMP(statut="o", typ=MATR_A_TYPES),
        MATR_MASS=SIMP(statut="o", typ=MATR_B_TYPES),
        MATR_AMOR=SIMP(statut="f", typ=MATR_B_TYPES),
        TYPE_CONTOUR=SIMP(statut="f", typ="TXM", defaut="CERCLE", into=("CERCLE",)),
        RAYON_CONTOUR=SIMP(statut="o", typ="R", val_min=1.0e-2),
        CENTRE_CONTOUR=SIMP(statut="f", typ="C", defaut=0.0 + 0.0j),
        COMPTAGE=FACT(
            statut="d",
            METHODE=SIMP(statut="f", typ="TXM", defaut="AUTO", into=("AUTO", "APM")),
            NBPOINT_CONTOUR=SIMP(statut="f", typ="I", defaut=40, val_min=10, val_max=1000),
            NMAX_ITER_CONTOUR=SIMP(statut="f", typ="I", defaut=3, val_min=1, val_max=5),
        ),
    ),
    b_general=BLOC(
        condition=equal_to("TYPE_MODE", "GENERAL"),
        MATR_A=SIMP(statut="o", typ=MATR_A_TYPES),
        MATR_B=SIMP(statut="o", typ=MATR_B_TYPES),
        MATR_C=SIMP(statut="f", typ=MATR_B_TYPES),
        CHAR_CRIT=SIMP(statut="f", typ="R", min=2, max="**"),
        b_contour=BLOC(
            condition=absent("CHAR_CRIT"),
            TYPE_CONTOUR=SIMP(statut="f", typ="TXM", defaut="CERCLE", into=("CERCLE",)),
            RAYON_CONTOUR=SIMP(statut="o", typ="R", val_min=1.0e-2),
            CENTRE_CONTOUR=SIMP(statut="f", typ="C", defaut=0.0 + 0.0j),
        ),
        COMPTAGE=FACT(
            statut="d",
            METHODE=SIMP(statut="f", typ="TXM", defaut="AUTO", into=("AUTO", "STURM", "APM")),
            SEUIL_CHAR_CRIT=SIMP(statut="f", typ="R", defaut=1.0e-2),
            PREC_SHIFT=SIMP(statut="f", typ="R", defaut=5.0e-2),
            NMAX_ITER_SHIFT=SIMP(statut="f", typ="I", defaut=3, val_min=0),
        ),
        NBPOINT_CONTOUR=SIMP(statut="f", typ="I", defaut=40, val_min=10, val_max=1000),
        NMAX_ITER_CONTOUR=SIMP(statut="f", typ="I", defaut=3, val_min=1, val_max=5),
    ),
    TITRE=SIMP(statut="f", typ="TXM"),
    SOLVEUR=C_SOLVEUR("INFO_MODE"),
    NIVEAU_PARALLELISME=SIMP(
        no_effect=PARALLEL, statut="f", typ="TXM", defaut="COMPLET", into=("PARTIEL", "COMPLET")
    ),
)
