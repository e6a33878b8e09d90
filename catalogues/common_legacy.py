"""Keyword definitions of code_aster 10 to 14 for generalized transients.

Shared by the legacy catalogues (DYNA_TRAN_MODAL) and by the legacy form of
DYNA_VIBRA (``DYNA_VIBRA_V13``, before COMPORTEMENT): a legacy call is
checked as written against these, then translated (``asterlite.legacy``)
and checked again against the modern catalogue.
"""

from asterlite.catalogues.common_post import FONCTION_OU_FORMULE, solveur

from asterlite.catalog import (
    BLOC,
    ENSEMBLE,
    EXCLUS,
    FACT,
    OPER,
    PRESENT_ABSENT,
    PRESENT_PRESENT,
    SIMP,
    UN_PARMI,
    equal_to,
    exists,
)

LEGACY_SCHEMES = (
    "NEWMARK", "EULER", "DEVOGE", "ADAPT", "ADAPT_ORDRE1", "ADAPT_ORDRE2", "ITMI",
    "RUNGE_KUTTA_54", "RUNGE_KUTTA_32", "DIFF_CENTRE", "WILSON",
)  # fmt: skip
FUNCTION = FONCTION_OU_FORMULE


def _ends() -> dict:
    """NOEUD_1/GROUP_NO_1 and NOEUD_2/GROUP_NO_2 as the legacy catalogues wrote them."""
    return dict(
        NOEUD_1=SIMP(statut="f", typ="no"),
        NOEUD_2=SIMP(statut="f", typ="no"),
        GROUP_NO_1=SIMP(statut="f", typ="grno"),
        GROUP_NO_2=SIMP(statut="f", typ="grno"),
    )


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
    """INCREMENT with the adaptive-step controls that later moved to SCHEMA_TEMPS."""
    return FACT(
        statut="o",
        max="**",
        regles=(UN_PARMI("LIST_INST", "PAS"),),
        LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
        b_list_inst=BLOC(
            condition=exists("LIST_INST"),
            regles=(EXCLUS("NUME_FIN", "INST_FIN"),),
            NUME_FIN=SIMP(statut="f", typ="I"),
            INST_FIN=SIMP(statut="f", typ="R"),
        ),
        PAS=SIMP(statut="f", typ="R"),
        b_pas=BLOC(
            condition=exists("PAS"),
            INST_INIT=SIMP(statut="f", typ="R"),
            INST_FIN=SIMP(statut="o", typ="R"),
        ),
        VERI_PAS=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
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
    return FACT(
        statut="f",
        max="**",
        regles=(
            UN_PARMI("FONC_MULT", "COEF_MULT", "ACCE"),
            UN_PARMI("VECT_ASSE_GENE", "NUME_ORDRE"),
            PRESENT_PRESENT("ACCE", "VITE", "DEPL"),
            EXCLUS("MULT_APPUI", "CORR_STAT"),
            PRESENT_PRESENT("MULT_APPUI", "ACCE"),
        ),
        VECT_ASSE_GENE=SIMP(statut="f", typ="vect_asse_gene"),
        NUME_ORDRE=SIMP(statut="f", typ="I"),
        FONC_MULT=SIMP(statut="f", typ=FUNCTION),
        COEF_MULT=SIMP(statut="f", typ="R"),
        ACCE=SIMP(statut="f", typ=FUNCTION),
        VITE=SIMP(statut="f", typ=FUNCTION),
        DEPL=SIMP(statut="f", typ=FUNCTION),
        MULT_APPUI=SIMP(statut="f", typ="TXM", into=("OUI",)),
        b_mult_appui=BLOC(
            condition=equal_to("MULT_APPUI", "OUI"),
            regles=(EXCLUS("NOEUD", "GROUP_NO"),),
            DIRECTION=SIMP(statut="f", typ="R", max="**"),
            NOEUD=SIMP(statut="f", typ="no", max="**"),
            GROUP_NO=SIMP(statut="f", typ="grno", max="**"),
        ),
        CORR_STAT=SIMP(statut="f", typ="TXM", into=("OUI",)),
        b_corr_stat=BLOC(
            condition=equal_to("CORR_STAT", "OUI"),
            D_FONC_DT=SIMP(statut="o", typ=FUNCTION),
            D_FONC_DT2=SIMP(statut="o", typ=FUNCTION),
        ),
    )


def choc_legacy() -> FACT:
    """CHOC: one shock (node against obstacle, or node against node)."""
    return FACT(
        statut="f",
        max="**",
        regles=(
            UN_PARMI("MAILLE", "GROUP_MA", "NOEUD_1", "GROUP_NO_1"),
            EXCLUS("NOEUD_2", "GROUP_NO_2"),
            PRESENT_ABSENT("GROUP_MA", "NOEUD_2", "GROUP_NO_2"),
            PRESENT_ABSENT("MAILLE", "NOEUD_2", "GROUP_NO_2"),
        ),
        INTITULE=SIMP(statut="f", typ="TXM"),
        GROUP_MA=SIMP(statut="f", typ="grma", max="**"),
        MAILLE=SIMP(statut="f", typ="ma", max="**"),
        **_ends(),
        OBSTACLE=SIMP(statut="o", typ="table_fonction"),
        ORIG_OBST=SIMP(statut="f", typ="R", min=3, max=3),
        NORM_OBST=SIMP(statut="o", typ="R", min=3, max=3),
        ANGL_VRIL=SIMP(statut="f", typ="R"),
        JEU=SIMP(statut="f", typ="R"),
        DIST_1=SIMP(statut="f", typ="R", val_min=0.0),
        DIST_2=SIMP(statut="f", typ="R", val_min=0.0),
        SOUS_STRUC_1=SIMP(statut="f", typ="TXM"),
        SOUS_STRUC_2=SIMP(statut="f", typ="TXM"),
        REPERE=SIMP(statut="f", typ="TXM"),
        RIGI_NOR=SIMP(statut="f", typ="R"),
        AMOR_NOR=SIMP(statut="f", typ="R"),
        RIGI_TAN=SIMP(statut="f", typ="R"),
        AMOR_TAN=SIMP(statut="f", typ="R"),
        FROTTEMENT=SIMP(statut="f", typ="TXM", into=("NON", "COULOMB", "COULOMB_STAT_DYNA")),
        b_coulomb=BLOC(
            condition=equal_to("FROTTEMENT", "COULOMB"), COULOMB=SIMP(statut="o", typ="R")
        ),
        b_coulomb_stat_dyna=BLOC(
            condition=equal_to("FROTTEMENT", "COULOMB_STAT_DYNA"),
            COULOMB_STAT=SIMP(statut="o", typ="R"),
            COULOMB_DYNA=SIMP(statut="o", typ="R"),
        ),
        LAME_FLUIDE=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
        b_lame=BLOC(
            condition=equal_to("LAME_FLUIDE", "OUI"),
            ALPHA=SIMP(statut="o", typ="R"),
            BETA=SIMP(statut="o", typ="R"),
            CHI=SIMP(statut="o", typ="R"),
            DELTA=SIMP(statut="o", typ="R"),
        ),
    )


def flambage_legacy() -> FACT:
    """FLAMBAGE: a shock support that buckles (scalar or function description)."""
    return FACT(
        statut="f",
        max="**",
        regles=(UN_PARMI("NOEUD_1", "GROUP_NO_1"), EXCLUS("NOEUD_2", "GROUP_NO_2")),
        INTITULE=SIMP(statut="f", typ="TXM"),
        **_ends(),
        OBSTACLE=SIMP(statut="o", typ="table_fonction"),
        ORIG_OBST=SIMP(statut="f", typ="R", max="**"),
        NORM_OBST=SIMP(statut="o", typ="R", max="**"),
        ANGL_VRIL=SIMP(statut="f", typ="R"),
        JEU=SIMP(statut="f", typ="R"),
        DIST_1=SIMP(statut="f", typ="R"),
        DIST_2=SIMP(statut="f", typ="R"),
        REPERE=SIMP(statut="f", typ="TXM"),
        RIGI_NOR=SIMP(statut="f", typ=("R", "fonction_sdaster")),
        FNOR_CRIT=SIMP(statut="f", typ="R"),
        FNOR_POST_FL=SIMP(statut="f", typ="R"),
        RIGI_NOR_POST_FL=SIMP(statut="f", typ="R"),
        FX=SIMP(statut="f", typ="fonction_sdaster"),
        AMOR_NOR=SIMP(statut="f", typ="fonction_sdaster"),
        CRIT_AMOR=SIMP(statut="f", typ="TXM", into=("INCLUS", "EXCLUS")),
    )


def anti_sism_legacy() -> FACT:
    return FACT(
        statut="f",
        max="**",
        regles=(UN_PARMI("NOEUD_1", "GROUP_NO_1"), UN_PARMI("NOEUD_2", "GROUP_NO_2")),
        **_ends(),
        RIGI_K1=SIMP(statut="f", typ="R"),
        RIGI_K2=SIMP(statut="f", typ="R"),
        SEUIL_FX=SIMP(statut="f", typ="R"),
        C=SIMP(statut="f", typ="R"),
        PUIS_ALPHA=SIMP(statut="f", typ="R"),
        DX_MAX=SIMP(statut="f", typ="R"),
    )


def dis_visc_legacy() -> FACT:
    return FACT(
        statut="f",
        max="**",
        regles=(
            UN_PARMI("NOEUD_1", "GROUP_NO_1"),
            UN_PARMI("NOEUD_2", "GROUP_NO_2"),
            UN_PARMI("K1", "UNSUR_K1"),
            UN_PARMI("K2", "UNSUR_K2"),
            UN_PARMI("K3", "UNSUR_K3"),
        ),
        **_ends(),
        K1=SIMP(statut="f", typ="R"),
        K2=SIMP(statut="f", typ="R"),
        K3=SIMP(statut="f", typ="R"),
        UNSUR_K1=SIMP(statut="f", typ="R"),
        UNSUR_K2=SIMP(statut="f", typ="R"),
        UNSUR_K3=SIMP(statut="f", typ="R"),
        C=SIMP(statut="o", typ="R"),
        PUIS_ALPHA=SIMP(statut="f", typ="R"),
        ITER_INTE_MAXI=SIMP(statut="f", typ="I"),
        RESI_INTE_RELA=SIMP(statut="f", typ="R"),
    )


def rotor_fiss_legacy() -> FACT:
    return FACT(
        statut="f",
        max="**",
        regles=(
            UN_PARMI("NOEUD_D", "GROUP_NO_D"),
            EXCLUS("NOEUD_G", "GROUP_NO_G"),
            PRESENT_PRESENT("NOEUD_D", "NOEUD_G"),
            PRESENT_PRESENT("GROUP_NO_D", "GROUP_NO_G"),
        ),
        ANGL_INIT=SIMP(statut="f", typ="R"),
        ANGL_ROTA=SIMP(statut="f", typ=("fonction_sdaster", "formule")),
        NOEUD_G=SIMP(statut="f", typ="no"),
        NOEUD_D=SIMP(statut="f", typ="no"),
        GROUP_NO_G=SIMP(statut="f", typ="grno"),
        GROUP_NO_D=SIMP(statut="f", typ="grno"),
        K_PHI=SIMP(statut="o", typ=("fonction_sdaster", "formule")),
        DK_DPHI=SIMP(statut="o", typ=("fonction_sdaster", "formule")),
    )


def rela_effo_legacy() -> FACT:
    """RELA_EFFO_DEPL / RELA_EFFO_VITE: a force function of one node's component."""
    return FACT(
        statut="f",
        max="**",
        regles=(UN_PARMI("NOEUD", "GROUP_NO"),),
        NOEUD=SIMP(statut="f", typ="no"),
        GROUP_NO=SIMP(statut="f", typ="grno"),
        SOUS_STRUC=SIMP(statut="f", typ="TXM"),
        NOM_CMP=SIMP(statut="f", typ="TXM"),
        RELATION=SIMP(statut="o", typ=FUNCTION),
    )


def nonlinearities_legacy() -> dict:
    """The factor keywords of localized nonlinearities before COMPORTEMENT."""
    return dict(
        CHOC=choc_legacy(),
        VERI_CHOC=FACT(
            statut="f",
            STOP_CRITERE=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
            SEUIL=SIMP(statut="f", typ="R"),
        ),
        FLAMBAGE=flambage_legacy(),
        ANTI_SISM=anti_sism_legacy(),
        DIS_VISC=dis_visc_legacy(),
        ROTOR_FISS=rotor_fiss_legacy(),
        RELA_EFFO_DEPL=rela_effo_legacy(),
        RELA_EFFO_VITE=rela_effo_legacy(),
    )


def gene_transient_legacy() -> dict:
    """Keywords common to DYNA_TRAN_MODAL and the legacy DYNA_VIBRA (GENE, TRAN)."""
    return dict(
        MATR_AMOR=SIMP(statut="f", typ="matr_asse_gene_r"),
        VITESSE_VARIABLE=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
        b_variable=BLOC(
            condition=equal_to("VITESSE_VARIABLE", "OUI"),
            MATR_GYRO=SIMP(statut="o", typ="matr_asse_gene_r"),
            VITE_ROTA=SIMP(statut="o", typ=("fonction_sdaster", "formule")),
            MATR_RIGY=SIMP(statut="f", typ="matr_asse_gene_r"),
            ACCE_ROTA=SIMP(statut="f", typ=("fonction_sdaster", "formule")),
        ),
        b_constante=BLOC(
            condition=~equal_to("VITESSE_VARIABLE", "OUI"),
            VITE_ROTA=SIMP(statut="f", typ="R"),
        ),
        AMOR_MODAL=FACT(
            statut="f",
            max=1,
            regles=(EXCLUS("AMOR_REDUIT", "LIST_AMOR"),),
            AMOR_REDUIT=SIMP(statut="f", typ="R", max="**"),
            LIST_AMOR=SIMP(statut="f", typ="listr8_sdaster"),
        ),
        SCHEMA_TEMPS=schema_temps_legacy(),
        ETAT_INIT=etat_init_legacy(),
        INCREMENT=increment_legacy(),
        ARCHIVAGE=archivage_legacy(),
        EXCIT=excit_legacy(),
        MODE_STAT=SIMP(statut="f", typ="mode_meca"),
        MODE_CORR=SIMP(statut="f", typ=("mult_elas", "mode_meca")),
        EXCIT_RESU=FACT(
            statut="f",
            max="**",
            RESULTAT=SIMP(statut="o", typ="tran_gene"),
            COEF_MULT=SIMP(statut="f", typ="R"),
        ),
        **nonlinearities_legacy(),
        IMPRESSION=FACT(
            statut="f",
            regles=(EXCLUS("TOUT", "NIVEAU"),),
            TOUT=SIMP(statut="f", typ="TXM", into=("OUI",)),
            NIVEAU=SIMP(
                statut="f", typ="TXM", into=("DEPL_LOC", "VITE_LOC", "FORC_LOC", "TAUX_CHOC")
            ),
            INST_INIT=SIMP(statut="f", typ="R"),
            INST_FIN=SIMP(statut="f", typ="R"),
            UNITE_DIS_VISC=SIMP(statut="f", typ="I"),
        ),
        SOLVEUR=solveur("LDLT", ("MULT_FRONT", "LDLT", "MUMPS")),
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
