"""DYNA_VIBRA: transient or harmonic dynamic response, on a physical or modal basis.

The heart of asterlite is ``TYPE_CALCUL='TRAN'``, ``BASE_CALCUL='GENE'``:
explicit or adaptive time integration of the modal equations with
localized nonlinearities (``COMPORTEMENT``: shocks with friction, buckling,
anti-seismic devices, viscous dampers, cracked rotors...). The physical
basis and the harmonic forms are catalogued as in code_aster 17 so that
existing decks validate.
"""

from asterlite.catalogues.common import NO_EFFECT_STORED
from asterlite.catalogues.common_post import (
    FONCTION_OU_FORMULE,
    comportement_dyna,
    concept_is,
    observation_dyna,
    para_lame_flui,
    precision_blocs,
    solveur,
)

from asterlite.catalog import (
    AU_MOINS_UN,
    BLOC,
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
from asterlite.dynamics.schemes import SCHEMES


def dyna_vibra_type(kw) -> str:
    """dyna_trans / tran_gene for a transient, dyna_harmo / acou_harmo / harm_gene for HARM."""
    base, calcul = kw.get("BASE_CALCUL"), kw.get("TYPE_CALCUL")
    if base == "PHYS":
        if calcul == "TRAN":
            return "dyna_trans"
        if concept_is(kw.get("MATR_RIGI"), "matr_asse_pres_c"):
            return "acou_harmo"
        return "dyna_harmo"
    return "tran_gene" if calcul == "TRAN" else "harm_gene"


TRAN_GENE = equal_to("TYPE_CALCUL", "TRAN") & equal_to("BASE_CALCUL", "GENE")
TRAN_PHYS = equal_to("TYPE_CALCUL", "TRAN") & equal_to("BASE_CALCUL", "PHYS")
HARM_GENE = equal_to("TYPE_CALCUL", "HARM") & equal_to("BASE_CALCUL", "GENE")
HARM_PHYS = equal_to("TYPE_CALCUL", "HARM") & equal_to("BASE_CALCUL", "PHYS")

# SCHEMA_TEMPS/SCHEMA when the deck gives none (code_aster 17's GENE default)
GENE_DEFAULT_SCHEME = "RUNGE_KUTTA_32"
ADAPTIVE = ("RUNGE_KUTTA_54", "RUNGE_KUTTA_32", "DEVOGE", "ADAPT_ORDRE1", "ADAPT_ORDRE2")
# code_aster 17's GENE schemes (the language; ITMI is refused by name), then the
# schemes asterlite adds (asterlite.dynamics.schemes: EULER, for code_aster 10's
# METHODE='EULER' in legacy decks)
GENE_SCHEMES = (
    "NEWMARK",
    "DIFF_CENTRE",
    "DEVOGE",
    "ADAPT_ORDRE1",
    "ADAPT_ORDRE2",
    "RUNGE_KUTTA_32",
    "RUNGE_KUTTA_54",
    "ITMI",
    "TRBDF2",
)
GENE_SCHEMES += tuple(name for name in SCHEMES if name not in GENE_SCHEMES)


def schema_temps(default: str, schemes: tuple[str, ...]) -> FACT:
    """SCHEMA_TEMPS: the integration scheme and the parameters of each family."""
    entries = dict(
        SCHEMA=SIMP(statut="f", typ="TXM", defaut=default, into=schemes),
        b_newmark=BLOC(
            condition=equal_to("SCHEMA", "NEWMARK"),
            BETA=SIMP(statut="f", typ="R", defaut=0.25),
            GAMMA=SIMP(statut="f", typ="R", defaut=0.5),
        ),
        b_rk_devo=BLOC(
            condition=equal_to("SCHEMA", ("RUNGE_KUTTA_54", "RUNGE_KUTTA_32", "DEVOGE")),
            TOLERANCE=SIMP(statut="f", typ="R", defaut=1.0e-5),
            ALPHA=SIMP(statut="f", typ="R", defaut=0.0),
        ),
        b_adapt_ord=BLOC(
            condition=equal_to("SCHEMA", ("ADAPT_ORDRE1", "ADAPT_ORDRE2")),
            VITE_MIN=SIMP(statut="f", typ="TXM", defaut="NORM", into=("MAXI", "NORM")),
            COEF_MULT_PAS=SIMP(statut="f", typ="R", defaut=1.1),
            COEF_DIVI_PAS=SIMP(statut="f", typ="R", defaut=1.3333334),
            PAS_LIMI_RELA=SIMP(statut="f", typ="R", defaut=1.0e-6, val_min=0.0),
            NB_POIN_PERIODE=SIMP(statut="f", typ="I", defaut=50),
        ),
        b_alladapt=BLOC(
            condition=equal_to("SCHEMA", ADAPTIVE),
            PAS_MINI=SIMP(statut="f", typ="R", val_min=1e-16),
            PAS_MAXI=SIMP(statut="f", typ="R", val_min=1e-16),
            NMAX_ITER_PAS=SIMP(statut="f", typ="I", defaut=16, val_min=0),
        ),
    )
    if "WILSON" in schemes:
        entries["b_wilson"] = BLOC(
            condition=equal_to("SCHEMA", "WILSON"), THETA=SIMP(statut="f", typ="R", defaut=1.4)
        )
    return FACT(statut="d", fr="Time integration scheme", **entries)


def etat_init(result_type: str, field_type: str, physical: bool) -> FACT:
    """ETAT_INIT: start from a previous result or from given displacement/velocity fields."""
    if physical:
        rules = (
            AU_MOINS_UN("RESULTAT", "DEPL", "VITE", "ACCE"),
            PRESENT_ABSENT("RESULTAT", "DEPL", "VITE", "ACCE"),
        )
    else:
        rules = (EXCLUS("RESULTAT", "DEPL"), EXCLUS("RESULTAT", "VITE"))
    fields = dict(
        DEPL=SIMP(statut="f", typ=field_type),
        VITE=SIMP(statut="f", typ=field_type),
    )
    if physical:
        fields["ACCE"] = SIMP(statut="f", typ=field_type)
    return FACT(
        statut="f",
        max=1,
        fr="Initial state",
        regles=rules,
        RESULTAT=SIMP(statut="f", typ=result_type),
        b_resu=BLOC(
            condition=exists("RESULTAT"),
            regles=(EXCLUS("NUME_ORDRE", "INST_INIT"),),
            NUME_ORDRE=SIMP(statut="f", typ="I"),
            INST_INIT=SIMP(statut="f", typ="R"),
            b_inst_init=BLOC(condition=exists("INST_INIT"), **precision_blocs()),
        ),
        **fields,
    )


def amor_modal(**extra) -> FACT:
    """AMOR_MODAL: reduced modal damping ratios, as values or as a list."""
    return FACT(
        statut="f",
        fr="Modal damping ratios",
        regles=(EXCLUS("AMOR_REDUIT", "LIST_AMOR"),),
        AMOR_REDUIT=SIMP(statut="f", typ="R", max="**"),
        LIST_AMOR=SIMP(statut="f", typ="listr8_sdaster"),
        **extra,
    )


def excit_harm(gene: bool) -> FACT:
    """EXCIT of a harmonic calculation: a load or vector times a (complex) coefficient."""
    if gene:
        load = dict(VECT_ASSE_GENE=SIMP(statut="o", typ="vect_asse_gene"))
        rules = ()
    else:
        load = dict(
            VECT_ASSE=SIMP(statut="f", typ="cham_no_sdaster"),
            CHARGE=SIMP(statut="f", typ=("char_meca", "char_cine_meca")),
        )
        rules = (UN_PARMI("VECT_ASSE", "CHARGE"),)
    return FACT(
        statut="f",
        max="**",
        regles=rules + (UN_PARMI("FONC_MULT", "FONC_MULT_C", "COEF_MULT", "COEF_MULT_C"),),
        **load,
        FONC_MULT_C=SIMP(statut="f", typ=("fonction_c", "formule_c")),
        COEF_MULT_C=SIMP(statut="f", typ="C"),
        FONC_MULT=SIMP(statut="f", typ=FONCTION_OU_FORMULE),
        COEF_MULT=SIMP(statut="f", typ="R"),
        PHAS_DEG=SIMP(statut="f", typ="R", defaut=0.0),
        PUIS_PULS=SIMP(statut="f", typ="I", defaut=0),
    )


DYNA_VIBRA = OPER(
    nom="DYNA_VIBRA",
    sd_prod=dyna_vibra_type,
    reentrant="f",
    fr="Transient or harmonic dynamic response on a physical or modal (generalized) basis",
    BASE_CALCUL=SIMP(statut="o", typ="TXM", into=("PHYS", "GENE")),
    TYPE_CALCUL=SIMP(statut="o", typ="TXM", into=("HARM", "TRAN")),
    # ---------------------------------------------------------------- physical model
    b_phys_model=BLOC(
        condition=equal_to("BASE_CALCUL", "PHYS"),
        MODELE=SIMP(statut="f", typ="modele_sdaster", no_effect=NO_EFFECT_STORED),
        CHAM_MATER=SIMP(statut="f", typ="cham_mater", no_effect=NO_EFFECT_STORED),
        CARA_ELEM=SIMP(statut="f", typ="cara_elem", no_effect=NO_EFFECT_STORED),
    ),
    # ---------------------------------------------------------------- matrices
    b_matr_tran_phys=BLOC(
        condition=TRAN_PHYS,
        MATR_MASS=SIMP(statut="o", typ="matr_asse_depl_r"),
        MATR_RIGI=SIMP(statut="o", typ="matr_asse_depl_r"),
        MATR_AMOR=SIMP(statut="f", typ="matr_asse_depl_r"),
        OBSERVATION=observation_dyna(),
        AMOR_MODAL=amor_modal(
            MODE_MECA=SIMP(statut="o", typ="mode_meca"),
            NB_MODE=SIMP(statut="f", typ="I"),
        ),
    ),
    b_matr_tran_gene=BLOC(
        condition=TRAN_GENE,
        regles=(EXCLUS("AMOR_MODAL", "MATR_AMOR"),),
        MATR_MASS=SIMP(statut="o", typ="matr_asse_gene_r"),
        MATR_RIGI=SIMP(statut="o", typ="matr_asse_gene_r"),
        MATR_AMOR=SIMP(statut="f", typ="matr_asse_gene_r"),
        AMOR_MODAL=amor_modal(),
        # rotating machinery: gyroscopic terms at constant or variable speed
        VITESSE_VARIABLE=SIMP(statut="f", typ="TXM", defaut="NON", into=("OUI", "NON")),
        b_variable=BLOC(
            condition=equal_to("VITESSE_VARIABLE", "OUI"),
            MATR_GYRO=SIMP(statut="o", typ="matr_asse_gene_r"),
            VITE_ROTA=SIMP(statut="o", typ=("fonction_sdaster", "formule")),
            MATR_RIGY=SIMP(statut="f", typ="matr_asse_gene_r"),
            ACCE_ROTA=SIMP(statut="f", typ=("fonction_sdaster", "formule")),
        ),
        b_constante=BLOC(
            condition=equal_to("VITESSE_VARIABLE", "NON"),
            VITE_ROTA=SIMP(statut="f", typ="R", defaut=0.0),
        ),
    ),
    b_matr_harm_phys=BLOC(
        condition=HARM_PHYS,
        regles=(EXCLUS("AMOR_MODAL", "MATR_AMOR"),),
        MATR_MASS=SIMP(statut="o", typ=("matr_asse_depl_r", "matr_asse_pres_c")),
        MATR_RIGI=SIMP(
            statut="o", typ=("matr_asse_depl_r", "matr_asse_depl_c", "matr_asse_pres_c")
        ),
        MATR_AMOR=SIMP(statut="f", typ=("matr_asse_depl_r", "matr_asse_pres_c")),
        MATR_IMPE_PHI=SIMP(statut="f", typ="matr_asse_depl_r"),
        AMOR_MODAL=amor_modal(),
        b_amor_flui=BLOC(
            condition=exists("MATR_AMOR") & exists("MATR_IMPE_PHI"),
            AMOR_FLUI=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
        ),
    ),
    b_matr_harm_gene=BLOC(
        condition=HARM_GENE,
        MATR_MASS=SIMP(statut="o", typ="matr_asse_gene_r"),
        MATR_RIGI=SIMP(statut="o", typ=("matr_asse_gene_r", "matr_asse_gene_c")),
        MATR_AMOR=SIMP(statut="f", typ="matr_asse_gene_r"),
        MATR_IMPE_PHI=SIMP(statut="f", typ="matr_asse_gene_r"),
        AMOR_MODAL=amor_modal(),
        b_amor_flui=BLOC(
            condition=exists("MATR_AMOR") & exists("MATR_IMPE_PHI"),
            AMOR_FLUI=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
        ),
    ),
    RESULTAT=SIMP(statut="f", typ=("dyna_harmo", "harm_gene")),
    # ---------------------------------------------------------------- harmonic parameters
    b_param_harm=BLOC(
        condition=equal_to("TYPE_CALCUL", "HARM"),
        regles=(UN_PARMI("FREQ", "LIST_FREQ"), EXCLUS("NOM_CHAM", "TOUT_CHAM")),
        FREQ=SIMP(statut="f", typ="R", max="**"),
        LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
        NOM_CHAM=SIMP(statut="f", typ="TXM", max=3, into=("DEPL", "VITE", "ACCE")),
        TOUT_CHAM=SIMP(statut="f", typ="TXM", into=("OUI",)),
    ),
    # ---------------------------------------------------------------- transient parameters
    b_schema_gene=BLOC(
        condition=TRAN_GENE,
        SCHEMA_TEMPS=schema_temps(GENE_DEFAULT_SCHEME, GENE_SCHEMES),
    ),
    b_schema_phys=BLOC(
        condition=TRAN_PHYS,
        SCHEMA_TEMPS=schema_temps(
            "NEWMARK",
            (
                "NEWMARK",
                "WILSON",
                "DIFF_CENTRE",
                "DEVOGE",
                "ADAPT_ORDRE1",
                "ADAPT_ORDRE2",
                "RUNGE_KUTTA_32",
                "RUNGE_KUTTA_54",
                "ITMI",
            ),
        ),
    ),
    b_param_tran=BLOC(
        condition=equal_to("TYPE_CALCUL", "TRAN"),
        INCREMENT=FACT(
            statut="o",
            fr="Time discretisation: a time step or a list of instants",
            regles=(UN_PARMI("LIST_INST", "PAS"),),
            LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
            b_list=BLOC(
                condition=exists("LIST_INST"),
                regles=(EXCLUS("INST_FIN", "NUME_FIN"),),
                NUME_FIN=SIMP(statut="f", typ="I"),
                INST_FIN=SIMP(statut="f", typ="R"),
            ),
            PAS=SIMP(statut="f", typ="R", val_min=1e-16),
            b_pas=BLOC(
                condition=exists("PAS"),
                INST_INIT=SIMP(statut="f", typ="R"),
                INST_FIN=SIMP(statut="o", typ="R"),
            ),
            VERI_PAS=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
        ),
    ),
    # ---------------------------------------------------------------- initial state
    b_init_gene=BLOC(
        condition=TRAN_GENE,
        ETAT_INIT=etat_init("tran_gene", "vect_asse_gene", physical=False),
    ),
    b_init_phys=BLOC(
        condition=TRAN_PHYS,
        ETAT_INIT=etat_init("dyna_trans", "cham_no_sdaster", physical=True),
    ),
    # ---------------------------------------------------------------- archiving
    b_dlt_prec=BLOC(
        condition=TRAN_PHYS,
        ARCHIVAGE=FACT(
            statut="f",
            max=1,
            regles=(EXCLUS("LIST_INST", "INST"),),
            PAS_ARCH=SIMP(statut="f", typ="I"),
            LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
            INST=SIMP(statut="f", typ="R", max="**"),
            b_list_inst=BLOC(condition=exists("LIST_INST") | exists("INST"), **precision_blocs()),
            CHAM_EXCLU=SIMP(statut="f", typ="TXM", max=2, into=("DEPL", "VITE", "ACCE")),
        ),
    ),
    b_not_dlt_prec=BLOC(
        condition=TRAN_GENE,
        ARCHIVAGE=FACT(
            statut="f",
            max=1,
            regles=(EXCLUS("LIST_INST", "INST"), AU_MOINS_UN("LIST_INST", "INST", "PAS_ARCH")),
            PAS_ARCH=SIMP(statut="f", typ="I", val_min=0),
            LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
            INST=SIMP(statut="f", typ="R", max="**"),
        ),
    ),
    # ---------------------------------------------------------------- energy
    # asterlite extension, not in code_aster 17 (PHYS only there): ENERGIE on a
    # TRAN/GENE transient gives its energy balance (asterlite.dynamics.energy)
    bloc_ener=BLOC(
        condition=equal_to("BASE_CALCUL", "PHYS") | TRAN_GENE,
        ENERGIE=FACT(
            statut="f", max=1, CALCUL=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI",))
        ),
    ),
    # ---------------------------------------------------------------- excitations, harmonic
    b_excit_harm_phys=BLOC(
        condition=HARM_PHYS,
        regles=(AU_MOINS_UN("EXCIT", "EXCIT_RESU"),),
        EXCIT=excit_harm(gene=False),
        EXCIT_RESU=FACT(
            statut="f",
            max="**",
            RESULTAT=SIMP(statut="o", typ="dyna_harmo"),
            COEF_MULT_C=SIMP(statut="o", typ="C"),
        ),
    ),
    b_excit_harm_gene=BLOC(
        condition=HARM_GENE,
        regles=(AU_MOINS_UN("EXCIT", "EXCIT_RESU"),),
        EXCIT=excit_harm(gene=True),
        EXCIT_RESU=FACT(
            statut="f",
            max="**",
            RESULTAT=SIMP(statut="o", typ="harm_gene"),
            COEF_MULT_C=SIMP(statut="o", typ="C"),
        ),
    ),
    # ---------------------------------------------------------------- excitations, transient
    b_excit_line_tran=BLOC(
        condition=TRAN_PHYS,
        EXCIT=FACT(
            statut="f",
            max="**",
            regles=(
                UN_PARMI("CHARGE", "VECT_ASSE"),
                EXCLUS("FONC_MULT", "COEF_MULT"),
                EXCLUS("ACCE", "COEF_MULT"),
                PRESENT_ABSENT("ACCE", "FONC_MULT"),
                PRESENT_PRESENT("ACCE", "VITE", "DEPL"),
            ),
            VECT_ASSE=SIMP(statut="f", typ="cham_no_sdaster"),
            CHARGE=SIMP(statut="f", typ=("char_meca", "char_cine_meca")),
            FONC_MULT=SIMP(statut="f", typ=FONCTION_OU_FORMULE),
            COEF_MULT=SIMP(statut="f", typ="R"),
            ACCE=SIMP(statut="f", typ=FONCTION_OU_FORMULE),
            VITE=SIMP(statut="f", typ=FONCTION_OU_FORMULE),
            DEPL=SIMP(statut="f", typ=FONCTION_OU_FORMULE),
            MULT_APPUI=SIMP(statut="f", typ="TXM", defaut="NON", into=("OUI", "NON")),
            b_mult_appui=BLOC(
                condition=equal_to("MULT_APPUI", "OUI"),
                DIRECTION=SIMP(statut="f", typ="R", max="**"),
                GROUP_NO=SIMP(statut="f", typ="grno", max="**"),
            ),
        ),
        MODE_STAT=SIMP(statut="f", typ="mode_meca"),
        EXCIT_RESU=FACT(
            statut="f",
            max="**",
            RESULTAT=SIMP(statut="o", typ="dyna_trans"),
            COEF_MULT=SIMP(statut="o", typ="R"),
        ),
    ),
    b_excit_tran_mod=BLOC(
        condition=TRAN_GENE,
        regles=(
            PRESENT_ABSENT("MODE_STAT", "MODE_CORR"),
            PRESENT_PRESENT("BASE_ELAS_FLUI", "NUME_VITE_FLUI"),
        ),
        EXCIT=FACT(
            statut="f",
            max="**",
            fr="Linear excitation: generalized load vector times a function of time",
            regles=(
                UN_PARMI("FONC_MULT", "COEF_MULT", "ACCE"),
                UN_PARMI("VECT_ASSE_GENE", "NUME_ORDRE"),
                PRESENT_PRESENT("ACCE", "VITE", "DEPL"),
                EXCLUS("MULT_APPUI", "CORR_STAT"),
                PRESENT_PRESENT("MULT_APPUI", "ACCE"),
            ),
            VECT_ASSE_GENE=SIMP(statut="f", typ="vect_asse_gene"),
            NUME_ORDRE=SIMP(statut="f", typ="I"),
            FONC_MULT=SIMP(statut="f", typ=FONCTION_OU_FORMULE),
            COEF_MULT=SIMP(statut="f", typ="R"),
            ACCE=SIMP(statut="f", typ=FONCTION_OU_FORMULE),
            VITE=SIMP(statut="f", typ=FONCTION_OU_FORMULE),
            DEPL=SIMP(statut="f", typ=FONCTION_OU_FORMULE),
            MULT_APPUI=SIMP(statut="f", typ="TXM", into=("OUI",)),
            b_mult_appui=BLOC(
                condition=equal_to("MULT_APPUI", "OUI"),
                DIRECTION=SIMP(statut="f", typ="R", max="**"),
                GROUP_NO=SIMP(statut="f", typ="grno", max="**"),
            ),
            CORR_STAT=SIMP(statut="f", typ="TXM", into=("OUI",)),
            b_corr_stat=BLOC(
                condition=equal_to("CORR_STAT", "OUI"),
                D_FONC_DT=SIMP(statut="o", typ=FONCTION_OU_FORMULE),
                D_FONC_DT2=SIMP(statut="o", typ=FONCTION_OU_FORMULE),
            ),
        ),
        MODE_STAT=SIMP(statut="f", typ="mode_meca"),
        MODE_CORR=SIMP(statut="f", typ=("mult_elas", "mode_meca")),
        EXCIT_RESU=FACT(
            statut="f",
            max="**",
            RESULTAT=SIMP(statut="o", typ="tran_gene"),
            COEF_MULT=SIMP(statut="f", typ="R", defaut=1.0),
        ),
        # localized nonlinearities
        COMPORTEMENT=comportement_dyna(),
        PARA_LAME_FLUI=para_lame_flui(),
        BASE_ELAS_FLUI=SIMP(statut="f", typ="melasflu_sdaster"),
        NUME_VITE_FLUI=SIMP(statut="f", typ="I"),
        VERI_CHOC=FACT(
            statut="f",
            fr="Stop (or warn) when a shock penetrates too far into its obstacle",
            STOP_CRITERE=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
            SEUIL=SIMP(statut="f", typ="R", defaut=0.5),
        ),
        b_nl_wet=BLOC(
            condition=exists("BASE_ELAS_FLUI"),
            TRAITEMENT_NONL=SIMP(statut="f", typ="TXM", defaut="IMPLICITE", into=("IMPLICITE",)),
        ),
        b_nl_dry=BLOC(
            condition=~exists("BASE_ELAS_FLUI"),
            TRAITEMENT_NONL=SIMP(
                statut="f", typ="TXM", defaut="EXPLICITE", into=("IMPLICITE", "EXPLICITE")
            ),
        ),
    ),
    # ---------------------------------------------------------------- linear solver
    b_sol_harm_gene=BLOC(condition=HARM_GENE, SOLVEUR=solveur("LDLT", ("LDLT", "MUMPS"))),
    b_sol_harm_phys=BLOC(
        condition=HARM_PHYS, SOLVEUR=solveur("MUMPS", ("MULT_FRONT", "LDLT", "MUMPS"))
    ),
    b_sol_line_tran=BLOC(
        condition=TRAN_PHYS,
        SOLVEUR=solveur("MUMPS", ("MULT_FRONT", "LDLT", "MUMPS", "GCPC", "PETSC")),
    ),
    b_sol_tran_gene=BLOC(
        condition=TRAN_GENE, SOLVEUR=solveur("LDLT", ("MULT_FRONT", "LDLT", "MUMPS"))
    ),
    # ---------------------------------------------------------------- miscellaneous
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", into=(1, 2)),
    b_impression=BLOC(
        condition=TRAN_GENE,
        IMPRESSION=FACT(
            statut="f",
            fr="Printing of the local quantities of the nonlinearities",
            regles=(
                PRESENT_ABSENT("UNITE_DIS_VISC", "INST_FIN", "INST_INIT", "TOUT", "NIVEAU"),
                PRESENT_ABSENT("UNITE_DIS_ECRO_TRAC", "INST_FIN", "INST_INIT", "TOUT", "NIVEAU"),
            ),
            TOUT=SIMP(statut="f", typ="TXM", into=("OUI",)),
            NIVEAU=SIMP(
                statut="f", typ="TXM", into=("DEPL_LOC", "VITE_LOC", "FORC_LOC", "TAUX_CHOC")
            ),
            INST_INIT=SIMP(statut="f", typ="R"),
            INST_FIN=SIMP(statut="f", typ="R"),
            UNITE_DIS_VISC=SIMP(
                statut="f", typ="I", fr="Output unit for DIS_VISC internal variables"
            ),
            UNITE_DIS_ECRO_TRAC=SIMP(
                statut="f", typ="I", fr="Output unit for DIS_ECRO_TRAC internal variables"
            ),
        ),
    ),
)
