"""CALC_MODES: eigenmodes (dynamic, buckling or general eigenproblem)."""

from asterlite.catalogues.common import C_SOLVEUR, NO_EFFECT_LOG, NO_EFFECT_STORED, OUI_NON

from asterlite.catalog import BLOC, EXCLUS, FACT, MACRO, SIMP, Condition, equal_to, exists, is_in
from asterlite.lang.values import Unknown

SIMULTANEOUS = ("PLUS_PETITE", "PLUS_GRANDE", "BANDE", "CENTRE", "TOUT")
INVERSE = ("SEPARE", "AJUSTE", "PROCHE")
NORMES = ("MASS_GENE", "RIGI_GENE", "EUCL", "EUCL_TRAN", "TRAN", "TRAN_ROTA")
MATR_RIGI_TYPES = (
    "matr_asse_depl_r", "matr_asse_depl_c", "matr_asse_temp_r", "matr_asse_gene_r",
    "matr_asse_gene_c", "matr_asse_pres_r", "matr_asse_elim_r",
)  # fmt: skip
MATR_MASS_TYPES = (
    "matr_asse_depl_r", "matr_asse_gene_r", "matr_asse_pres_r", "matr_asse_temp_r",
    "matr_asse_elim_r",
)  # fmt: skip
MATR_FLAMB_TYPES = ("matr_asse_depl_r", "matr_asse_gene_r", "matr_asse_pres_r")


def _satisfies(concept, type_name: str) -> bool:
    return bool(getattr(concept, "satisfies", lambda _t: False)(type_name))


def _real_physical_stiffness(values) -> bool | None:
    rigi = values.get("MATR_RIGI")
    return None if rigi is Unknown else _satisfies(rigi, "matr_asse_depl_r")


REAL_PHYSICAL = Condition(_real_physical_stiffness, "MATR_RIGI is a matr_asse_depl_r")


def _sdprod(kw) -> str:
    if kw.get("TYPE_RESU") in ("MODE_FLAMB", "GENERAL"):
        return "mode_flamb"
    rigi = kw.get("MATR_RIGI")
    # damped modes of physical matrices are complex; of generalized ones, mode_gene
    physical_damping = _satisfies(kw.get("MATR_AMOR"), "matr_asse_depl_r")
    if physical_damping or _satisfies(rigi, "matr_asse_depl_c"):
        return "mode_meca_c"
    if _satisfies(rigi, "matr_asse_pres_r"):
        return "mode_acou"
    if _satisfies(rigi, "matr_asse_gene_r") or _satisfies(rigi, "matr_asse_gene_c"):
        return "mode_gene"
    return "mode_meca"


def _shift(**keywords) -> dict:
    """Keywords common to every search window."""
    return dict(
        **keywords,
        # how the solver moves a shift that falls on an eigenvalue: its cost, not the modes
        NMAX_ITER_SHIFT=SIMP(no_effect=EIGEN_TUNING, statut="f", typ="I", defaut=3, val_min=0),
        PREC_SHIFT=SIMP(no_effect=EIGEN_TUNING, statut="f", typ="R", defaut=5.0e-2, val_min=0.0),
    )


def _window(name: str, options, fr: str = "", **keywords) -> BLOC:
    """CALC_FREQ/CALC_CHAR_CRIT factor keyword for some OPTION values."""
    condition = (
        is_in("OPTION", options) if isinstance(options, tuple) else equal_to("OPTION", options)
    )
    return BLOC(condition=condition, **{name: FACT(statut="d", fr=fr, **_shift(**keywords))})


def _frequency_windows() -> dict:
    """CALC_FREQ for a dynamic problem."""
    nmax = dict(NMAX_FREQ=SIMP(statut="f", typ="I", defaut=10, val_min=0))
    seuil = dict(SEUIL_FREQ=SIMP(statut="f", typ="R", defaut=1.0e-2, val_min=0.0))
    listed = dict(
        FREQ=SIMP(statut="o", typ="R", max="**"),
        AMOR_REDUIT=SIMP(statut="f", typ="R", max="**"),
        NMAX_FREQ=SIMP(statut="f", typ="I", defaut=0, val_min=0),
        **seuil,
    )
    return dict(
        b_all=_window("CALC_FREQ", "TOUT", "All eigenfrequencies", **nmax, **seuil),
        b_smallest=_window(
            "CALC_FREQ", "PLUS_PETITE", "Smallest eigenfrequencies", **nmax, **seuil
        ),
        b_largest=_window(
            "CALC_FREQ",
            "PLUS_GRANDE",
            "Largest eigenfrequencies",
            NMAX_FREQ=SIMP(statut="f", typ="I", defaut=1, val_min=0),
            **seuil,
        ),
        b_centre=_window(
            "CALC_FREQ",
            "CENTRE",
            "Eigenfrequencies nearest to a value",
            FREQ=SIMP(statut="o", typ="R"),
            AMOR_REDUIT=SIMP(statut="f", typ="R", val_min=0.0, val_max=1.0),
            **nmax,
            **seuil,
        ),
        b_band=_window(
            "CALC_FREQ",
            "BANDE",
            "Eigenfrequencies in bands",
            FREQ=SIMP(statut="o", typ="R", min=2, max="**"),
            TABLE_FREQ=SIMP(statut="f", typ="table_sdaster"),
            NIVEAU_PARALLELISME=SIMP(
                statut="f", typ="TXM", defaut="COMPLET", into=("PARTIEL", "COMPLET")
            ),
            **seuil,
        ),
        b_nearest=_window("CALC_FREQ", "PROCHE", **listed),
        b_adjust=_window("CALC_FREQ", ("SEPARE", "AJUSTE"), **listed),
    )


def _critical_load_windows() -> dict:
    """CALC_CHAR_CRIT for buckling and general problems."""
    nmax = dict(NMAX_CHAR_CRIT=SIMP(statut="f", typ="I", defaut=10, val_min=0))
    seuil = dict(SEUIL_CHAR_CRIT=SIMP(statut="f", typ="R", defaut=1.0e-2, val_min=0.0))
    return dict(
        b_all=_window("CALC_CHAR_CRIT", "TOUT", **nmax, **seuil),
        b_smallest=_window("CALC_CHAR_CRIT", "PLUS_PETITE", **nmax, **seuil),
        b_centre=_window(
            "CALC_CHAR_CRIT", "CENTRE", CHAR_CRIT=SIMP(statut="o", typ="R"), **nmax, **seuil
        ),
        b_band=_window(
            "CALC_CHAR_CRIT",
            "BANDE",
            CHAR_CRIT=SIMP(statut="o", typ="R", min=2, max=2),
            TABLE_CHAR_CRIT=SIMP(statut="f", typ="table_sdaster"),
            **seuil,
        ),
        b_adjust=_window(
            "CALC_CHAR_CRIT",
            INVERSE,
            CHAR_CRIT=SIMP(statut="o", typ="R", max="**"),
            NMAX_CHAR_CRIT=SIMP(statut="f", typ="I", defaut=0, val_min=0),
            **seuil,
        ),
    )


# The eigen solver's method and tuning change how code_aster converges, not the
# converged pairs that asterlite computes to full precision with scipy.
EIGEN_TUNING = "eigen solver method and tuning"


def _eigen_solvers(simultaneous) -> dict:
    """SOLVEUR_MODAL: Lanczos/Jacobi/Sorensen/QZ or inverse iterations."""
    return dict(
        b_EigenSolv1=BLOC(
            condition=is_in("OPTION", simultaneous),
            SOLVEUR_MODAL=FACT(
                statut="d",
                regles=(EXCLUS("DIM_SOUS_ESPACE", "COEF_DIM_ESPACE"),),
                # JACOBI fixes the basis of equal eigenvalues (modal/subspace_start.py)
                METHODE=SIMP(
                    statut="f",
                    typ="TXM",
                    defaut="SORENSEN",
                    into=("TRI_DIAG", "JACOBI", "SORENSEN", "QZ"),
                ),
                b_tri_diag=BLOC(
                    condition=equal_to("METHODE", "TRI_DIAG"),
                    PREC_ORTHO=SIMP(
                        no_effect=EIGEN_TUNING, statut="f", typ="R", defaut=1.0e-12, val_min=0.0
                    ),
                    NMAX_ITER_ORTHO=SIMP(
                        no_effect=EIGEN_TUNING, statut="f", typ="I", defaut=5, val_min=0
                    ),
                    PREC_LANCZOS=SIMP(
                        no_effect=EIGEN_TUNING, statut="f", typ="R", defaut=1.0e-8, val_min=0.0
                    ),
                    NMAX_ITER_QR=SIMP(
                        no_effect=EIGEN_TUNING, statut="f", typ="I", defaut=30, val_min=0
                    ),
                    MODE_RIGIDE=SIMP(
                        no_effect=EIGEN_TUNING, statut="f", typ="TXM", defaut="NON", into=OUI_NON
                    ),
                ),
                b_jacobi=BLOC(
                    condition=equal_to("METHODE", "JACOBI"),
                    PREC_BATHE=SIMP(
                        no_effect=EIGEN_TUNING, statut="f", typ="R", defaut=1.0e-10, val_min=0.0
                    ),
                    NMAX_ITER_BATHE=SIMP(
                        no_effect=EIGEN_TUNING, statut="f", typ="I", defaut=40, val_min=0
                    ),
                    PREC_JACOBI=SIMP(
                        no_effect=EIGEN_TUNING, statut="f", typ="R", defaut=1.0e-2, val_min=0.0
                    ),
                    NMAX_ITER_JACOBI=SIMP(
                        no_effect=EIGEN_TUNING, statut="f", typ="I", defaut=12, val_min=0
                    ),
                ),
                b_sorensen=BLOC(
                    condition=equal_to("METHODE", "SORENSEN"),
                    PREC_SOREN=SIMP(
                        no_effect=EIGEN_TUNING, statut="f", typ="R", defaut=0.0, val_min=0.0
                    ),
                    NMAX_ITER_SOREN=SIMP(
                        no_effect=EIGEN_TUNING, statut="f", typ="I", defaut=20, val_min=1
                    ),
                    PARA_ORTHO_SOREN=SIMP(
                        no_effect=EIGEN_TUNING, statut="f", typ="R", defaut=0.717
                    ),
                ),
                b_qz=BLOC(
                    condition=equal_to("METHODE", "QZ"),
                    TYPE_QZ=SIMP(
                        no_effect=EIGEN_TUNING,
                        statut="f",
                        typ="TXM",
                        defaut="QZ_SIMPLE",
                        into=("QZ_QR", "QZ_SIMPLE", "QZ_EQUI"),
                    ),
                ),
                APPROCHE=SIMP(  # the operator ARPACK iterates on, not the eigenpairs
                    no_effect=EIGEN_TUNING,
                    statut="f",
                    typ="TXM",
                    defaut="REEL",
                    into=("REEL", "IMAG", "COMPLEXE"),
                ),
                DIM_SOUS_ESPACE=SIMP(no_effect=EIGEN_TUNING, statut="f", typ="I"),
                COEF_DIM_ESPACE=SIMP(no_effect=EIGEN_TUNING, statut="f", typ="I"),
            ),
        ),
        b_EigenSolv2=BLOC(
            condition=is_in("OPTION", INVERSE),
            SOLVEUR_MODAL=FACT(
                statut="d",
                NMAX_ITER_SEPARE=SIMP(
                    no_effect=EIGEN_TUNING, statut="f", typ="I", defaut=30, val_min=1
                ),
                PREC_SEPARE=SIMP(
                    no_effect=EIGEN_TUNING, statut="f", typ="R", defaut=1.0e-4, val_min=1.0e-70
                ),
                NMAX_ITER_AJUSTE=SIMP(
                    no_effect=EIGEN_TUNING, statut="f", typ="I", defaut=15, val_min=1
                ),
                PREC_AJUSTE=SIMP(
                    no_effect=EIGEN_TUNING, statut="f", typ="R", defaut=1.0e-4, val_min=1.0e-70
                ),
                OPTION_INV=SIMP(
                    no_effect=EIGEN_TUNING,
                    statut="f",
                    typ="TXM",
                    defaut="DIRECT",
                    into=("DIRECT", "RAYLEIGH"),
                ),
                PREC_INV=SIMP(
                    no_effect=EIGEN_TUNING, statut="f", typ="R", defaut=1.0e-5, val_min=1.0e-70
                ),
                NMAX_ITER_INV=SIMP(
                    no_effect=EIGEN_TUNING, statut="f", typ="I", defaut=30, val_min=1
                ),
            ),
        ),
    )


def _veri_mode(seuil: float, sturm_default: str, sturm_into=OUI_NON) -> FACT:
    return FACT(
        statut="d",
        # asterlite checks residuals itself where its eigen solver iterates (sparse)
        no_effect="code_aster's checks of its eigen solver (residuals, Sturm count)",
        STOP_ERREUR=SIMP(statut="f", typ="TXM", defaut="OUI", into=OUI_NON),
        SEUIL=SIMP(statut="f", typ="R", val_min=0.0, defaut=seuil),
        PREC_SHIFT=SIMP(statut="f", typ="R", defaut=5.0e-3, val_min=0.0),
        STURM=SIMP(statut="f", typ="TXM", defaut=sturm_default, into=sturm_into),
    )


def _norm_mode() -> FACT:
    return FACT(
        statut="f",
        NORME=SIMP(statut="f", typ="TXM", defaut="TRAN_ROTA", into=NORMES),
        INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    )


def _buckling_like(matrices: dict) -> dict:
    """Keywords of TYPE_RESU='MODE_FLAMB' and 'GENERAL' (critical loads)."""
    simultaneous = ("PLUS_PETITE", "BANDE", "CENTRE", "TOUT")
    return dict(
        **matrices,
        NORM_MODE=_norm_mode(),
        OPTION=SIMP(statut="f", typ="TXM", defaut="PLUS_PETITE", into=simultaneous + INVERSE),
        **_critical_load_windows(),
        **_eigen_solvers(simultaneous),
        b_linSolv_Inv3=BLOC(condition=is_in("OPTION", INVERSE), SOLVEUR=C_SOLVEUR("MODE_ITER_INV")),
        b_linSolv_Simu=BLOC(
            condition=is_in("OPTION", simultaneous), SOLVEUR=C_SOLVEUR("MODE_ITER_SIMULT")
        ),
        b_sturm_simult=BLOC(
            condition=is_in("OPTION", simultaneous), VERI_MODE=_veri_mode(1.0e-6, "OUI")
        ),
        b_veri_mode_inv=BLOC(
            condition=is_in("OPTION", INVERSE), VERI_MODE=_veri_mode(1.0e-2, "NON")
        ),
    )


CALC_MODES = MACRO(
    nom="CALC_MODES",
    sd_prod=_sdprod,
    reentrant="n",
    fr="Compute eigenmodes of a structure",
    TYPE_RESU=SIMP(
        statut="f", typ="TXM", defaut="DYNAMIQUE", into=("DYNAMIQUE", "MODE_FLAMB", "GENERAL")
    ),
    CHAM_MATER=SIMP(statut="f", typ="cham_mater", no_effect=NO_EFFECT_STORED),
    CARA_ELEM=SIMP(statut="f", typ="cara_elem", no_effect=NO_EFFECT_STORED),
    b_dyna=BLOC(
        condition=equal_to("TYPE_RESU", "DYNAMIQUE"),
        MATR_RIGI=SIMP(statut="o", typ=MATR_RIGI_TYPES),
        MATR_MASS=SIMP(statut="o", typ=MATR_MASS_TYPES),
        MATR_AMOR=SIMP(statut="f", typ=("matr_asse_depl_r", "matr_asse_gene_r")),
        NORM_MODE=_norm_mode(),
        OPTION=SIMP(statut="f", typ="TXM", defaut="PLUS_PETITE", into=SIMULTANEOUS + INVERSE),
        **_frequency_windows(),
        **_eigen_solvers(SIMULTANEOUS),
        b_linSolv_Inv1=BLOC(
            condition=equal_to("OPTION", "PROCHE"), SOLVEUR=C_SOLVEUR("MODE_ITER_INV")
        ),
        b_linSolv_Inv2=BLOC(
            condition=is_in("OPTION", ("SEPARE", "AJUSTE")) & ~exists("MATR_AMOR"),
            SOLVEUR=C_SOLVEUR("MODE_ITER_INV"),
        ),
        b_linSolv_Inv3=BLOC(
            condition=is_in("OPTION", ("SEPARE", "AJUSTE")) & exists("MATR_AMOR"),
            SOLVEUR=C_SOLVEUR("MODE_ITER_INV"),
        ),
        b_linSolv_Simu=BLOC(
            condition=is_in("OPTION", SIMULTANEOUS), SOLVEUR=C_SOLVEUR("MODE_ITER_SIMULT")
        ),
        b_post=BLOC(
            condition=REAL_PHYSICAL,
            FILTRE_MODE=FACT(
                statut="f",
                CRIT_EXTR=SIMP(
                    statut="f", typ="TXM", defaut="MASS_EFFE_UN", into=("MASS_EFFE_UN", "MASS_GENE")
                ),
                SEUIL=SIMP(statut="f", typ="R", defaut=1.0e-3),
            ),
            IMPRESSION=FACT(
                statut="f",
                no_effect=NO_EFFECT_LOG,
                TOUT_PARA=SIMP(statut="f", typ="TXM", defaut="OUI", into=OUI_NON),
                CUMUL=SIMP(statut="f", typ="TXM", defaut="OUI", into=OUI_NON),
                CRIT_EXTR=SIMP(
                    statut="f", typ="TXM", defaut="MASS_EFFE_UN", into=("MASS_EFFE_UN", "MASS_GENE")
                ),
            ),
        ),
        b_sturm_simult=BLOC(
            condition=is_in("OPTION", ("PLUS_PETITE", "PLUS_GRANDE", "CENTRE", "TOUT")),
            VERI_MODE=_veri_mode(1.0e-6, "OUI"),
        ),
        b_sturm_bande=BLOC(
            condition=equal_to("OPTION", "BANDE"),
            VERI_MODE=_veri_mode(1.0e-6, "GLOBAL", ("GLOBAL", "LOCAL", "OUI", "NON")),
        ),
        b_veri_mode_inv=BLOC(
            condition=is_in("OPTION", INVERSE), VERI_MODE=_veri_mode(1.0e-2, "NON")
        ),
    ),
    b_flamb=BLOC(
        condition=equal_to("TYPE_RESU", "MODE_FLAMB"),
        **_buckling_like(
            dict(
                MATR_RIGI=SIMP(statut="o", typ=MATR_FLAMB_TYPES),
                MATR_RIGI_GEOM=SIMP(statut="o", typ=MATR_FLAMB_TYPES),
            )
        ),
    ),
    b_general=BLOC(
        condition=equal_to("TYPE_RESU", "GENERAL"),
        **_buckling_like(
            dict(
                MATR_A=SIMP(statut="o", typ=MATR_FLAMB_TYPES),
                MATR_B=SIMP(statut="o", typ=MATR_FLAMB_TYPES),
            )
        ),
    ),
    STOP_BANDE_VIDE=SIMP(statut="f", typ="TXM", defaut="OUI", into=OUI_NON),
    AMELIORATION=SIMP(statut="f", typ="TXM", defaut="NON", into=OUI_NON),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
