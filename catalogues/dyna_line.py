"""DYNA_LINE: linear transient or harmonic response, solved on a physical or modal basis.

Like code_aster 17, the result is a physical result (dyna_trans for TRAN,
dyna_harmo for HARM); with BASE_CALCUL='GENE' the modal basis and the
generalised result may also be kept through BASE_RESU=CO(...) (mode_meca)
and RESU_GENE=CO(...) (tran_gene or harm_gene). The soil-structure (ISS)
and fluid-structure (IFS) variants are not described.
"""

from asterlite.catalogues.common import C_SOLVEUR, OUI_NON, critere_precision, group_no
from asterlite.catalogues.common_post import comportement_dyna

from asterlite.catalog import (
    AU_MOINS_UN,
    BLOC,
    EXCLUS,
    FACT,
    MACRO,
    PRESENT_ABSENT,
    PRESENT_PRESENT,
    SIMP,
    UN_PARMI,
    absent,
    equal_to,
    exists,
    is_in,
)
from asterlite.lang.values import CO

FONCTION = ("fonction_sdaster", "nappe_sdaster", "formule")
TRAN = equal_to("TYPE_CALCUL", "TRAN")
HARM = equal_to("TYPE_CALCUL", "HARM")
GENE = equal_to("BASE_CALCUL", "GENE")
PHYS = equal_to("BASE_CALCUL", "PHYS")
SCHEMAS = (
    "NEWMARK", "WILSON", "DIFF_CENTRE", "DEVOGE", "ADAPT_ORDRE1", "ADAPT_ORDRE2",
    "RUNGE_KUTTA_32", "RUNGE_KUTTA_54", "ITMI",
)  # fmt: skip


def _sdprod(kw) -> str:
    harmonic = kw.get("TYPE_CALCUL") == "HARM"
    # the CO outputs, typed as code_aster's dyna_line_sdprod does
    if isinstance(kw.get("BASE_RESU"), CO):
        kw.get("BASE_RESU").produced_type = "mode_meca"
    if isinstance(kw.get("RESU_GENE"), CO):
        kw.get("RESU_GENE").produced_type = "harm_gene" if harmonic else "tran_gene"
    return "dyna_harmo" if harmonic else "dyna_trans"


def _archivage(with_exclusions: bool) -> FACT:
    extra = {}
    if with_exclusions:
        extra = dict(
            b_list_inst=BLOC(condition=exists("LIST_INST") | exists("INST"), **critere_precision()),
            CHAM_EXCLU=SIMP(statut="f", typ="TXM", max=2, into=("DEPL", "VITE", "ACCE")),
        )
    return FACT(
        statut="f",
        regles=(EXCLUS("LIST_INST", "INST"), AU_MOINS_UN("LIST_INST", "INST", "PAS_ARCH")),
        PAS_ARCH=SIMP(statut="f", typ="I"),
        LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
        INST=SIMP(statut="f", typ="R", max="**"),
        **extra,
    )


def _support_motion(group_no_statut: str = "f") -> dict:
    return dict(
        regles=(PRESENT_PRESENT("ACCE", "VITE", "DEPL"), PRESENT_ABSENT("ACCE", "FONC_MULT")),
        DIRECTION=SIMP(statut="o", typ="R", max=6),
        GROUP_NO=group_no(group_no_statut),
        FONC_MULT=SIMP(statut="f", typ=FONCTION),
        ACCE=SIMP(statut="f", typ=FONCTION),
        VITE=SIMP(statut="f", typ=FONCTION),
        DEPL=SIMP(statut="f", typ=FONCTION),
    )


def _static_enrichment() -> dict:
    return dict(
        ENRI_STAT=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="OUI"),
        b_param_enri_stat=BLOC(
            condition=equal_to("ENRI_STAT", "OUI"),
            ORTHO=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="NON"),
            FREQ_COUP_STAT=SIMP(statut="f", typ="R"),
        ),
    )


def _rayleigh_vnor(**extra) -> BLOC:
    return BLOC(
        condition=equal_to("TYPE_AMOR", "RAYLEIGH"),
        VNOR=SIMP(statut="f", typ="R", into=(1.0, -1.0), defaut=1.0),
        **extra,
    )


DYNA_LINE = MACRO(
    nom="DYNA_LINE",
    sd_prod=_sdprod,
    reentrant="n",
    fr="Linear transient or harmonic dynamic response",
    TYPE_CALCUL=SIMP(statut="o", typ="TXM", into=("HARM", "TRAN")),
    BASE_CALCUL=SIMP(statut="o", typ="TXM", into=("PHYS", "GENE")),
    MODELE=SIMP(statut="o", typ="modele_sdaster"),
    CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
    CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
    CHARGE=SIMP(statut="f", typ=("char_meca", "char_cine_meca"), max="**"),
    BANDE_ANALYSE=SIMP(
        statut="f", typ="R", min=1, max=2, fr="Frequency band (max, or min and max)"
    ),
    PCENT_COUP=SIMP(statut="f", typ="I", val_min=80, val_max=100, defaut=90),
    b_param_gene=BLOC(
        condition=GENE,
        BASE_RESU=SIMP(statut="f", typ="CO", fr="Keep the modal basis (mode_meca)"),
        RESU_GENE=SIMP(statut="f", typ="CO", fr="Keep the generalised result"),
    ),
    b_param_harm=BLOC(
        condition=HARM,
        regles=(UN_PARMI("FREQ", "LIST_FREQ"),),
        FREQ=SIMP(statut="f", typ="R", max="**"),
        LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
    ),
    b_param_tran=BLOC(
        condition=TRAN,
        SCHEMA_TEMPS=FACT(
            statut="d",
            SCHEMA=SIMP(statut="f", typ="TXM", defaut="DEVOGE", into=SCHEMAS),
            b_newmark=BLOC(
                condition=equal_to("SCHEMA", "NEWMARK"),
                BETA=SIMP(statut="f", typ="R", defaut=0.25),
                GAMMA=SIMP(statut="f", typ="R", defaut=0.5),
            ),
            b_wilson=BLOC(
                condition=equal_to("SCHEMA", "WILSON"), THETA=SIMP(statut="f", typ="R", defaut=1.4)
            ),
            b_rk_devo=BLOC(
                condition=is_in("SCHEMA", ("RUNGE_KUTTA_54", "RUNGE_KUTTA_32", "DEVOGE")),
                TOLERANCE=SIMP(statut="f", typ="R", defaut=1.0e-5),
                ALPHA=SIMP(statut="f", typ="R", defaut=0.0),
            ),
            b_adapt_ord=BLOC(
                condition=is_in("SCHEMA", ("ADAPT_ORDRE1", "ADAPT_ORDRE2")),
                VITE_MIN=SIMP(statut="f", typ="TXM", defaut="NORM", into=("MAXI", "NORM")),
                COEF_MULT_PAS=SIMP(statut="f", typ="R", defaut=1.1),
                COEF_DIVI_PAS=SIMP(statut="f", typ="R", defaut=1.3333334),
                PAS_LIMI_RELA=SIMP(statut="f", typ="R", defaut=1.0e-6),
                NB_POIN_PERIODE=SIMP(statut="f", typ="I", defaut=50),
            ),
            b_alladapt=BLOC(
                condition=is_in(
                    "SCHEMA",
                    ("RUNGE_KUTTA_54", "RUNGE_KUTTA_32", "DEVOGE", "ADAPT_ORDRE1", "ADAPT_ORDRE2"),
                ),
                PAS_MINI=SIMP(statut="f", typ="R"),
                PAS_MAXI=SIMP(statut="f", typ="R"),
                NMAX_ITER_PAS=SIMP(statut="f", typ="I", defaut=16),
            ),
        ),
        INCREMENT=FACT(
            statut="o",
            INST_INIT=SIMP(statut="f", typ="R"),
            PAS=SIMP(statut="f", typ="R"),
            INST_FIN=SIMP(statut="o", typ="R"),
        ),
    ),
    b_dlt_prec=BLOC(condition=PHYS & TRAN, ARCHIVAGE=_archivage(with_exclusions=True)),
    b_not_dlt_prec=BLOC(condition=~PHYS & TRAN, ARCHIVAGE=_archivage(with_exclusions=False)),
    b_excit_line_tran=BLOC(
        condition=TRAN,
        regles=(AU_MOINS_UN("ETAT_INIT", "EXCIT"),),
        ETAT_INIT=FACT(
            statut="f",
            DEPL=SIMP(statut="f", typ="cham_no_sdaster"),
            VITE=SIMP(statut="f", typ="cham_no_sdaster"),
        ),
        EXCIT=FACT(
            statut="f",
            max="**",
            TYPE_APPUI=SIMP(statut="f", typ="TXM", into=("MONO", "MULTI")),
            b_no_appui=BLOC(
                condition=absent("TYPE_APPUI"),
                CHARGE=SIMP(statut="o", typ="char_meca"),
                FONC_MULT=SIMP(statut="o", typ=FONCTION),
            ),
            b_mult_mono=BLOC(condition=equal_to("TYPE_APPUI", "MONO"), **_support_motion()),
            b_mult_appui=BLOC(condition=equal_to("TYPE_APPUI", "MULTI"), **_support_motion()),
        ),
    ),
    b_excit_line_harm=BLOC(
        condition=HARM,
        EXCIT=FACT(
            statut="o",
            max="**",
            regles=(UN_PARMI("FONC_MULT", "FONC_MULT_C", "COEF_MULT", "COEF_MULT_C"),),
            TYPE_APPUI=SIMP(statut="f", typ="TXM", into=("MONO", "MULTI")),
            FONC_MULT_C=SIMP(statut="f", typ=("fonction_c", "formule_c")),
            COEF_MULT_C=SIMP(statut="f", typ="C"),
            FONC_MULT=SIMP(statut="f", typ=FONCTION),
            COEF_MULT=SIMP(statut="f", typ="R"),
            PHAS_DEG=SIMP(statut="f", typ="R", defaut=0.0),
            PUIS_PULS=SIMP(statut="f", typ="I", defaut=0),
            b_no_appui=BLOC(
                condition=absent("TYPE_APPUI"), CHARGE=SIMP(statut="o", typ="char_meca")
            ),
            b_mult_mono=BLOC(
                condition=equal_to("TYPE_APPUI", "MONO"),
                DIRECTION=SIMP(statut="o", typ="R", max=6),
                GROUP_NO=group_no(),
            ),
            b_mult_appui=BLOC(
                condition=equal_to("TYPE_APPUI", "MULTI"),
                DIRECTION=SIMP(statut="o", typ="R", max=6),
                GROUP_NO=group_no("o"),
            ),
        ),
    ),
    b_amor_tran_phys=BLOC(
        condition=TRAN & PHYS,
        AMORTISSEMENT=FACT(
            statut="f",
            TYPE_AMOR=SIMP(statut="o", typ="TXM", into=("RAYLEIGH",)),
            VNOR=SIMP(statut="f", typ="R", into=(1.0, -1.0), defaut=1.0),
        ),
    ),
    b_amor_harm_phys=BLOC(
        condition=HARM & PHYS,
        AMORTISSEMENT=FACT(
            statut="f",
            TYPE_AMOR=SIMP(statut="o", typ="TXM", into=("RAYLEIGH", "HYST")),
            b_amor_flui_abso=_rayleigh_vnor(
                MATR_IMPE_PHI=SIMP(statut="f", typ="TXM", defaut="NON", into=OUI_NON)
            ),
        ),
    ),
    b_amor_tran_gene=BLOC(
        condition=TRAN & GENE,
        AMORTISSEMENT=FACT(
            statut="f",
            TYPE_AMOR=SIMP(statut="o", typ="TXM", into=("RAYLEIGH", "MODAL")),
            b_modal=BLOC(
                condition=equal_to("TYPE_AMOR", "MODAL"),
                AMOR_REDUIT=SIMP(statut="o", typ="R", max="**"),
            ),
            b_amor_flui_abso=_rayleigh_vnor(),
        ),
    ),
    b_amor_harm_gene=BLOC(
        condition=HARM & GENE,
        AMORTISSEMENT=FACT(
            statut="f",
            TYPE_AMOR=SIMP(statut="o", typ="TXM", into=("RAYLEIGH", "MODAL", "HYST")),
            b_modal=BLOC(
                condition=equal_to("TYPE_AMOR", "MODAL"),
                AMOR_REDUIT=SIMP(statut="o", typ="R", max="**"),
            ),
            b_amor_flui_abso=_rayleigh_vnor(
                MATR_IMPE_PHI=SIMP(statut="f", typ="TXM", defaut="NON", into=OUI_NON)
            ),
        ),
    ),
    b_harm_phys=BLOC(condition=PHYS & HARM, SOLVEUR=C_SOLVEUR("DYNA_LINE_HARM")),
    b_tran_phys=BLOC(condition=PHYS & TRAN, SOLVEUR=C_SOLVEUR("DYNA_LINE_TRAN")),
    b_harm_gene=BLOC(
        condition=HARM & GENE, SOLVEUR=C_SOLVEUR("DYNA_TRAN_MODAL"), **_static_enrichment()
    ),
    b_tran_gene=BLOC(
        condition=TRAN & GENE,
        SOLVEUR=C_SOLVEUR("DYNA_TRAN_MODAL"),
        COMPORTEMENT=comportement_dyna(),
        **_static_enrichment(),
    ),
)
