"""Keyword definitions of code_aster 10 to 14 for generalized transients.

Shared by the legacy catalogues (DYNA_TRAN_MODAL) and by the legacy form of
DYNA_VIBRA (``DYNA_VIBRA_V13``, before COMPORTEMENT): a legacy call is
checked as written against these, then translated (``asterlite.legacy``)
and checked again against the modern catalogue.
"""

from asterlite.catalogues.common_post import comportement_dyna, para_lame_flui
from asterlite.catalogues.dyna_vibra import DYNA_VIBRA

from asterlite.catalog import (
    BLOC,
    ENSEMBLE,
    EXCLUS,
    FACT,
    OPER,
    PRESENT_ABSENT,
    SIMP,
    equal_to,
    exists,
)

LEGACY_SCHEMES = (
    "NEWMARK", "EULER", "DEVOGE", "ADAPT", "ADAPT_ORDRE1", "ADAPT_ORDRE2", "ITMI",
    "RUNGE_KUTTA_54", "RUNGE_KUTTA_32", "DIFF_CENTRE", "WILSON",
)  # fmt: skip
MATRICES = ("MATR_MASS", "MATR_RIGI")  # named MASS_GENE/RIGI_GENE in code_aster 10


def _modern(bloc: str) -> dict:
    """The entries of a generalized-transient block of today's DYNA_VIBRA."""
    return DYNA_VIBRA.entries[bloc].entries


def schema_temps_legacy() -> FACT:
    """SCHEMA_TEMPS of code_aster 11 to 13 (default NEWMARK, RK TOLERANCE 1e-3)."""
    return FACT(
        statut="f",
        SCHEMA=SIMP(statut="f", typ="TXM", into=LEGACY_SCHEMES),
        b_newmark=BLOC(
            condition=equal_to("SCHEMA", "NEWMARK"),
            BETA=SIMP(statut="f", typ="R"),
            GAMMA=SIMP(statut="f", typ="R"),
        ),
        b_wilson=BLOC(condition=equal_to("SCHEMA", "WILSON"), THETA=SIMP(statut="f", typ="R")),
        b_runge_kutta=BLOC(
            condition=equal_to("SCHEMA", ("RUNGE_KUTTA_54", "RUNGE_KUTTA_32")),
            TOLERANCE=SIMP(statut="f", typ="R"),
        ),
        b_itmi=BLOC(
            condition=equal_to("SCHEMA", "ITMI"),
            regles=(ENSEMBLE("BASE_ELAS_FLUI", "NUME_VITE_FLUI"),),
            BASE_ELAS_FLUI=SIMP(statut="f", typ="melasflu_sdaster"),
            NUME_VITE_FLUI=SIMP(statut="f", typ="I"),
            ETAT_STAT=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
            PREC_DUREE=SIMP(statut="f", typ="R"),
            CHOC_FLUI=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
            NB_MODE=SIMP(statut="f", typ="I"),
            NB_MODE_FLUI=SIMP(statut="f", typ="I"),
            TS_REG_ETAB=SIMP(statut="f", typ="R"),
        ),
    )


def increment_legacy() -> FACT:
    """Today's INCREMENT, repeatable, with the adaptive-step controls that later
    moved to SCHEMA_TEMPS."""
    modern = _modern("b_param_tran")["INCREMENT"]
    return FACT(
        statut="o",
        max="**",
        regles=modern.rules,
        **modern.entries,
        VITE_MIN=SIMP(statut="f", typ="TXM", into=("MAXI", "NORM")),
        COEF_MULT_PAS=SIMP(statut="f", typ="R"),
        COEF_DIVI_PAS=SIMP(statut="f", typ="R"),
        PAS_LIMI_RELA=SIMP(statut="f", typ="R"),
        NB_POIN_PERIODE=SIMP(statut="f", typ="I"),
        NMAX_ITER_PAS=SIMP(statut="f", typ="I"),
        PAS_MAXI=SIMP(statut="f", typ="R"),
        PAS_MINI=SIMP(statut="f", typ="R"),
    )


def etat_init_legacy() -> FACT:
    return FACT(
        statut="f",
        regles=(EXCLUS("RESULTAT", "DEPL"), EXCLUS("RESULTAT", "VITE")),
        RESULTAT=SIMP(statut="f", typ="tran_gene"),
        b_resu=BLOC(
            condition=exists("RESULTAT"),
            regles=(EXCLUS("NUME_ORDRE", "INST_INIT"),),
            INST_INIT=SIMP(statut="f", typ="R"),
            NUME_ORDRE=SIMP(statut="f", typ="I"),
            CRITERE=SIMP(statut="f", typ="TXM", into=("RELATIF", "ABSOLU")),
            PRECISION=SIMP(statut="f", typ="R"),
        ),
        DEPL=SIMP(statut="f", typ="vect_asse_gene"),
        VITE=SIMP(statut="f", typ="vect_asse_gene"),
    )


def archivage_legacy() -> FACT:
    return FACT(
        statut="f",
        max=1,
        regles=(EXCLUS("PAS_ARCH", "LIST_INST", "INST", "LIST_ARCH"),),
        LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
        INST=SIMP(statut="f", typ="R", max="**"),
        PAS_ARCH=SIMP(statut="f", typ="I"),
        LIST_ARCH=SIMP(statut="f", typ="listis_sdaster"),
        CRITERE=SIMP(statut="f", typ="TXM", into=("RELATIF", "ABSOLU")),
        PRECISION=SIMP(statut="f", typ="R"),
    )


def excit_legacy() -> FACT:
    """Today's EXCIT, whose supports (MULT_APPUI) could also be mesh nodes (NOEUD)."""
    modern = _modern("b_excit_tran_mod")["EXCIT"]
    support = modern.entries["b_mult_appui"]
    entries = dict(modern.entries)
    entries["b_mult_appui"] = BLOC(
        condition=support.condition,
        regles=support.rules + (EXCLUS("NOEUD", "GROUP_NO"),),
        **support.entries,
        NOEUD=SIMP(statut="f", typ="no", max="**"),
    )
    return FACT(statut=modern.statut, max=modern.max, regles=modern.rules, **entries)


# COMPORTEMENT block of each legacy nonlinearity family (catalogues.common_post)
FAMILY_BLOCS = {
    "DIS_CHOC": "b_choc",
    "FLAMBAGE": "b_buckling",
    "ANTI_SISM": "b_antisism",
    "DIS_VISC": "b_disvisc",
    "ROTOR_FISS": "b_rotor",
    "RELA_EFFO_DEPL": "b_refx",
    "RELA_EFFO_VITE": "b_refv",
}


def _family(relation: str, *, drop=(), renames=None, **extra) -> FACT:
    """A legacy nonlinearity factor keyword made from today's COMPORTEMENT block
    of ``relation``: the same keywords and rules, less ``drop``, with keywords
    renamed back to their legacy names (``renames``: modern -> legacy) and
    ``extra`` legacy-only entries. Defaults do not matter here: a legacy call
    is validated as written, then translated and validated by DYNA_VIBRA."""
    bloc = comportement_dyna().entries[FAMILY_BLOCS[relation]]
    renames = renames or {}
    entries = {
        renames.get(name, name): entry for name, entry in bloc.entries.items() if name not in drop
    }
    return FACT(statut="f", max="**", regles=bloc.rules, **entries, **extra)


def choc_legacy() -> FACT:
    """CHOC: one shock (node against obstacle, or node against node), with the
    fluid film keywords code_aster 17 dropped (LAME_FLUIDE, ALPHA, BETA, CHI,
    DELTA: kept by today's DIS_CHOC block as a hidden asterlite extension)."""
    return _family("DIS_CHOC")


def flambage_legacy() -> FACT:
    """FLAMBAGE: a shock support that buckles, with the scalar law of code_aster
    10-14 (FNOR_CRIT...) or today's functions of the crushing."""
    return _family(
        "FLAMBAGE",
        # today's block: the functions, or code_aster 15's scalar law (hidden)
        drop=("FX", "RIGI_NOR", "AMOR_NOR", "FNOR_CRIT", "b_crushing_functions", "b_scalar_law"),
        RIGI_NOR=SIMP(statut="f", typ=("R", "fonction_sdaster")),
        FNOR_CRIT=SIMP(statut="f", typ="R"),
        FNOR_POST_FL=SIMP(statut="f", typ="R"),
        RIGI_NOR_POST_FL=SIMP(statut="f", typ="R"),
        FX=SIMP(statut="f", typ="fonction_sdaster"),
        AMOR_NOR=SIMP(statut="f", typ="fonction_sdaster"),
    )


def nonlinearities_legacy() -> dict:
    """The factor keywords of localized nonlinearities before COMPORTEMENT."""
    return dict(
        CHOC=choc_legacy(),
        VERI_CHOC=_modern("b_excit_tran_mod")["VERI_CHOC"],
        FLAMBAGE=flambage_legacy(),
        ANTI_SISM=_family("ANTI_SISM"),
        DIS_VISC=_family("DIS_VISC", renames={"RESI_INTE": "RESI_INTE_RELA"}),
        ROTOR_FISS=_family("ROTOR_FISS"),
        RELA_EFFO_DEPL=_family("RELA_EFFO_DEPL", renames={"FONCTION": "RELATION"}),
        RELA_EFFO_VITE=_family("RELA_EFFO_VITE", renames={"FONCTION": "RELATION"}),
    )


def gene_transient_legacy() -> dict:
    """Keywords common to DYNA_TRAN_MODAL and the legacy DYNA_VIBRA (GENE, TRAN)."""
    return dict(
        # matrices, modal damping, rotation speed: as today
        **{k: v for k, v in _modern("b_matr_tran_gene").items() if k not in MATRICES},
        SCHEMA_TEMPS=schema_temps_legacy(),
        ETAT_INIT=etat_init_legacy(),
        INCREMENT=increment_legacy(),
        ARCHIVAGE=archivage_legacy(),
        EXCIT=excit_legacy(),
        **{k: _modern("b_excit_tran_mod")[k] for k in ("MODE_STAT", "MODE_CORR", "EXCIT_RESU")},
        **nonlinearities_legacy(),
        PARA_LAME_FLUI=para_lame_flui(),
        IMPRESSION=_modern("b_impression")["IMPRESSION"],
        SOLVEUR=_modern("b_sol_tran_gene")["SOLVEUR"],
        INFO=SIMP(statut="f", typ="I", into=(1, 2)),
        TITRE=SIMP(statut="f", typ="TXM", max="**"),
    )


DYNA_VIBRA_V13 = OPER(
    nom="DYNA_VIBRA",
    sd_prod="tran_gene",
    reentrant="f",
    fr="DYNA_VIBRA of code_aster 13-14, before COMPORTEMENT (generalized transient)",
    regles=(EXCLUS("AMOR_MODAL", "MATR_AMOR"), PRESENT_ABSENT("MODE_STAT", "MODE_CORR")),
    BASE_CALCUL=SIMP(statut="o", typ="TXM", into=("GENE",)),
    TYPE_CALCUL=SIMP(statut="o", typ="TXM", into=("TRAN",)),
    MATR_MASS=SIMP(statut="o", typ="matr_asse_gene_r"),
    MATR_RIGI=SIMP(statut="o", typ="matr_asse_gene_r"),
    **gene_transient_legacy(),
)
