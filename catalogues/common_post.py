"""Shared fragments of the dynamics, function, table and test catalogues.

Written in code_aster's vocabulary (code_aster 17 ``Commons``): lists of
allowed values, the precision/criterion pair, table filters, the
``TEST_*`` reference keywords, the solver factor keyword, and two helpers
that look at the *type* of a concept given to a keyword (code_aster's
``is_type(...)`` conditions and ``AsType(...)`` in ``sd_prod`` functions).
"""

from __future__ import annotations

from asterlite.catalogues.common import NO_EFFECT_SOLVER

from asterlite.catalog import (
    BLOC,
    EXCLUS,
    FACT,
    PRESENT_ABSENT,
    PRESENT_PRESENT,
    SIMP,
    UN_PARMI,
    Condition,
    absent,
    equal_to,
    exists,
)
from asterlite.lang.values import Unknown

# --------------------------------------------------------------------------
# Concept types
# --------------------------------------------------------------------------

#: a table, whatever its flavour (code_aster's table_fonction/table_container
#: derive from table_sdaster)
TABLE = ("table_sdaster", "table_fonction", "table_container")

#: a real function of one variable, a formula, or a function of two variables
FONCTION_OU_FORMULE = ("fonction_sdaster", "nappe_sdaster", "formule")

#: every result code_aster stores by order number (any of them satisfies resultat_sdaster)
RESULTAT = ("resultat_sdaster",)


def concept_is(value, *type_names: str) -> bool | None:
    """True/False when ``value`` is a concept of one of ``type_names``, None if unknown."""
    if value is None:
        return False
    if value is Unknown:
        return None
    satisfies = getattr(value, "satisfies", None)
    if satisfies is None:  # a CO or some other non-concept value
        return None
    if "*" in getattr(value, "aster_types", ()):  # check mode: a concept of any type
        return None
    return any(satisfies(name) for name in type_names)


def is_type(keyword: str, *type_names: str) -> Condition:
    """BLOC condition: keyword ``keyword`` holds a concept of one of ``type_names``.

    code_aster writes these ``is_type("RESU_GENE") == tran_gene``. Under
    ``asterlite check`` the concept may be unknown: the condition is then
    undetermined (None).
    """

    def test(level) -> bool | None:
        return concept_is(level.get(keyword), *type_names)

    return Condition(test, f"{keyword} is a {' or '.join(type_names)}")


def vale_calc_is_zero(level) -> bool | None:
    """code_aster's ORDRE_GRANDEUR condition: the first VALE_CALC is (almost) zero."""
    value = level.get("VALE_CALC")
    if value is None:
        return False
    if isinstance(value, (list, tuple)):
        value = value[0] if value else None
    if value is Unknown:
        return None
    try:
        return abs(value) < 1.0e-16
    except TypeError:
        return None


# --------------------------------------------------------------------------
# Allowed values
# --------------------------------------------------------------------------

#: parameter names of functions (code_aster's C_PARA_FONCTION)
PARA_FONCTION = (
    "DX", "DY", "DZ", "DRX", "DRY", "DRZ", "DTAN", "TEMP", "TSEC",
    "INST", "X", "Y", "Z", "EPSI", "META", "FREQ", "PULS", "DSP",
    "AMOR", "ABSC", "SIGM", "HYDR", "SECH", "PORO", "SAT", "IRRA",
    "PGAZ", "PCAP", "PLIQ", "PVAP", "PAD", "VITE", "ENDO",
    "NORM", "EPAIS", "NEUT1", "NEUT2", "NEUT3", "NEUT4", "XF", "YF", "ZF", "NUME_ORDRE",
)  # fmt: skip

PROLONGEMENT = ("CONSTANT", "LINEAIRE", "EXCLU")
INTERPOLATION = ("LIN", "LOG")
CRITERES = ("RELATIF", "ABSOLU")
COMPARAISONS = (
    "EQ", "LT", "GT", "NE", "LE", "GE", "VIDE", "NON_VIDE", "MAXI", "MAXI_ABS", "MINI", "MINI_ABS",
)  # fmt: skip

_USER_FIELDS = tuple(
    f"UT{i:02d}_{kind}" for kind in ("ELGA", "ELNO", "ELEM", "NOEU", "CART") for i in range(1, 11)
)

#: field names of results (code_aster's C_NOM_CHAM_INTO)
NOM_CHAM = (
    # displacements and other nodal unknowns
    "ACCE", "ACCE_ABSOLU", "DEPL", "DEPL_ABSOLU", "VITE", "VITE_ABSOLU", "TEMP",
    "HHO_DEPL", "HHO_VITE", "CONT_NOEU", "CONT_ELEM", "VARI_ELGA", "DEPL_ELGA",
    # stresses and generalised forces
    "EFGE_ELGA", "EFGE_ELNO", "EFGE_NOEU", "EGRU_ELNO", "SIEF_ELGA", "SIEF_ELNO", "SIEF_NOEU",
    "SIMY_ELGA", "SIGM_ELGA", "SIGM_ELNO", "SIGM_NOEU", "SIPM_ELNO", "SIPO_ELNO", "SIPO_NOEU",
    "SIRO_ELEM", "STRX_ELGA",
    # strains
    "DEGE_ELGA", "DEGE_ELNO", "DEGE_NOEU", "EPFD_ELGA", "EPFD_ELNO", "EPFD_NOEU",
    "EPFP_ELGA", "EPFP_ELNO", "EPFP_NOEU", "EPME_ELGA", "EPME_ELNO", "EPME_NOEU",
    "EPMG_ELGA", "EPMG_ELNO", "EPMG_NOEU", "EPSG_ELGA", "EPSG_ELNO", "EPSG_NOEU",
    "EPSI_ELGA", "EPSI_ELNO", "EPSI_NOEU", "EPSP_ELGA", "EPSP_ELNO", "EPSP_NOEU",
    "EPVC_ELGA", "EPVC_ELNO", "EPVC_NOEU", "EPSL_ELGA", "EPSL_ELNO", "EPSL_NOEU",
    # energies
    "DISS_ELEM", "DISS_ELGA", "DISS_ELNO", "DISS_NOEU", "ECIN_ELEM", "ENEL_ELEM", "ENEL_ELGA",
    "ENEL_ELNO", "ENEL_NOEU", "ENTR_ELEM", "EPOT_ELEM", "ETOT_ELEM", "ETOT_ELGA", "ETOT_ELNO",
    "ETOT_NOEU",
    # criteria
    "DERA_ELGA", "DERA_ELNO", "DERA_NOEU", "ENDO_ELGA", "ENDO_ELNO", "ENDO_NOEU",
    "EPEQ_ELGA", "EPEQ_ELNO", "EPEQ_NOEU", "EPGQ_ELGA", "EPGQ_ELNO", "EPGQ_NOEU",
    "EPMQ_ELGA", "EPMQ_ELNO", "EPMQ_NOEU", "INDL_ELGA", "PDIL_ELGA",
    "SIEQ_ELGA", "SIEQ_ELNO", "SIEQ_NOEU",
    # internal and command variables
    "VARC_ELGA", "VARI_ELNO", "VARI_NOEU",
    # other physics
    "FLHN_ELGA", "TEMP_ELGA", "FLUX_ELGA", "FLUX_ELNO", "FLUX_NOEU", "HYDR_ELGA", "HYDR_ELNO",
    "HYDR_NOEU", "SOUR_ELGA", "ETHE_ELEM", "HHO_TEMP", "PRAC_ELNO", "PRAC_NOEU", "PRME_ELNO",
    "INTE_ELNO", "INTE_NOEU", "DURT_ELNO", "DURT_NOEU", "META_ELNO", "META_NOEU",
    # nodal forces
    "FORC_NODA", "REAC_NODA",
    # error estimators
    "SIZ1_NOEU", "ERZ1_ELEM", "SIZ2_NOEU", "ERZ2_ELEM", "ERME_ELEM", "ERME_ELNO", "ERME_NOEU",
    "QIRE_ELEM", "QIRE_ELNO", "QIRE_NOEU", "QIZ1_ELEM", "QIZ2_ELEM", "SING_ELEM", "SING_ELNO",
    "ERTH_ELEM", "ERTH_ELNO", "ERTH_NOEU",
    # material properties and miscellaneous
    "MATE_ELGA", "MATE_ELEM", "COHE_ELEM", "COMPORTEMENT", "COMPORTHER", "DEPL_VIBR", "DIVU",
    "EPSA_ELNO", "EPSA_NOEU", "FERR_ELEM", "FSUR_2D", "FSUR_3D", "FVOL_2D", "FVOL_3D", "COEF_H",
    "T_EXT", "IRRA", "MODE_FLAMB", "MODE_STAB", "NEUT", "PRES", "PRES_NOEU", "PTOT", "RESI_NOEU",
    "RESI_RELA_NOEU", "SISE_ELNO", "VITE_VENT",
) + _USER_FIELDS  # fmt: skip


# --------------------------------------------------------------------------
# Small keyword groups
# --------------------------------------------------------------------------


def precision_blocs(mandatory_absolute: bool = True) -> dict:
    """CRITERE with its PRECISION: default 1e-6 when RELATIF, mandatory when ABSOLU."""
    return dict(
        CRITERE=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=CRITERES),
        b_prec_rela=BLOC(
            condition=equal_to("CRITERE", "RELATIF"),
            PRECISION=SIMP(statut="f", typ="R", defaut=1.0e-6),
        ),
        b_prec_abso=BLOC(
            condition=equal_to("CRITERE", "ABSOLU"),
            PRECISION=SIMP(statut="o" if mandatory_absolute else "f", typ="R"),
        ),
    )


def table_filter(vale_max=1, regexp: bool = False, crit_always: bool = False) -> FACT:
    """The FILTRE factor keyword selecting rows of a table (NOM_PARA, CRIT_COMP, VALE*)."""
    comparisons = COMPARAISONS + (("REGEXP",) if regexp else ())
    entries = dict(
        NOM_PARA=SIMP(statut="o", typ="TXM"),
        CRIT_COMP=SIMP(statut="f", typ="TXM", defaut="EQ", into=comparisons),
        b_vale=BLOC(
            condition=equal_to("CRIT_COMP", ("EQ", "NE", "GT", "LT", "GE", "LE")),
            regles=(UN_PARMI("VALE", "VALE_I", "VALE_K", "VALE_C"),),
            VALE=SIMP(statut="f", typ="R", max=vale_max),
            VALE_I=SIMP(statut="f", typ="I", max=vale_max),
            VALE_C=SIMP(statut="f", typ="C", max=vale_max),
            VALE_K=SIMP(statut="f", typ="TXM", max=vale_max),
        ),
    )
    if regexp:
        entries["b_regexp"] = BLOC(
            condition=equal_to("CRIT_COMP", "REGEXP"), VALE_K=SIMP(statut="o", typ="TXM")
        )
    if crit_always:
        entries["CRITERE"] = SIMP(statut="f", typ="TXM", defaut="RELATIF", into=CRITERES)
        entries["PRECISION"] = SIMP(statut="f", typ="R", defaut=1.0e-3)
    else:
        entries["b_crit"] = BLOC(
            condition=equal_to("CRIT_COMP", ("EQ", "NE")),
            CRITERE=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=CRITERES),
            PRECISION=SIMP(statut="f", typ="R", defaut=1.0e-3),
        )
    return FACT(statut="f", max="**", **entries)


# --------------------------------------------------------------------------
# TEST_RESU / TEST_TABLE / TEST_FONCTION: the checked value and its references
# --------------------------------------------------------------------------


def test_reference(keyword: str, max="**") -> dict:  # noqa: A002 - code_aster's option name
    """Keywords stating what a TEST_* occurrence expects (code_aster's C_TEST_REFERENCE).

    ``VALE_CALC`` (non-regression value, tolerance ``TOLE_MACHINE``, default
    1e-6 relative) and, with ``REFERENCE``, ``VALE_REFE`` checked within
    ``PRECISION`` (default 1e-3). Integer, complex and text variants exist
    depending on what is tested.
    """
    with_int = keyword != "FONCTION"
    with_complex = keyword not in ("OBJET", "FICHIER", "MAILLAGE")
    with_text = keyword in ("FICHIER", "TABLE")
    vale_abs = keyword not in ("CARTE", "FICHIER")
    type_test = keyword not in ("CARTE", "GENE", "OBJET")
    several_tolerances = keyword in ("RESU", "GENE")

    suffixes = [""]
    calc: dict = {}
    refe: dict = {}
    for suffix, typ, wanted in (("_I", "I", with_int), ("_C", "C", with_complex),
                                ("_K", "TXM", with_text)):  # fmt: skip
        if wanted:
            suffixes.append(suffix)
            calc["VALE_CALC" + suffix] = SIMP(statut="f", typ=typ, max=max)
            refe["VALE_REFE" + suffix] = SIMP(statut="f", typ=typ, max=max)
    if vale_abs:
        calc["VALE_ABS"] = SIMP(statut="f", typ="TXM", defaut="NON", into=("OUI", "NON"))
    if type_test:
        calc["TYPE_TEST"] = SIMP(statut="f", typ="TXM", into=("SOMM_ABS", "SOMM", "MAX", "MIN"))
    if several_tolerances:
        calc["TOLE_MACHINE"] = SIMP(statut="f", typ="R", max=2)
        calc["CRITERE"] = SIMP(statut="f", typ="TXM", max=2, into=CRITERES)
    else:
        calc["TOLE_MACHINE"] = SIMP(statut="f", typ="R", defaut=1.0e-6)
        calc["CRITERE"] = SIMP(statut="f", typ="TXM", defaut="RELATIF", into=CRITERES)

    return dict(
        b_values=BLOC(
            condition=Condition(lambda level: True, "always"),
            regles=(UN_PARMI(*("VALE_CALC" + s for s in suffixes)),),
            VALE_CALC=SIMP(statut="f", typ="R", max=max),
            b_ordre_grandeur=BLOC(
                condition=Condition(vale_calc_is_zero, "VALE_CALC is zero"),
                ORDRE_GRANDEUR=SIMP(statut="f", typ="R"),
            ),
            LEGENDE=SIMP(statut="f", typ="TXM", no_effect="label of the check in the listing"),
            REFERENCE=SIMP(
                statut="f",
                typ="TXM",
                into=("ANALYTIQUE", "SOURCE_EXTERNE", "AUTRE_ASTER", "NON_DEFINI"),
            ),
            b_reference=BLOC(
                condition=exists("REFERENCE"),
                regles=(UN_PARMI(*("VALE_REFE" + s for s in suffixes)),),
                VALE_REFE=SIMP(statut="f", typ="R", max=max),
                PRECISION=SIMP(statut="f", typ="R", defaut=1.0e-3),
                **refe,
            ),
            **calc,
        )
    )


# --------------------------------------------------------------------------
# SOLVEUR (code_aster's C_SOLVEUR), the variants the dynamics commands need
# --------------------------------------------------------------------------


def solveur(default: str, methods: tuple[str, ...]) -> FACT:
    """The linear solver factor keyword: METHODE and the options of each method."""
    direct = dict(
        NPREC=SIMP(statut="f", typ="I", defaut=8),
        STOP_SINGULIER=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
    )
    entries: dict = dict(METHODE=SIMP(statut="f", typ="TXM", defaut=default, into=methods))
    if "MULT_FRONT" in methods:
        entries["b_mult_front"] = BLOC(
            condition=equal_to("METHODE", "MULT_FRONT"),
            RENUM=SIMP(statut="f", typ="TXM", defaut="MDA", into=("MD", "MDA")),
            ELIM_LAGR=SIMP(statut="f", typ="TXM", defaut="NON", into=("OUI", "NON")),
            **direct,
        )
    if "LDLT" in methods:
        entries["b_ldlt"] = BLOC(
            condition=equal_to("METHODE", "LDLT"),
            RENUM=SIMP(statut="f", typ="TXM", defaut="RCMK", into=("RCMK",)),
            ELIM_LAGR=SIMP(statut="f", typ="TXM", defaut="NON", into=("OUI", "NON")),
            **direct,
        )
    if "MUMPS" in methods:
        entries["b_mumps"] = BLOC(
            condition=equal_to("METHODE", "MUMPS"),
            RENUM=SIMP(
                statut="f",
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
            ELIM_LAGR=SIMP(statut="f", typ="TXM", defaut="LAGR2", into=("OUI", "NON", "LAGR2")),
            TYPE_RESOL=SIMP(
                statut="f", typ="TXM", defaut="AUTO", into=("NONSYM", "SYMGEN", "SYMDEF", "AUTO")
            ),
            ACCELERATION=SIMP(
                statut="f",
                typ="TXM",
                defaut="AUTO",
                into=("AUTO", "FR", "FR+", "FR++", "LR", "LR+", "LR++"),
            ),
            LOW_RANK_SEUIL=SIMP(statut="f", typ="R", defaut=0.0),
            PRETRAITEMENTS=SIMP(statut="f", typ="TXM", defaut="AUTO", into=("SANS", "AUTO")),
            POSTTRAITEMENTS=SIMP(
                statut="f", typ="TXM", defaut="AUTO", into=("SANS", "AUTO", "FORCE", "MINI")
            ),
            PCENT_PIVOT=SIMP(statut="f", typ="I", defaut=35, val_min=1),
            NB_RHS=SIMP(statut="f", typ="I", defaut=1, val_min=1, val_max=32),
            RESI_RELA=SIMP(statut="f", typ="R", defaut=-1.0),
            GESTION_MEMOIRE=SIMP(
                statut="f",
                typ="TXM",
                defaut="AUTO",
                into=("IN_CORE", "OUT_OF_CORE", "AUTO", "EVAL"),
            ),
            **direct,
        )
    iterative = [m for m in ("GCPC", "PETSC") if m in methods]
    if iterative:
        entries["b_iterative"] = BLOC(
            condition=equal_to("METHODE", tuple(iterative)),
            PRE_COND=SIMP(statut="f", typ="TXM"),
            RESI_RELA=SIMP(statut="f", typ="R", defaut=1.0e-6),
            NMAX_ITER=SIMP(statut="f", typ="I", defaut=0),
            ELIM_LAGR=SIMP(statut="f", typ="TXM", defaut="NON", into=("OUI", "NON")),
            RENUM=SIMP(statut="f", typ="TXM"),
        )
    return FACT(statut="d", no_effect=NO_EFFECT_SOLVER, **entries)


# --------------------------------------------------------------------------
# COMPORTEMENT of DYNA_VIBRA (and DYNA_LINE): localized nonlinearities on a
# modal basis (code_aster's C_COMPORTEMENT_DYNA)
# --------------------------------------------------------------------------

RELATIONS_DYNA = (
    "DIS_CHOC",
    "ROTOR_FISS",
    "FLAMBAGE",
    "ANTI_SISM",
    "DIS_VISC",
    "DIS_ECRO_TRAC",
    "CHOC_ELAS_TRAC",
    "RELA_EFFO_DEPL",
    "RELA_EFFO_VITE",
)
# relations added from outside this package (docs/architecture.md, "Adding a
# relation"): RELATION value -> the keywords of its block; read when a
# catalogue holding COMPORTEMENT is built, so register before loading it
ADDED_RELATIONS: dict[str, dict] = {}


def register_relation(name: str, **keywords) -> None:
    """Add a COMPORTEMENT relation and its keywords (``SIMP``, ``FACT``, ``BLOC``)."""
    if name in RELATIONS_DYNA or name in ADDED_RELATIONS:
        raise ValueError(f"relation {name!r} is already catalogued")
    ADDED_RELATIONS[name] = dict(keywords)


def _two_nodes() -> dict:
    """The two ends of a discrete nonlinearity (NOEUD_* are hidden legacy spellings)."""
    return dict(
        NOEUD_1=SIMP(statut="c", typ="no"),
        NOEUD_2=SIMP(statut="c", typ="no"),
        GROUP_NO_1=SIMP(statut="f", typ="grno"),
        GROUP_NO_2=SIMP(statut="f", typ="grno"),
    )


def para_lame_flui() -> FACT:
    """PARA_LAME_FLUI (code_aster 12-14; top-level NMAX_ITER, RESI_RELA, LAMBDA in
    code_aster 10-11): the fixed-point iterations of the fluid film
    (CHOC/LAME_FLUIDE), an asterlite extension of today's DYNA_VIBRA."""
    return FACT(
        statut="f",
        max=1,
        NMAX_ITER=SIMP(statut="f", typ="I", defaut=20, val_min=1),
        RESI_RELA=SIMP(statut="f", typ="R", defaut=1.0e-3, val_min=0.0),
        LAMBDA=SIMP(statut="f", typ="R", defaut=10.0),
    )


def comportement_dyna() -> FACT:
    """COMPORTEMENT: one occurrence per localized nonlinearity, chosen by RELATION."""

    one_of_each_end = (UN_PARMI("NOEUD_1", "GROUP_NO_1"), UN_PARMI("NOEUD_2", "GROUP_NO_2"))
    return FACT(
        statut="f",
        max="**",
        fr="Localized nonlinearities (shocks, buckling, dampers, cracked rotor...)",
        RELATION=SIMP(statut="o", typ="TXM", into=RELATIONS_DYNA + tuple(ADDED_RELATIONS)),
        # -- shock with an obstacle, penalised normal force and Coulomb friction
        b_choc=BLOC(
            condition=equal_to("RELATION", "DIS_CHOC"),
            regles=(
                UN_PARMI("MAILLE", "GROUP_MA", "NOEUD_1", "GROUP_NO_1"),
                EXCLUS("NOEUD_2", "GROUP_NO_2"),
                PRESENT_ABSENT("GROUP_MA", "NOEUD_2", "GROUP_NO_2"),
                PRESENT_ABSENT("MAILLE", "NOEUD_2", "GROUP_NO_2"),
            ),
            INTITULE=SIMP(statut="f", typ="TXM"),
            GROUP_MA=SIMP(statut="f", typ="grma", max="**"),
            MAILLE=SIMP(statut="c", typ="ma", max="**"),
            **_two_nodes(),
            OBSTACLE=SIMP(statut="o", typ="table_fonction"),
            ORIG_OBST=SIMP(statut="f", typ="R", min=3, max=3),
            NORM_OBST=SIMP(statut="o", typ="R", min=3, max=3),
            ANGL_VRIL=SIMP(statut="f", typ="R"),
            JEU=SIMP(statut="f", typ="R", defaut=1.0),
            DIST_1=SIMP(statut="f", typ="R", val_min=0.0),
            DIST_2=SIMP(statut="f", typ="R", val_min=0.0),
            SOUS_STRUC_1=SIMP(statut="f", typ="TXM"),
            SOUS_STRUC_2=SIMP(statut="f", typ="TXM"),
            REPERE=SIMP(statut="f", typ="TXM", defaut="GLOBAL"),
            RIGI_NOR=SIMP(statut="o", typ="R"),
            AMOR_NOR=SIMP(statut="f", typ="R", defaut=0.0),
            RIGI_TAN=SIMP(statut="f", typ="R", defaut=0.0),
            AMOR_TAN=SIMP(statut="f", typ="R"),
            FROTTEMENT=SIMP(
                statut="f", typ="TXM", defaut="NON", into=("NON", "COULOMB", "COULOMB_STAT_DYNA")
            ),
            b_coulomb=BLOC(
                condition=equal_to("FROTTEMENT", "COULOMB"),
                COULOMB=SIMP(statut="o", typ="R"),
                UNIDIRECTIONNEL=SIMP(statut="f", typ="TXM", defaut="NON", into=("OUI", "NON")),
            ),
            b_c_st_dyna=BLOC(
                condition=equal_to("FROTTEMENT", "COULOMB_STAT_DYNA"),
                COULOMB_STAT=SIMP(statut="o", typ="R"),
                COULOMB_DYNA=SIMP(statut="o", typ="R"),
                UNIDIRECTIONNEL=SIMP(statut="f", typ="TXM", defaut="NON", into=("OUI", "NON")),
            ),
            # asterlite extension (hidden): the fluid film of code_aster 10-14's
            # CHOC (asterlite.dynamics.fluid_film), reached from legacy decks
            LAME_FLUIDE=SIMP(statut="c", typ="TXM", into=("OUI", "NON")),
            b_lame_fluide=BLOC(
                condition=equal_to("LAME_FLUIDE", "OUI"),
                ALPHA=SIMP(statut="o", typ="R"),
                BETA=SIMP(statut="o", typ="R"),
                CHI=SIMP(statut="o", typ="R"),
                DELTA=SIMP(statut="o", typ="R"),
            ),
        ),
        # -- cracked rotor: stiffness depending on the rotation angle
        b_rotor=BLOC(
            condition=equal_to("RELATION", "ROTOR_FISS"),
            regles=(
                UN_PARMI("NOEUD_D", "GROUP_NO_D"),
                EXCLUS("NOEUD_G", "GROUP_NO_G"),
                PRESENT_PRESENT("NOEUD_D", "NOEUD_G"),
                PRESENT_PRESENT("GROUP_NO_D", "GROUP_NO_G"),
            ),
            ANGL_INIT=SIMP(statut="f", typ="R", defaut=0.0),
            ANGL_ROTA=SIMP(statut="f", typ=("fonction_sdaster", "formule")),
            NOEUD_G=SIMP(statut="c", typ="no"),
            NOEUD_D=SIMP(statut="c", typ="no"),
            GROUP_NO_G=SIMP(statut="f", typ="grno"),
            GROUP_NO_D=SIMP(statut="f", typ="grno"),
            K_PHI=SIMP(statut="o", typ=("fonction_sdaster", "formule")),
            DK_DPHI=SIMP(statut="o", typ=("fonction_sdaster", "formule")),
        ),
        # -- buckling of a shock support (force-displacement law with crushing)
        b_buckling=BLOC(
            condition=equal_to("RELATION", "FLAMBAGE"),
            regles=(UN_PARMI("NOEUD_1", "GROUP_NO_1"), EXCLUS("NOEUD_2", "GROUP_NO_2")),
            INTITULE=SIMP(statut="f", typ="TXM"),
            **_two_nodes(),
            OBSTACLE=SIMP(statut="o", typ="table_fonction"),
            ORIG_OBST=SIMP(statut="f", typ="R", max="**"),
            NORM_OBST=SIMP(statut="o", typ="R", max="**"),
            ANGL_VRIL=SIMP(statut="f", typ="R"),
            JEU=SIMP(statut="f", typ="R", defaut=1.0),
            DIST_1=SIMP(statut="f", typ="R"),
            DIST_2=SIMP(statut="f", typ="R"),
            REPERE=SIMP(statut="f", typ="TXM", defaut="GLOBAL"),
            CRIT_AMOR=SIMP(statut="f", typ="TXM", defaut="INCLUS", into=("INCLUS", "EXCLUS")),
            # asterlite extension (hidden): code_aster 15's scalar law, which its decks
            # give (asterlite.legacy.v15) and asterlite runs as code_aster 15 did
            FNOR_CRIT=SIMP(statut="c", typ="R"),
            b_crushing_functions=BLOC(
                condition=absent("FNOR_CRIT"),
                FX=SIMP(statut="o", typ="fonction_sdaster", fr="Axial force vs displacement"),
                RIGI_NOR=SIMP(statut="o", typ="fonction_sdaster", fr="Stiffness vs displacement"),
                AMOR_NOR=SIMP(statut="o", typ="fonction_sdaster", fr="Damping vs displacement"),
            ),
            b_scalar_law=BLOC(
                condition=exists("FNOR_CRIT"),
                RIGI_NOR=SIMP(statut="o", typ="R"),
                AMOR_NOR=SIMP(statut="f", typ="R", defaut=0.0),
                FNOR_POST_FL=SIMP(statut="o", typ="R"),
                ENFO_FL=SIMP(statut="f", typ="R", defaut=1.0e-20),
                AMOR_FL=SIMP(statut="f", typ="R"),
                LARG_PLAT=SIMP(statut="f", typ="R", defaut=0.0),
                DEPL_POST_FL=SIMP(statut="f", typ="R", max="**"),
                RIGI_POST_FL=SIMP(statut="f", typ="R", max="**"),
                AMOR_POST_FL=SIMP(statut="f", typ="R", max="**"),
            ),
        ),
        # -- anti-seismic device
        b_antisism=BLOC(
            condition=equal_to("RELATION", "ANTI_SISM"),
            regles=one_of_each_end,
            **_two_nodes(),
            RIGI_K1=SIMP(statut="f", typ="R", defaut=0.0),
            RIGI_K2=SIMP(statut="f", typ="R", defaut=0.0),
            SEUIL_FX=SIMP(statut="f", typ="R", defaut=0.0),
            C=SIMP(statut="f", typ="R", defaut=0.0),
            PUIS_ALPHA=SIMP(statut="f", typ="R", defaut=0.0),
            DX_MAX=SIMP(statut="f", typ="R", defaut=1.0),
        ),
        # -- generalized Zener viscous discrete element
        b_disvisc=BLOC(
            condition=equal_to("RELATION", "DIS_VISC"),
            regles=one_of_each_end
            + (UN_PARMI("K1", "UNSUR_K1"), UN_PARMI("K2", "UNSUR_K2"), UN_PARMI("K3", "UNSUR_K3")),
            **_two_nodes(),
            K1=SIMP(statut="f", typ="R", val_min=1.0e-08, fr="Stiffness in series"),
            K2=SIMP(statut="f", typ="R", val_min=0.0, fr="Stiffness parallel to the dashpot"),
            K3=SIMP(statut="f", typ="R", val_min=1.0e-08, fr="Stiffness in the viscous branch"),
            UNSUR_K1=SIMP(statut="f", typ="R", val_min=0.0, fr="Flexibility in series"),
            UNSUR_K2=SIMP(statut="f", typ="R", val_min=1.0e-08, fr="Parallel flexibility"),
            UNSUR_K3=SIMP(statut="f", typ="R", val_min=0.0, fr="Viscous-branch flexibility"),
            C=SIMP(statut="o", typ="R", val_min=1.0e-08, fr="Viscous coefficient"),
            PUIS_ALPHA=SIMP(
                statut="f",
                typ="R",
                val_min=1.0e-08,
                val_max=1.0,
                defaut=0.5,
                fr="Exponent of the viscous law, in ]0, 1]",
            ),
            ITER_INTE_MAXI=SIMP(statut="f", typ="I", defaut=20),
            RESI_INTE=SIMP(statut="f", typ="R", defaut=1.0e-6),
        ),
        # -- discrete element with isotropic or kinematic hardening
        b_disecro=BLOC(
            condition=equal_to("RELATION", "DIS_ECRO_TRAC"),
            regles=one_of_each_end + (UN_PARMI("FX", "FTAN"),),
            **_two_nodes(),
            FX=SIMP(statut="f", typ="fonction_sdaster", fr="Axial force vs displacement"),
            FTAN=SIMP(statut="f", typ="fonction_sdaster", fr="Tangential force vs displacement"),
            b_ftan=BLOC(
                condition=exists("FTAN"),
                ECROUISSAGE=SIMP(statut="o", typ="TXM", into=("ISOTROPE", "CINEMATIQUE")),
            ),
            ITER_INTE_MAXI=SIMP(statut="f", typ="I", defaut=20),
            RESI_INTE=SIMP(statut="f", typ="R", defaut=1.0e-6),
        ),
        # -- nonlinear elastic shock in the axial direction
        b_dischocelastrac=BLOC(
            condition=equal_to("RELATION", "CHOC_ELAS_TRAC"),
            regles=one_of_each_end,
            **_two_nodes(),
            DIST_1=SIMP(statut="f", typ="R", val_min=0.0),
            DIST_2=SIMP(statut="f", typ="R", val_min=0.0),
            FX=SIMP(statut="o", typ="fonction_sdaster", fr="Nonlinear elastic axial force"),
        ),
        # -- force as a function of a displacement component
        b_refx=BLOC(
            condition=equal_to("RELATION", "RELA_EFFO_DEPL"),
            regles=(UN_PARMI("NOEUD", "GROUP_NO"),),
            NOEUD=SIMP(statut="c", typ="no"),
            GROUP_NO=SIMP(statut="f", typ="grno"),
            SOUS_STRUC=SIMP(statut="f", typ="TXM"),
            NOM_CMP=SIMP(statut="f", typ="TXM"),
            FONCTION=SIMP(statut="o", typ=FONCTION_OU_FORMULE),
        ),
        # -- force as a function of a velocity component
        b_refv=BLOC(
            condition=equal_to("RELATION", "RELA_EFFO_VITE"),
            regles=(UN_PARMI("NOEUD", "GROUP_NO"),),
            NOEUD=SIMP(statut="c", typ="no"),
            GROUP_NO=SIMP(statut="f", typ="grno"),
            SOUS_STRUC=SIMP(statut="f", typ="TXM"),
            NOM_CMP=SIMP(statut="f", typ="TXM"),
            FONCTION=SIMP(statut="o", typ=FONCTION_OU_FORMULE),
        ),
        **{
            f"b_added_{name.lower()}": BLOC(condition=equal_to("RELATION", name), **keywords)
            for name, keywords in ADDED_RELATIONS.items()
        },
    )


def observation_dyna() -> FACT:
    """OBSERVATION of a physical transient: field values stored in a table while computing."""
    nodes = dict(
        TOUT=SIMP(statut="f", typ="TXM", into=("OUI",)),
        NOEUD=SIMP(statut="c", typ="no", max="**"),
        GROUP_NO=SIMP(statut="f", typ="grno", max="**"),
        MAILLE=SIMP(statut="c", typ="ma", max="**"),
        GROUP_MA=SIMP(statut="f", typ="grma", max="**"),
    )
    return FACT(
        statut="f",
        max=99,
        regles=(UN_PARMI("NOM_CMP", "NOM_VARI"),),
        NOM_CHAM=SIMP(statut="o", typ="TXM", into=("DEPL", "VITE", "ACCE")),
        TITRE=SIMP(statut="f", typ="TXM"),
        OBSE_ETAT_INIT=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
        EVAL_CHAM=SIMP(
            statut="f",
            typ="TXM",
            defaut="VALE",
            into=("MIN", "MAX", "MOY", "MAXI_ABS", "MINI_ABS", "VALE"),
        ),
        NOM_CMP=SIMP(statut="f", typ="TXM", max=20),
        NOM_VARI=SIMP(statut="f", typ="TXM", max=20),
        EVAL_CMP=SIMP(statut="f", typ="TXM", defaut="VALE", into=("VALE", "FORMULE")),
        b_formule=BLOC(
            condition=equal_to("EVAL_CMP", "FORMULE"), FORMULE=SIMP(statut="o", typ="formule")
        ),
        b_cham_no=BLOC(
            condition=equal_to("NOM_CHAM", ("DEPL", "VITE", "ACCE")),
            regles=(UN_PARMI("NOEUD", "GROUP_NO", "GROUP_MA", "MAILLE", "TOUT"),),
            **nodes,
        ),
        INST=SIMP(statut="f", typ="R", max="**"),
        LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
        PAS_OBSE=SIMP(statut="f", typ="I"),
        **precision_blocs(),
    )


def any_given(*names: str) -> Condition:
    """BLOC condition: at least one of the keywords ``names`` is given."""
    condition = exists(names[0])
    for name in names[1:]:
        condition = condition | exists(name)
    return condition
