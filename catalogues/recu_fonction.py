"""RECU_FONCTION: extract a function from a result, a field, a table or a nappe.

For a ``tran_gene`` (the usual case here): a generalized or physical
component against time (``NOM_CHAM``), or the local quantities of a shock
(``GROUP_NO_CHOC`` with ``PARA_X``/``PARA_Y``: ``INST``, ``FN``, ``FT1``,
``DXLOC``, ``VINT1``...).
"""

from asterlite.catalogues.common_post import (
    INTERPOLATION,
    NOM_CHAM,
    PARA_FONCTION,
    PROLONGEMENT,
    TABLE,
    any_given,
    concept_is,
    is_type,
    precision_blocs,
    table_filter,
)

from asterlite.catalog import (
    AU_MOINS_UN,
    BLOC,
    EXCLUS,
    OPER,
    PRESENT_ABSENT,
    PRESENT_PRESENT,
    SIMP,
    UN_PARMI,
    equal_to,
    exists,
)

SHOCK_PARAMETERS = (
    "INST", "FN", "FT1", "FT2", "VN", "VT1", "VT2", "DXLOC", "DYLOC", "DZLOC",
) + tuple(f"VINT{i}" for i in range(1, 21))  # fmt: skip


def recu_fonction_type(kw) -> str:
    """fonction_c from harmonic results, complex table columns or cross spectra."""
    if concept_is(kw.get("RESULTAT"), "dyna_harmo") or concept_is(kw.get("RESU_GENE"), "harm_gene"):
        return "fonction_c"
    if kw.get("INTE_SPEC") is not None:
        if kw.get("NUME_ORDRE_J") is not None and kw.get("NUME_ORDRE_I") != kw.get("NUME_ORDRE_J"):
            return "fonction_c"
        if kw.get("NOEUD_J") is not None and kw.get("NOEUD_I") != kw.get("NOEUD_J"):
            return "fonction_c"
        if kw.get("NOM_CMP_J") is not None and kw.get("NOM_CMP_I") != kw.get("NOM_CMP_J"):
            return "fonction_c"
    if kw.get("TABLE") is not None and (
        kw.get("NOM_PARA_TABL") == "FONCTION_C" or kw.get("PARA_Y") == "VALE_C"
    ):
        return "fonction_c"
    return "fonction_sdaster"


def _location(node_statut: str = "c") -> dict:
    return dict(
        GROUP_MA=SIMP(statut="f", typ="grma"),
        NOEUD=SIMP(statut=node_statut, typ="no"),
        GROUP_NO=SIMP(statut="f", typ="grno"),
        POINT=SIMP(statut="f", typ="I"),
        SOUS_POINT=SIMP(statut="f", typ="I"),
    )


_LOCATION_RULES = (
    AU_MOINS_UN("GROUP_MA", "GROUP_NO", "NOEUD"),
    PRESENT_ABSENT("POINT", "NOEUD", "GROUP_NO"),
    PRESENT_ABSENT("SOUS_POINT", "NOEUD", "GROUP_NO"),
    EXCLUS("GROUP_NO", "NOEUD"),
)

RECU_FONCTION = OPER(
    nom="RECU_FONCTION",
    sd_prod=recu_fonction_type,
    reentrant="n",
    fr="Extract the evolution of a quantity as a function",
    regles=(
        UN_PARMI(
            "CHAM_GD", "RESULTAT", "RESU_GENE", "TABLE", "BASE_ELAS_FLUI", "NAPPE", "INTE_SPEC"
        ),
    ),
    CHAM_GD=SIMP(statut="f", typ=("cham_no_sdaster", "cham_elem")),
    RESULTAT=SIMP(statut="f", typ="resultat_sdaster"),
    RESU_GENE=SIMP(statut="f", typ=("tran_gene", "mode_gene", "harm_gene")),
    TABLE=SIMP(statut="f", typ=TABLE),
    BASE_ELAS_FLUI=SIMP(statut="f", typ="melasflu_sdaster"),
    NAPPE=SIMP(statut="f", typ="nappe_sdaster"),
    INTE_SPEC=SIMP(statut="f", typ="interspectre"),
    # ---------------------------------------------------------------- access to a result
    b_acces=BLOC(
        condition=exists("RESULTAT") | exists("RESU_GENE"),
        TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
        NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
        LIST_ORDRE=SIMP(statut="f", typ="listis_sdaster"),
        TOUT_INST=SIMP(statut="f", typ="TXM", into=("OUI",)),
        INST=SIMP(statut="f", typ="R", max="**"),
        LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
        FREQ=SIMP(statut="f", typ="R", max="**"),
        LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
        NUME_MODE=SIMP(statut="f", typ="I", max="**"),
        b_prec=BLOC(
            condition=any_given("INST", "LIST_INST", "FREQ", "LIST_FREQ"),
            **precision_blocs(),
            INTERP_NUME=SIMP(statut="f", typ="TXM", into=("NON", "LIN")),
        ),
    ),
    # ---------------------------------------------------------------- fluid-elastic basis
    b_base_elas_flui=BLOC(
        condition=exists("BASE_ELAS_FLUI"),
        NUME_MODE=SIMP(statut="o", typ="I"),
        PARA_X=SIMP(statut="o", typ="TXM", into=("VITE_FLU", "NB_CONNORS")),
        b_connors=BLOC(
            condition=equal_to("PARA_X", "NB_CONNORS"),
            PARA_Y=SIMP(statut="o", typ="TXM", into=("VITE_CRIT", "INSTAB_EDF", "INSTAB_TOUT_CMP")),
        ),
        b_cdck=BLOC(
            condition=equal_to("PARA_X", "VITE_FLU"),
            regles=(UN_PARMI("TOUT_ORDRE", "NUME_ORDRE"),),
            TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
            NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
            PARA_Y=SIMP(statut="o", typ="TXM", into=("FREQ", "AMOR")),
        ),
    ),
    # ---------------------------------------------------------------- cross spectrum
    b_inte_spec=BLOC(
        condition=exists("INTE_SPEC"),
        regles=(UN_PARMI("NUME_ORDRE_I", "NOEUD_I", "NUME_ORDRE"),),
        NOM_CHAM=SIMP(statut="f", typ="TXM", into=NOM_CHAM),
        NUME_ORDRE=SIMP(statut="f", typ="I"),
        NOEUD_I=SIMP(statut="f", typ="no"),
        NUME_ORDRE_I=SIMP(statut="f", typ="I"),
        b_nume_ordre_i=BLOC(
            condition=exists("NUME_ORDRE_I"), NUME_ORDRE_J=SIMP(statut="f", typ="I")
        ),
        b_noeud_i=BLOC(
            condition=exists("NOEUD_I"),
            NOEUD_J=SIMP(statut="f", typ="no"),
            NOM_CMP_I=SIMP(statut="o", typ="TXM"),
            NOM_CMP_J=SIMP(statut="f", typ="TXM"),
        ),
    ),
    # ---------------------------------------------------------------- table
    b_table=BLOC(
        condition=exists("TABLE"),
        regles=(UN_PARMI("PARA_X", "NOM_PARA_TABL"), PRESENT_PRESENT("PARA_X", "PARA_Y")),
        PARA_X=SIMP(statut="f", typ="TXM", fr="Column of the abscissas"),
        PARA_Y=SIMP(statut="f", typ="TXM", fr="Column of the ordinates"),
        NOM_PARA_TABL=SIMP(statut="f", typ="TXM", into=("FONCTION", "FONCTION_C")),
        FILTRE=table_filter(crit_always=True),
    ),
    # ---------------------------------------------------------------- result on the physical basis
    b_resu=BLOC(
        condition=exists("RESULTAT"),
        regles=(UN_PARMI("NOM_CHAM", "NOM_PARA_RESU"),),
        NOM_CHAM=SIMP(statut="f", typ="TXM", into=NOM_CHAM),
        NOM_PARA_RESU=SIMP(statut="f", typ="TXM"),
        b_cham=BLOC(
            condition=exists("NOM_CHAM"),
            regles=_LOCATION_RULES + (UN_PARMI("NOM_CMP", "NOM_VARI"),),
            NOM_CMP=SIMP(statut="f", typ="TXM"),
            NOM_VARI=SIMP(statut="f", typ="TXM"),
            **_location(),
        ),
    ),
    # ---------------------------------------------------------------- transient on a modal basis
    b_tran_gene=BLOC(
        condition=is_type("RESU_GENE", "tran_gene"),
        regles=(UN_PARMI("NOM_CHAM", "NOEUD_CHOC", "GROUP_NO_CHOC"),),
        NOM_CHAM=SIMP(statut="f", typ="TXM", into=("DEPL", "VITE", "ACCE", "PTEM")),
        NOEUD_CHOC=SIMP(statut="c", typ="no"),
        GROUP_NO_CHOC=SIMP(statut="f", typ="grno"),
        b_cham=BLOC(
            condition=equal_to("NOM_CHAM", ("DEPL", "VITE", "ACCE")),
            regles=(
                UN_PARMI("GROUP_NO", "NOEUD", "NUME_CMP_GENE"),
                UN_PARMI("NOM_CMP", "NUME_CMP_GENE"),
                EXCLUS("MULT_APPUI", "CORR_STAT"),
            ),
            NOM_CMP=SIMP(statut="f", typ="TXM"),
            NUME_CMP_GENE=SIMP(statut="f", typ="I", val_min=1),
            NOEUD=SIMP(statut="c", typ="no"),
            GROUP_NO=SIMP(statut="f", typ="grno"),
            MULT_APPUI=SIMP(statut="f", typ="TXM", into=("OUI",)),
            CORR_STAT=SIMP(statut="f", typ="TXM", into=("OUI",)),
            ACCE_MONO_APPUI=SIMP(statut="f", typ=("fonction_sdaster", "formule")),
        ),
        b_choc=BLOC(
            condition=exists("NOEUD_CHOC") | exists("GROUP_NO_CHOC"),
            regles=(PRESENT_PRESENT("SOUS_STRUC", "INTITULE"),),
            PARA_X=SIMP(statut="o", typ="TXM", into=SHOCK_PARAMETERS),
            PARA_Y=SIMP(statut="o", typ="TXM", into=SHOCK_PARAMETERS),
            LIST_PARA=SIMP(statut="f", typ="listr8_sdaster"),
            INTITULE=SIMP(statut="f", typ="TXM"),
            SOUS_STRUC=SIMP(statut="f", typ="TXM"),
        ),
    ),
    b_harm_gene=BLOC(
        condition=is_type("RESU_GENE", "harm_gene"),
        regles=(
            UN_PARMI("NOM_CMP", "NUME_CMP_GENE"),
            UN_PARMI("GROUP_NO", "NOEUD", "NUME_CMP_GENE"),
        ),
        NOM_CHAM=SIMP(statut="f", typ="TXM", into=("DEPL", "VITE", "ACCE")),
        NOM_CMP=SIMP(statut="f", typ="TXM"),
        NUME_CMP_GENE=SIMP(statut="f", typ="I", val_min=1),
        NOEUD=SIMP(statut="c", typ="no"),
        GROUP_NO=SIMP(statut="f", typ="grno"),
    ),
    b_mode_gene=BLOC(
        condition=is_type("RESU_GENE", "mode_gene"),
        regles=(UN_PARMI("NOM_CHAM", "NOM_PARA_RESU"),),
        NOM_CHAM=SIMP(statut="f", typ="TXM", into=NOM_CHAM),
        NOM_PARA_RESU=SIMP(statut="f", typ="TXM"),
        b_cham=BLOC(
            condition=exists("NOM_CHAM"),
            regles=(UN_PARMI("NUME_CMP_GENE", "NOM_CMP"),),
            NUME_CMP_GENE=SIMP(statut="f", typ="I", val_min=1),
            NOM_CMP=SIMP(statut="f", typ="TXM"),
            b_cmp=BLOC(
                condition=exists("NOM_CMP"),
                regles=(UN_PARMI("NOEUD", "GROUP_NO"), UN_PARMI("SQUELETTE", "SOUS_STRUC")),
                NOEUD=SIMP(statut="c", typ="no"),
                GROUP_NO=SIMP(statut="f", typ="grno"),
                SQUELETTE=SIMP(statut="f", typ="squelette"),
                SOUS_STRUC=SIMP(statut="f", typ="TXM"),
            ),
        ),
    ),
    # ---------------------------------------------------------------- field
    b_cham_gd=BLOC(
        condition=exists("CHAM_GD"),
        regles=_LOCATION_RULES,
        NOM_CMP=SIMP(statut="o", typ="TXM"),
        **_location(),
    ),
    # ---------------------------------------------------------------- nappe
    b_nappe=BLOC(
        condition=exists("NAPPE"),
        VALE_PARA_FONC=SIMP(statut="o", typ="R"),
        PRECISION=SIMP(statut="f", typ="R", defaut=1.0e-3),
        CRITERE=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=("RELATIF", "ABSOLU")),
    ),
    # ---------------------------------------------------------------- attributes of the result
    NOM_PARA=SIMP(statut="f", typ="TXM", into=PARA_FONCTION),
    NOM_RESU=SIMP(statut="f", typ="TXM"),
    INTERPOL=SIMP(statut="f", typ="TXM", max=2, into=INTERPOLATION),
    PROL_DROITE=SIMP(statut="f", typ="TXM", into=PROLONGEMENT),
    PROL_GAUCHE=SIMP(statut="f", typ="TXM", into=PROLONGEMENT),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
