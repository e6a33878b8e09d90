"""MODE_ITER_SIMULT (code_aster up to 12): eigenmodes by simultaneous iterations.

Legacy command, replaced by CALC_MODES (OPTION 'PLUS_PETITE', 'BANDE',
'CENTRE', 'TOUT'). Both historical spellings are accepted as written
(``MATR_A``/``MATR_B``/``MATR_C`` and ``MATR_RIGI``/``MATR_MASS``/``MATR_AMOR``);
its legacy form translates the call (see ``asterlite.legacy.modes``).
"""

from asterlite.catalogues.common import C_SOLVEUR, OUI_NON

from asterlite.catalog import BLOC, EXCLUS, FACT, OPER, SIMP, UN_PARMI, equal_to

MATRIX_TYPES = (
    "matr_asse_depl_r", "matr_asse_depl_c", "matr_asse_gene_r", "matr_asse_gene_c",
    "matr_asse_pres_r",
)  # fmt: skip
SIMULTANEOUS = ("PLUS_PETITE", "BANDE", "CENTRE", "TOUT")


def _window(value_name: str, nmax_name: str, seuil_name: str) -> FACT:
    """CALC_FREQ / CALC_CHAR_CRIT as the legacy command wrote it."""
    return FACT(
        statut="f",
        regles=(EXCLUS("DIM_SOUS_ESPACE", "COEF_DIM_ESPACE"),),
        OPTION=SIMP(statut="f", typ="TXM", into=SIMULTANEOUS),
        b_values=BLOC(
            condition=equal_to("OPTION", ("CENTRE", "BANDE")),
            **{value_name: SIMP(statut="o", typ="R", max="**")},
        ),
        AMOR_REDUIT=SIMP(statut="f", typ="R"),
        **{nmax_name: SIMP(statut="f", typ="I", val_min=0)},
        APPROCHE=SIMP(statut="f", typ="TXM", into=("REEL", "IMAG", "COMPLEXE")),
        DIM_SOUS_ESPACE=SIMP(statut="f", typ="I"),
        COEF_DIM_ESPACE=SIMP(statut="f", typ="I"),
        NPREC_SOLVEUR=SIMP(statut="f", typ="I"),
        NMAX_ITER_SHIFT=SIMP(statut="f", typ="I", val_min=0),
        PREC_SHIFT=SIMP(statut="f", typ="R", val_min=0.0),
        **{seuil_name: SIMP(statut="f", typ="R", val_min=0.0)},
        TABLE_FREQ=SIMP(statut="f", typ="table_sdaster"),
    )


def matrices(types: tuple) -> dict:
    """The matrices of MODE_ITER_SIMULT and MODE_ITER_INV, under both their names
    (MATR_A/MATR_B/MATR_C before code_aster 11)."""
    names = ("MATR_RIGI", "MATR_MASS", "MATR_AMOR", "MATR_A", "MATR_B", "MATR_C")
    return {name: SIMP(statut="f", typ=types) for name in names}


MATRIX_RULES = (UN_PARMI("MATR_RIGI", "MATR_A"), UN_PARMI("MATR_MASS", "MATR_B"))


def veri_mode() -> FACT:
    return FACT(
        statut="f",
        STOP_ERREUR=SIMP(statut="f", typ="TXM", into=OUI_NON),
        PREC_SHIFT=SIMP(statut="f", typ="R"),
        SEUIL=SIMP(statut="f", typ="R"),
        STURM=SIMP(statut="f", typ="TXM", into=OUI_NON),
    )


MODE_ITER_SIMULT = OPER(
    nom="MODE_ITER_SIMULT",
    sd_prod=lambda kw: None,
    reentrant="n",
    fr="Eigenmodes by simultaneous iterations (legacy: CALC_MODES)",
    regles=MATRIX_RULES,
    **matrices(MATRIX_TYPES),
    METHODE=SIMP(statut="f", typ="TXM", into=("TRI_DIAG", "JACOBI", "SORENSEN", "QZ")),
    PREC_ORTHO=SIMP(statut="f", typ="R"),
    NMAX_ITER_ORTHO=SIMP(statut="f", typ="I"),
    PREC_LANCZOS=SIMP(statut="f", typ="R"),
    NMAX_ITER_QR=SIMP(statut="f", typ="I"),
    PREC_BATHE=SIMP(statut="f", typ="R"),
    NMAX_ITER_BATHE=SIMP(statut="f", typ="I"),
    PREC_JACOBI=SIMP(statut="f", typ="R"),
    NMAX_ITER_JACOBI=SIMP(statut="f", typ="I"),
    PREC_SOREN=SIMP(statut="f", typ="R"),
    NMAX_ITER_SOREN=SIMP(statut="f", typ="I"),
    PARA_ORTHO_SOREN=SIMP(statut="f", typ="R"),
    TYPE_QZ=SIMP(statut="f", typ="TXM", into=("QZ_QR", "QZ_SIMPLE", "QZ_EQUI")),
    TYPE_RESU=SIMP(statut="f", typ="TXM", into=("DYNAMIQUE", "MODE_FLAMB", "GENERAL")),
    OPTION=SIMP(statut="f", typ="TXM", into=("MODE_RIGIDE", "SANS")),
    b_flamb=BLOC(
        condition=equal_to("TYPE_RESU", ("MODE_FLAMB", "GENERAL")),
        MATR_RIGI_GEOM=SIMP(statut="f", typ=MATRIX_TYPES),
        CALC_CHAR_CRIT=_window("CHAR_CRIT", "NMAX_CHAR_CRIT", "SEUIL_CHAR_CRIT"),
        CALC_FREQ=_window("CHAR_CRIT", "NMAX_FREQ", "SEUIL_FREQ"),
    ),
    b_dynam=BLOC(
        condition=~equal_to("TYPE_RESU", ("MODE_FLAMB", "GENERAL")),
        CALC_FREQ=_window("FREQ", "NMAX_FREQ", "SEUIL_FREQ"),
    ),
    VERI_MODE=veri_mode(),
    SOLVEUR=C_SOLVEUR("MODE_ITER_SIMULT", statut="f"),
    SENSIBILITE=SIMP(statut="f", typ="TXM", max="**"),
    STOP_FREQ_VIDE=SIMP(statut="f", typ="TXM", into=OUI_NON),
    STOP_BANDE_VIDE=SIMP(statut="f", typ="TXM", into=OUI_NON),
    INFO=SIMP(statut="f", typ="I", into=(1, 2)),
    TITRE=SIMP(statut="f", typ="TXM", max="**"),
)
