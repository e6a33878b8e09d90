"""Catalogue fragments shared by several commands (code_aster's ``Commons``).

Helpers writing catalogues may ADD fragments here; never rewrite existing ones.
Each fragment is a function returning a fresh object, or a plain tuple of
choices, so that a command file reads like its code_aster counterpart.
"""

from asterlite.catalog import BLOC, FACT, SIMP, equal_to, is_in

# ---------------------------------------------------------------------------
# Common choice lists
# ---------------------------------------------------------------------------

# Why some keywords change no result in asterlite (catalogue ``no_effect=``).
NO_EFFECT_LOG = "messages of code_aster's run only"
NO_EFFECT_DATABASE = "code_aster's JEVEUX database and memory management"
# asterlite solves its linear systems with scipy's direct solvers: the choice
# and tuning of code_aster's solver changes cost, not results beyond round-off.
NO_EFFECT_SOLVER = "linear solver method and tuning"
# code_aster records these with a result for later commands; asterlite's later
# commands reach the model, material and characteristics through the numbering.
NO_EFFECT_STORED = "recorded with the result for later commands"

OUI_NON = ("OUI", "NON")

#: Result field names accepted by NOM_CHAM (the subset of code_aster's
#: C_NOM_CHAM_INTO that mechanical dynamics uses).
NOM_CHAM_INTO = (
    "DEPL",
    "VITE",
    "ACCE",
    "DEPL_ABSOLU",
    "VITE_ABSOLU",
    "ACCE_ABSOLU",
    "FORC_NODA",
    "REAC_NODA",
    "EFGE_ELGA",
    "EFGE_ELNO",
    "EFGE_NOEU",
    "SIEF_ELGA",
    "SIEF_ELNO",
    "SIEF_NOEU",
    "SIGM_ELGA",
    "SIGM_ELNO",
    "SIGM_NOEU",
    "SIPM_ELNO",
    "SIPO_ELNO",
    "SIPO_NOEU",
    "SIEQ_ELGA",
    "SIEQ_ELNO",
    "SIEQ_NOEU",
    "STRX_ELGA",
    "DEGE_ELGA",
    "DEGE_ELNO",
    "DEGE_NOEU",
    "EPSI_ELGA",
    "EPSI_ELNO",
    "EPSI_NOEU",
    "EPEQ_ELGA",
    "EPEQ_ELNO",
    "EPEQ_NOEU",
    "VARI_ELGA",
    "VARI_ELNO",
    "VARI_NOEU",
    "ENEL_ELEM",
    "ENEL_ELGA",
    "ENEL_ELNO",
    "ENEL_NOEU",
    "ECIN_ELEM",
    "EPOT_ELEM",
    "TEMP",
    "PRES",
)

#: Physical quantities ("grandeurs") used to build TYPE_CHAM values.
NOM_GRANDEUR = (
    "ABSC_R",
    "CAORIE_R",
    "DEPL_C",
    "DEPL_F",
    "DEPL_R",
    "EPSI_R",
    "FORC_C",
    "FORC_F",
    "FORC_R",
    "GEOM_R",
    "INST_R",
    "NEUT_F",
    "NEUT_I",
    "NEUT_R",
    "PRES_R",
    "SIEF_C",
    "SIEF_R",
    "STRX_R",
    "TEMP_F",
    "TEMP_R",
    "VARI_R",
)

#: CREA_CHAMP/TYPE_CHAM values: a location (CART, NOEU, ELEM, ELNO, ELGA)
#: followed by a quantity, as in code_aster's C_TYPE_CHAM_INTO.
TYPE_CHAM_INTO = tuple(
    f"{location}_{quantity}"
    for location in ("CART", "NOEU", "ELEM", "ELNO", "ELGA")
    for quantity in NOM_GRANDEUR
)

# ---------------------------------------------------------------------------
# SOLVEUR: the linear solver factor keyword (code_aster's C_SOLVEUR)
# ---------------------------------------------------------------------------

# commands whose linear systems are only solved by direct methods
_SOLVE_DIRECT = (
    "DEFI_BASE_MODALE",
    "DYNA_LINE_HARM",
    "DYNA_TRAN_MODAL",
    "INFO_MODE",
    "MODE_ITER_INV",
    "MODE_ITER_SIMULT",
)
_DIRECT_ONLY = (*_SOLVE_DIRECT, "MACRO_ELAS_MULT")
_MODAL = ("INFO_MODE", "MODE_ITER_INV", "MODE_ITER_SIMULT")
# commands that only factorise (INFO_MODE's Sturm counts): no solve to post-process
_FACTOR_ONLY = ("INFO_MODE",)
_LINEAR = ("MECA_STATIQUE", "MODE_STATIQUE", "MACRO_ELAS_MULT")


def C_SOLVEUR(command: str, statut: str = "d") -> FACT:  # noqa: N802 - code_aster's name
    """The SOLVEUR factor keyword as code_aster 17 defines it for ``command``.

    ``command`` follows code_aster's classification: "MECA_STATIQUE",
    "MODE_STATIQUE", "MACRO_ELAS_MULT" (linear statics), "MODE_ITER_SIMULT"/"MODE_ITER_INV"
    (inside CALC_MODES), "DEFI_BASE_MODALE", "DYNA_TRAN_MODAL" (modal
    transient), "DYNA_LINE_TRAN" (non-linear class).
    """
    direct_only = command in _DIRECT_ONLY
    modal = command in _MODAL
    methods = (
        ("MULT_FRONT", "LDLT", "MUMPS")
        if direct_only
        else (
            "MULT_FRONT",
            "LDLT",
            "MUMPS",
            "GCPC",
            "PETSC",
        )
    )
    default = "LDLT" if command == "DYNA_TRAN_MODAL" else "MUMPS"
    stop_default = "NON" if command == "DEFI_BASE_MODALE" else "OUI"

    def stop_singulier():
        return (
            {} if modal else {"STOP_SINGULIER": SIMP(typ="TXM", defaut=stop_default, into=OUI_NON)}
        )

    def solve_only(**keywords):
        return {} if command in _FACTOR_ONLY else keywords

    def elim_lagr(into=OUI_NON, defaut="NON"):
        return {} if modal else {"ELIM_LAGR": SIMP(typ="TXM", defaut=defaut, into=into)}

    mumps_elim = (
        SIMP(typ="TXM", defaut="LAGR2", into=("NON", "LAGR2"))
        if modal
        else SIMP(typ="TXM", defaut="LAGR2", into=("OUI", "NON", "LAGR2"))
    )
    iterative = {}
    if not direct_only:
        iterative = {
            "b_gcpc": BLOC(
                condition=equal_to("METHODE", "GCPC"),
                fr="Preconditioned conjugate gradient parameters",
                PRE_COND=SIMP(
                    typ="TXM", defaut="LDLT_INC", into=("LDLT_INC", "LDLT_SP", "LDLT_DP")
                ),
                RENUM=SIMP(typ="TXM", defaut="RCMK", into=("RCMK", "SANS", "METIS", "PARMETIS")),
                NIVE_REMPLISSAGE=SIMP(typ="I", defaut=0),
                REAC_PRECOND=SIMP(typ="I", defaut=30),
                PCENT_PIVOT=SIMP(typ="I", defaut=20, val_min=1),
                RESI_RELA=SIMP(typ="R", defaut=1.0e-6),
                NMAX_ITER=SIMP(typ="I", defaut=0),
                **elim_lagr(),
            ),
            "b_petsc": BLOC(
                condition=equal_to("METHODE", "PETSC"),
                fr="PETSc parameters",
                ALGORITHME=SIMP(
                    typ="TXM",
                    defaut="FGMRES",
                    into=("CG", "CR", "GMRES", "GCR", "FGMRES", "GMRES_LMP"),
                ),
                PRE_COND=SIMP(
                    typ="TXM",
                    defaut="LDLT_SP",
                    into=(
                        "LDLT_INC",
                        "LDLT_SP",
                        "LDLT_DP",
                        "JACOBI",
                        "SOR",
                        "ML",
                        "BOOMER",
                        "GAMG",
                        "BLOC_LAGR",
                        "FIELDSPLIT",
                        "UTILISATEUR",
                        "HPDDM",
                        "SANS",
                    ),
                ),
                RENUM=SIMP(typ="TXM", defaut="SANS", into=("SANS", "RCMK", "METIS", "PARMETIS")),
                OPTION_PETSC=SIMP(typ="TXM", defaut=""),
                RESI_RELA=SIMP(typ="R", defaut=1.0e-6),
                NMAX_ITER=SIMP(typ="I", defaut=0),
                **elim_lagr(),
            ),
        }
    return FACT(
        statut=statut,
        fr="Linear solver",
        no_effect=NO_EFFECT_SOLVER,
        METHODE=SIMP(typ="TXM", defaut=default, into=methods),
        b_mult_front=BLOC(
            condition=equal_to("METHODE", "MULT_FRONT"),
            fr="Multifrontal solver parameters",
            RENUM=SIMP(typ="TXM", defaut="MDA", into=("MD", "MDA")),
            NPREC=SIMP(typ="I", defaut=8),
            **stop_singulier(),
            **elim_lagr(),
        ),
        b_ldlt=BLOC(
            condition=equal_to("METHODE", "LDLT"),
            fr="LDLT solver parameters",
            RENUM=SIMP(typ="TXM", defaut="RCMK", into=("RCMK",)),
            NPREC=SIMP(typ="I", defaut=8),
            **stop_singulier(),
            **elim_lagr(),
        ),
        b_mumps=BLOC(
            condition=equal_to("METHODE", "MUMPS"),
            fr="MUMPS solver parameters",
            RENUM=SIMP(
                typ="TXM",
                defaut="AUTO",
                into=(
                    "AMD",
                    "AMF",
                    "PORD",
                    "METIS",
                    "QAMD",
                    "SCOTCH",
                    "AUTO",
                    "PARMETIS",
                    "PTSCOTCH",
                ),
            ),
            NPREC=SIMP(typ="I", defaut=8),
            ELIM_LAGR=mumps_elim,
            TYPE_RESOL=SIMP(typ="TXM", defaut="AUTO", into=("NONSYM", "SYMGEN", "SYMDEF", "AUTO")),
            ACCELERATION=SIMP(
                typ="TXM",
                defaut="FR" if command in _SOLVE_DIRECT else "AUTO",
                into=("AUTO", "FR", "FR+", "FR++", "LR", "LR+", "LR++"),
            ),
            LOW_RANK_SEUIL=SIMP(typ="R", defaut=0.0),
            PRETRAITEMENTS=SIMP(typ="TXM", defaut="AUTO", into=("SANS", "AUTO")),
            **solve_only(
                POSTTRAITEMENTS=SIMP(
                    typ="TXM", defaut="AUTO", into=("SANS", "AUTO", "FORCE", "MINI")
                )
            ),
            PCENT_PIVOT=SIMP(typ="I", defaut=35, val_min=1),
            # right-hand sides MUMPS solves at once (a block size: speed only)
            NB_RHS=(
                SIMP(typ="I", defaut=-128, val_min=-1024, val_max=1024)
                if command == "MODE_STATIQUE"
                else SIMP(typ="I", defaut=1, val_min=1, val_max=32)
            ),
            **solve_only(RESI_RELA=SIMP(typ="R", defaut=1.0e-6 if command in _LINEAR else -1.0)),
            GESTION_MEMOIRE=SIMP(
                typ="TXM", defaut="AUTO", into=("IN_CORE", "OUT_OF_CORE", "AUTO", "EVAL")
            ),
            **stop_singulier(),
        ),
        **iterative,
    )


# ---------------------------------------------------------------------------
# Selecting mesh entities
# ---------------------------------------------------------------------------


def group_ma(statut: str = "f", max="**") -> SIMP:  # noqa: A002
    """GROUP_MA: names of element groups."""
    return SIMP(statut=statut, typ="grma", max=max)


def group_no(statut: str = "f", max="**") -> SIMP:  # noqa: A002
    """GROUP_NO: names of node groups."""
    return SIMP(statut=statut, typ="grno", max=max)


def noeud(max="**") -> SIMP:  # noqa: A002
    """NOEUD: node names (kept hidden, 'c', as in code_aster 17)."""
    return SIMP(statut="c", typ="no", max=max)


def maille(max="**") -> SIMP:  # noqa: A002
    """MAILLE: element names (kept hidden, 'c', as in code_aster 17)."""
    return SIMP(statut="c", typ="ma", max=max)


def tout() -> SIMP:
    """TOUT='OUI': the whole mesh."""
    return SIMP(statut="f", typ="TXM", into=("OUI",))


# ---------------------------------------------------------------------------
# Time/frequency selection in a result (CRITERE/PRECISION pairs)
# ---------------------------------------------------------------------------


def critere_precision(default_precision: float = 1.0e-6) -> dict:
    """CRITERE with the PRECISION blocks code_aster attaches to it."""
    return {
        "CRITERE": SIMP(statut="f", typ="TXM", defaut="RELATIF", into=("RELATIF", "ABSOLU")),
        "b_prec_rela": BLOC(
            condition=equal_to("CRITERE", "RELATIF"),
            PRECISION=SIMP(statut="f", typ="R", defaut=default_precision),
        ),
        "b_prec_abso": BLOC(
            condition=equal_to("CRITERE", "ABSOLU"), PRECISION=SIMP(statut="o", typ="R")
        ),
    }


__all__ = [
    "ANY_CONCEPT",
    "C_SOLVEUR",
    "NOM_CHAM_INTO",
    "NOM_GRANDEUR",
    "OUI_NON",
    "TYPE_CHAM_INTO",
    "critere_precision",
    "group_ma",
    "group_no",
    "is_in",
    "maille",
    "noeud",
    "tout",
]


# ---------------------------------------------------------------------------
# Any concept (code_aster's "assd"), for DETRUIRE and IMPR_CO
# ---------------------------------------------------------------------------

ANY_CONCEPT = (
    "assd",
    "maillage_sdaster", "squelette", "modele_sdaster", "cara_elem", "char_meca",
    "char_cine_meca", "mater_sdaster", "cham_mater", "matr_elem_depl_r", "matr_elem_depl_c",
    "vect_elem_depl_r", "nume_ddl_sdaster", "matr_asse_depl_r", "matr_asse_depl_c",
    "cham_no_sdaster", "cham_elem", "carte_sdaster", "mode_meca", "mode_meca_c", "mode_gene",
    "mode_flamb", "nume_ddl_gene", "matr_asse_gene_r", "matr_asse_gene_c", "vect_asse_gene",
    "tran_gene", "harm_gene", "dyna_trans", "dyna_harmo", "fonction_sdaster", "fonction_c",
    "formule", "nappe_sdaster", "table_sdaster", "table_fonction", "table_container",
    "listr8_sdaster", "listis_sdaster", "resultat_sdaster", "evol_elas", "evol_noli",
    "mult_elas", "interf_dyna_clas", "macr_elem_dyna", "entier", "reel",
)  # fmt: skip
