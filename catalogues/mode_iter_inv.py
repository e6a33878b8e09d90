"""MODE_ITER_INV (code_aster up to 12): eigenmodes by inverse iterations.

Legacy command, replaced by CALC_MODES (OPTION 'SEPARE', 'AJUSTE' or
'PROCHE'; the legacy default was 'AJUSTE'). Its legacy form translates
the call (see ``asterlite.legacy.modes``).
"""

from asterlite.catalogues.common import C_SOLVEUR
from asterlite.catalogues.mode_iter_simult import MATRIX_RULES, matrices, veri_mode

from asterlite.catalog import BLOC, FACT, OPER, SIMP, equal_to

MATRIX_TYPES = ("matr_asse_depl_r", "matr_asse_gene_r", "matr_asse_pres_r")
INVERSE = ("SEPARE", "AJUSTE", "PROCHE")


def _window(value_name: str) -> FACT:
    return FACT(
        statut="o",
        OPTION=SIMP(statut="f", typ="TXM", into=INVERSE),
        **{value_name: SIMP(statut="o", typ="R", max="**")},
        AMOR_REDUIT=SIMP(statut="f", typ="R", max="**"),
        NMAX_FREQ=SIMP(statut="f", typ="I", val_min=0),
        NMAX_ITER_SEPARE=SIMP(statut="f", typ="I", val_min=0),
        PREC_SEPARE=SIMP(statut="f", typ="R", val_min=0.0),
        NMAX_ITER_AJUSTE=SIMP(statut="f", typ="I", val_min=0),
        PREC_AJUSTE=SIMP(statut="f", typ="R", val_min=0.0),
        NPREC_SOLVEUR=SIMP(statut="f", typ="I"),
        NMAX_ITER_SHIFT=SIMP(statut="f", typ="I", val_min=0),
        PREC_SHIFT=SIMP(statut="f", typ="R", val_min=0.0),
        SEUIL_FREQ=SIMP(statut="f", typ="R", val_min=0.0),
    )


MODE_ITER_INV = OPER(
    nom="MODE_ITER_INV",
    sd_prod=lambda kw: None,
    reentrant="n",
    fr="Eigenmodes by inverse iterations (legacy: CALC_MODES)",
    regles=MATRIX_RULES,
    **matrices(MATRIX_TYPES),
    TYPE_RESU=SIMP(statut="f", typ="TXM", into=("DYNAMIQUE", "MODE_FLAMB")),
    b_dynam=BLOC(condition=~equal_to("TYPE_RESU", "MODE_FLAMB"), CALC_FREQ=_window("FREQ")),
    b_flamb=BLOC(condition=equal_to("TYPE_RESU", "MODE_FLAMB"), CALC_FREQ=_window("CHAR_CRIT")),
    CALC_MODE=FACT(
        statut="f",
        OPTION=SIMP(statut="f", typ="TXM", into=("DIRECT", "RAYLEIGH")),
        PREC=SIMP(statut="f", typ="R", val_min=0.0),
        NMAX_ITER=SIMP(statut="f", typ="I", val_min=0),
    ),
    VERI_MODE=veri_mode(),
    SOLVEUR=C_SOLVEUR("MODE_ITER_INV", statut="f"),
    SENSIBILITE=SIMP(statut="f", typ="TXM", max="**"),
    INFO=SIMP(statut="f", typ="I", into=(1, 2)),
    TITRE=SIMP(statut="f", typ="TXM", max="**"),
)
