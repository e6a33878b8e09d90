"""FACTORISER: factorise an assembled matrix for later solves (RESOUDRE)."""

from asterlite.catalog import BLOC, EXCLUS, OPER, SIMP, equal_to, is_in

MATRIX_TYPES = (
    "matr_asse_depl_r",
    "matr_asse_depl_c",
    "matr_asse_temp_r",
    "matr_asse_temp_c",
    "matr_asse_pres_r",
    "matr_asse_pres_c",
)


def _sdprod(kw) -> str:
    matrix = kw.get("MATR_ASSE")
    for name in MATRIX_TYPES:
        if getattr(matrix, "satisfies", lambda _t: False)(name):
            return name
    return "matr_asse_depl_r"


def _direct(renum_into, renum_default, **extra) -> dict:
    return dict(
        RENUM=SIMP(statut="f", typ="TXM", into=renum_into, defaut=renum_default),
        STOP_SINGULIER=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
        NPREC=SIMP(statut="f", typ="I", defaut=8),
        **extra,
    )


FACTORISER = OPER(
    nom="FACTORISER",
    sd_prod=_sdprod,
    reentrant="f",
    fr="Factorise an assembled matrix (direct solvers) or build a preconditioner",
    MATR_ASSE=SIMP(statut="o", typ=MATRIX_TYPES),
    METHODE=SIMP(
        statut="f", typ="TXM", defaut="MUMPS", into=("MULT_FRONT", "LDLT", "GCPC", "PETSC", "MUMPS")
    ),
    b_mult_front=BLOC(condition=equal_to("METHODE", "MULT_FRONT"), **_direct(("MD", "MDA"), "MDA")),
    b_ldlt=BLOC(
        condition=equal_to("METHODE", "LDLT"),
        regles=(EXCLUS("BLOC_DEBUT", "DDL_DEBUT"), EXCLUS("BLOC_FIN", "DDL_FIN")),
        **_direct(
            ("RCMK",),
            "RCMK",
            BLOC_DEBUT=SIMP(statut="f", typ="I", val_min=1),
            DDL_DEBUT=SIMP(statut="f", typ="I", val_min=1),
            BLOC_FIN=SIMP(statut="f", typ="I", val_min=1),
            DDL_FIN=SIMP(statut="f", typ="I", val_min=1),
        ),
    ),
    b_mumps=BLOC(
        condition=equal_to("METHODE", "MUMPS"),
        **_direct(
            ("AMD", "AMF", "PORD", "METIS", "QAMD", "SCOTCH", "AUTO", "PARMETIS", "PTSCOTCH"),
            "AUTO",
            TYPE_RESOL=SIMP(
                statut="f", typ="TXM", defaut="AUTO", into=("NONSYM", "SYMGEN", "SYMDEF", "AUTO")
            ),
            PRETRAITEMENTS=SIMP(statut="f", typ="TXM", defaut="AUTO", into=("SANS", "AUTO")),
            PCENT_PIVOT=SIMP(statut="f", typ="I", defaut=20),
            ELIM_LAGR=SIMP(statut="f", typ="TXM", defaut="LAGR2", into=("LAGR2", "NON")),
            GESTION_MEMOIRE=SIMP(
                statut="f", typ="TXM", defaut="IN_CORE", into=("IN_CORE", "OUT_OF_CORE", "EVAL")
            ),
            ACCELERATION=SIMP(
                statut="f", typ="TXM", defaut="AUTO", into=("AUTO", "FR", "FR+", "LR", "LR+")
            ),
            LOW_RANK_SEUIL=SIMP(statut="f", typ="R", defaut=0.0),
        ),
    ),
    b_iterat=BLOC(
        condition=is_in("METHODE", ("GCPC", "PETSC")),
        PRE_COND=SIMP(
            statut="f",
            typ="TXM",
            into=("LDLT_INC", "JACOBI", "SOR", "LDLT_SP", "LDLT_DP"),
            defaut="LDLT_INC",
        ),
    ),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", into=(1, 2)),
)
