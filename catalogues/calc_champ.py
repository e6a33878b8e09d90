"""CALC_CHAMP: compute element or nodal fields of a result (stresses, forces...).

code_aster splits the options by result family (linear, dynamic,
non-linear); asterlite accepts the union of the linear/dynamic options.
"""

from asterlite.catalogues.common import critere_precision, group_ma

from asterlite.catalog import AU_MOINS_UN, EXCLUS, FACT, OPER, PRESENT_ABSENT, SIMP, UN_PARMI


def _family(prefix_list, locations=("ELGA", "ELNO", "NOEU")) -> tuple:
    return tuple(f"{p}_{loc}" for p in prefix_list for loc in locations)


CONTRAINTE = (
    "EFGE_ELGA", "EFGE_ELNO", "EGRU_ELNO", "EFGE_NOEU", "SIEF_ELGA", "SIEF_ELNO", "SIEF_NOEU",
    "SIGM_ELGA", "SIGM_ELNO", "SIGM_NOEU", "SIMY_ELGA", "SIPM_ELNO", "SIPO_ELNO", "SIPO_NOEU",
    "SIRO_ELEM", "STRX_ELGA",
)  # fmt: skip
DEFORMATION = _family(("DEGE", "EPME", "EPSG", "EPSI", "EPVC", "EPSL"))
ENERGIE = (
    "DISS_ELEM", *_family(("DISS", "ENEL", "ETOT")), "ECIN_ELEM", "ENEL_ELEM", "ENTR_ELEM",
    "EPOT_ELEM", "ETOT_ELEM",
)  # fmt: skip
CRITERES = _family(("EPEQ", "EPGQ", "EPMQ", "SIEQ"))
VARI_INTERNE = ("VARC_ELGA", "VARC_ELNO", "VARC_NOEU", "VARI_ELNO", "VARI_NOEU")
PROPRIETES = ("MATE_ELGA", "MATE_ELEM", "MASS_ELGA")
FORCE = ("FORC_NODA", "REAC_NODA")
FONCTION = ("fonction_sdaster", "nappe_sdaster", "formule")
RESULTAT = (
    "resultat_sdaster", "evol_elas", "mode_meca", "mode_meca_c", "mult_elas", "fourier_elas",
    "mode_flamb", "comb_fourier", "dyna_harmo", "dyna_trans", "evol_noli",
)  # fmt: skip


def _sdprod(kw) -> str:
    resultat = kw.get("RESULTAT")
    return getattr(resultat, "aster_type", None) or "resultat_sdaster"


def _options(into: tuple, fr: str) -> SIMP:
    return SIMP(statut="f", typ="TXM", max="**", into=into, fr=fr)


CALC_CHAMP = OPER(
    nom="CALC_CHAMP",
    sd_prod=_sdprod,
    reentrant="f",
    fr="Compute element or nodal fields and add them to a result",
    regles=(
        EXCLUS(
            "TOUT_ORDRE",
            "NUME_ORDRE",
            "INST",
            "FREQ",
            "NUME_MODE",
            "NOEUD_CMP",
            "LIST_INST",
            "LIST_FREQ",
            "LIST_ORDRE",
            "NOM_CAS",
        ),
        PRESENT_ABSENT("TOUT", "GROUP_MA"),
        AU_MOINS_UN(
            "CONTRAINTE",
            "DEFORMATION",
            "ENERGIE",
            "CRITERES",
            "VARI_INTERNE",
            "PROPRIETES",
            "FORCE",
            "CHAM_UTIL",
        ),
    ),  # fmt: skip
    MODELE=SIMP(statut="f", typ="modele_sdaster"),
    CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
    CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
    RESULTAT=SIMP(statut="o", typ=RESULTAT, fr="Result of a global command"),
    TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
    NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
    NUME_MODE=SIMP(statut="f", typ="I", max="**"),
    NOEUD_CMP=SIMP(statut="f", typ="TXM", max="**"),
    NOM_CAS=SIMP(statut="f", typ="TXM"),
    INST=SIMP(statut="f", typ="R", max="**"),
    FREQ=SIMP(statut="f", typ="R", max="**"),
    LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
    LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
    LIST_ORDRE=SIMP(statut="f", typ="listis_sdaster"),
    **critere_precision(),
    TOUT=SIMP(statut="f", typ="TXM", into=("OUI",)),
    GROUP_MA=group_ma(),
    CONTRAINTE=_options(CONTRAINTE, "Stresses and generalised forces"),
    DEFORMATION=_options(DEFORMATION, "Strains"),
    ENERGIE=_options(ENERGIE, "Energies"),
    CRITERES=_options(CRITERES, "Equivalent stresses and strains"),
    VARI_INTERNE=_options(VARI_INTERNE, "Internal and command variables"),
    PROPRIETES=_options(PROPRIETES, "Material properties"),
    FORCE=_options(FORCE, "Nodal forces and reactions"),
    EXCIT=FACT(
        statut="f",
        max="**",
        fr="Loads holding distributed forces on beams, temperatures...",
        regles=(EXCLUS("FONC_MULT", "COEF_MULT"),),
        CHARGE=SIMP(statut="o", typ=("char_meca", "char_cine_meca")),
        PHAS_DEG=SIMP(statut="f", typ="R", defaut=0.0),
        PUIS_PULS=SIMP(statut="f", typ="I", defaut=0),
        FONC_MULT_C=SIMP(statut="f", typ=("fonction_c", "formule_c")),
        COEF_MULT_C=SIMP(statut="f", typ="C"),
        FONC_MULT=SIMP(statut="f", typ=FONCTION),
        COEF_MULT=SIMP(statut="f", typ="R"),
        TYPE_CHARGE=SIMP(
            statut="f",
            typ="TXM",
            defaut="FIXE_CSTE",
            into=("FIXE_CSTE", "FIXE_PILO", "SUIV", "DIDI"),
        ),
    ),
    CHAM_UTIL=FACT(
        statut="f",
        max="**",
        fr="User fields UTnn computed from a formula, a criterion or a norm",
        regles=(UN_PARMI("FORMULE", "CRITERE", "NORME"),),
        NOM_CHAM=SIMP(statut="o", typ="TXM"),
        FORMULE=SIMP(statut="f", typ=("formule", "formule_c"), max="**"),
        CRITERE=SIMP(statut="f", typ="TXM", into=("TRACE", "VMIS", "INVA_2")),
        NORME=SIMP(statut="f", typ="TXM", into=("L2", "FROBENIUS")),
        NUME_CHAM_RESU=SIMP(statut="o", typ="I", val_min=1, val_max=20),
    ),
    PARALLELISME_TEMPS=SIMP(
        no_effect="parallel computing over the instants",
        statut="f",
        typ="TXM",
        defaut="NON",
        into=("OUI", "NON"),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
