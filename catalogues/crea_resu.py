"""CREA_RESU: create or enrich a result from fields.

Supported operations: AFFE (all result types), ASSE, PERM_CHAM, KUCV,
CONV_CHAR and CONV_RESU. PROL_RTZ and PREP_VARC are code_aster choices whose
keywords asterlite does not describe yet.
"""

from asterlite.catalogues.common import (
    NO_EFFECT_STORED,
    NOM_CHAM_INTO,
    OUI_NON,
    critere_precision,
    group_no,
)

from asterlite.catalog import (
    BLOC,
    FACT,
    OPER,
    PRESENT_ABSENT,
    SIMP,
    UN_PARMI,
    equal_to,
    exists,
    is_in,
)

CHAM_GD = ("cham_no_sdaster", "cham_elem", "carte_sdaster", "cham_gd_sdaster")
FONCTION = ("fonction_sdaster", "nappe_sdaster", "formule")
TYPES_RESU = (
    "MODE_MECA", "MODE_MECA_C", "MULT_ELAS", "EVOL_ELAS", "EVOL_NOLI", "DYNA_HARMO",
    "DYNA_TRANS", "FOURIER_ELAS", "FOURIER_THER", "EVOL_THER", "EVOL_VARC", "EVOL_CHAR",
    "EVOL_SECH",
)  # fmt: skip
EVOLUTIONS = ("EVOL_ELAS", "EVOL_NOLI", "EVOL_THER", "EVOL_VARC", "DYNA_TRANS", "EVOL_SECH")


def _sdprod(kw) -> str:
    return str(kw.get("TYPE_RESU") or "EVOL_ELAS").lower()


def _affe(type_resu, **keywords) -> dict:
    """AFFE occurrences: a field, its model data and where it goes."""
    return dict(
        CHAM_GD=SIMP(statut="o", typ=CHAM_GD),
        MODELE=SIMP(statut="f", typ="modele_sdaster"),
        CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
        CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
        **keywords,
    )


def _at_instants() -> dict:
    return dict(
        INST=SIMP(statut="f", typ="R", max="**"),
        LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
        NUME_INIT=SIMP(statut="f", typ="I", val_min=1),
        NUME_FIN=SIMP(statut="f", typ="I", val_min=1),
        PRECISION=SIMP(statut="f", typ="R", defaut=0.0),
        CRITERE=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=("RELATIF", "ABSOLU")),
    )


def _affe_bloc(types, resultat, **affe_keywords) -> BLOC:
    condition = equal_to("OPERATION", "AFFE") & (
        is_in("TYPE_RESU", types) if isinstance(types, tuple) else equal_to("TYPE_RESU", types)
    )
    regles = affe_keywords.pop("regles", ())
    return BLOC(
        condition=condition,
        RESULTAT=SIMP(statut="f", typ=resultat),
        AFFE=FACT(statut="o", max="**", regles=regles, **_affe(types, **affe_keywords)),
    )


def _excit(charges, **extra) -> FACT:
    return FACT(
        statut="f",
        max="**",
        CHARGE=SIMP(statut="o", typ=charges),
        FONC_MULT=SIMP(statut="f", typ=FONCTION),
        **extra,
    )


CREA_RESU = OPER(
    nom="CREA_RESU",
    sd_prod=_sdprod,
    reentrant="f",
    fr="Create or enrich a result from fields",
    OPERATION=SIMP(
        statut="o",
        typ="TXM",
        into=(
            "AFFE",
            "ASSE",
            "PERM_CHAM",
            "PROL_RTZ",
            "PREP_VARC",
            "KUCV",
            "CONV_CHAR",
            "CONV_RESU",
        ),
    ),
    TYPE_RESU=SIMP(statut="o", typ="TXM", into=TYPES_RESU),
    b_affe_mult_elas=_affe_bloc(
        "MULT_ELAS",
        "mult_elas",
        NOM_CAS=SIMP(statut="f", typ="TXM"),
        CHARGE=SIMP(statut="f", typ="char_meca", max="**"),
        NOM_CHAM=SIMP(statut="o", typ="TXM", into=NOM_CHAM_INTO),
    ),
    b_affe_evol_dyn=_affe_bloc(
        EVOLUTIONS,
        ("evol_elas", "evol_noli", "evol_ther", "evol_varc", "dyna_trans", "evol_sech"),
        regles=(UN_PARMI("INST", "LIST_INST"),),
        **_at_instants(),
        NOM_CHAM=SIMP(statut="o", typ="TXM", into=NOM_CHAM_INTO),
    ),
    b_affe_evol_char=_affe_bloc(
        "EVOL_CHAR",
        (
            "evol_elas",
            "evol_noli",
            "evol_ther",
            "evol_varc",
            "evol_char",
            "dyna_trans",
            "evol_sech",
        ),
        regles=(UN_PARMI("INST", "LIST_INST"),),
        **_at_instants(),
        NOM_CHAM=SIMP(
            statut="o",
            typ="TXM",
            into=(
                "PRES",
                "FORC_NODA",
                "FSUR_2D",
                "FSUR_3D",
                "FVOL_2D",
                "FVOL_3D",
                "VITE_VENT",
                "T_EXT",
                "COEF_H",
                "FLUN",
            ),
        ),  # fmt: skip
    ),
    b_affe_fourier_elas=_affe_bloc(
        "FOURIER_ELAS",
        "fourier_elas",
        NUME_MODE=SIMP(statut="f", typ="I"),
        TYPE_MODE=SIMP(statut="f", typ="TXM", defaut="SYME", into=("SYME", "ANTI", "TOUS")),
        CHARGE=SIMP(statut="f", typ="char_meca", max="**"),
        NOM_CHAM=SIMP(statut="o", typ="TXM", into=NOM_CHAM_INTO),
    ),
    b_affe_fourier_ther=_affe_bloc(
        "FOURIER_THER",
        "fourier_ther",
        NUME_MODE=SIMP(statut="f", typ="I"),
        TYPE_MODE=SIMP(statut="f", typ="TXM", defaut="SYME", into=("SYME", "ANTI", "TOUS")),
        NOM_CHAM=SIMP(statut="o", typ="TXM", into=NOM_CHAM_INTO),
    ),
    b_mode_meca=BLOC(
        condition=equal_to("OPERATION", "AFFE")
        & is_in("TYPE_RESU", ("MODE_MECA", "MODE_MECA_C", "DYNA_HARMO", "DYNA_TRANS")),
        MATR_RIGI=SIMP(statut="f", typ="matr_asse_depl_r", no_effect=NO_EFFECT_STORED),
        MATR_MASS=SIMP(statut="f", typ="matr_asse_depl_r", no_effect=NO_EFFECT_STORED),
    ),
    b_evol_elas=BLOC(
        condition=equal_to("OPERATION", "AFFE") & equal_to("TYPE_RESU", "EVOL_ELAS"),
        EXCIT=_excit(
            ("char_meca", "char_cine_meca"),
            TYPE_CHARGE=SIMP(statut="f", typ="TXM", defaut="FIXE_CSTE", into=("FIXE_CSTE",)),
        ),
    ),
    b_evol_ther=BLOC(
        condition=equal_to("OPERATION", "AFFE") & is_in("TYPE_RESU", ("EVOL_THER", "EVOL_SECH")),
        EXCIT=_excit(("char_ther", "char_cine_ther")),
    ),
    b_evol_noli=BLOC(
        condition=equal_to("OPERATION", "AFFE") & equal_to("TYPE_RESU", "EVOL_NOLI"),
        VERI_VARI=SIMP(statut="f", typ="TXM", defaut="OUI", into=OUI_NON),
        EXCIT=_excit(
            ("char_meca", "char_cine_meca"),
            TYPE_CHARGE=SIMP(
                statut="f",
                typ="TXM",
                defaut="FIXE_CSTE",
                into=("FIXE_CSTE", "FIXE_PILO", "SUIV", "DIDI"),
            ),
            DEPL=SIMP(statut="f", typ=FONCTION),
            ACCE=SIMP(statut="f", typ=FONCTION),
            VITE=SIMP(statut="f", typ=FONCTION),
            MULT_APPUI=SIMP(statut="f", typ="TXM", defaut="NON", into=OUI_NON),
            DIRECTION=SIMP(statut="f", typ="R", max="**"),
            GROUP_NO=group_no(),
        ),
    ),
    b_affe_mode_meca=_affe_bloc(
        "MODE_MECA",
        "mode_meca",
        NUME_MODE=SIMP(statut="o", typ="I"),
        FREQ=SIMP(statut="f", typ="R"),
        AXE=SIMP(statut="f", typ="TXM", into=("X", "Y", "Z")),
        NOM_CHAM=SIMP(statut="o", typ="TXM", into=NOM_CHAM_INTO),
    ),
    b_affe_mode_meca_c=_affe_bloc(
        "MODE_MECA_C",
        "mode_meca_c",
        NUME_MODE=SIMP(statut="o", typ="I"),
        FREQ=SIMP(statut="f", typ="R"),
        AXE=SIMP(statut="f", typ="TXM", into=("X", "Y", "Z")),
        AMOR_REDUIT=SIMP(statut="f", typ="R"),
        NOM_CHAM=SIMP(statut="o", typ="TXM", into=NOM_CHAM_INTO),
    ),
    b_affe_dyna_harmo=_affe_bloc(
        "DYNA_HARMO",
        "dyna_harmo",
        regles=(UN_PARMI("FREQ", "LIST_FREQ"),),
        FREQ=SIMP(statut="f", typ="R", max="**"),
        LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
        CRITERE=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=("RELATIF", "ABSOLU")),
        PRECISION=SIMP(statut="f", typ="R", defaut=0.0),
        NOM_CHAM=SIMP(statut="o", typ="TXM", into=NOM_CHAM_INTO),
    ),
    b_asse=BLOC(
        condition=equal_to("OPERATION", "ASSE"),
        ASSE=FACT(
            statut="o",
            max="**",
            RESULTAT=SIMP(statut="o", typ="evol_ther"),
            TRANSLATION=SIMP(statut="f", typ="R", defaut=0.0),
        ),
    ),
    b_perm_cham=BLOC(
        condition=equal_to("OPERATION", "PERM_CHAM"),
        NOM_CHAM=SIMP(
            statut="f", typ="TXM", into=("DEPL", "SIEF_ELGA", "VARI_ELGA", "STRX_ELGA"), max="**"
        ),
        RESU_INIT=SIMP(statut="o", typ="evol_noli"),
        INST_INIT=SIMP(statut="f", typ="R"),
        **critere_precision(),
        MAILLAGE_INIT=SIMP(statut="o", typ="maillage_sdaster"),
        RESU_FINAL=SIMP(statut="o", typ="evol_noli"),
        MAILLAGE_FINAL=SIMP(statut="o", typ="maillage_sdaster"),
        PERM_CHAM=FACT(
            statut="o",
            max="**",
            GROUP_MA_FINAL=SIMP(statut="o", typ="grma"),
            GROUP_MA_INIT=SIMP(statut="o", typ="grma"),
            TRAN=SIMP(statut="o", typ="R", min=3, max=3),
            PRECISION=SIMP(statut="f", typ="R", defaut=1.0e-3),
        ),
    ),
    b_prod_evol_char=BLOC(
        condition=equal_to("OPERATION", "KUCV") & is_in("TYPE_RESU", ("EVOL_CHAR", "DYNA_TRANS")),
        KUCV=FACT(
            statut="o",
            regles=(UN_PARMI("INST", "LIST_INST"),),
            RESU_INIT=SIMP(statut="o", typ=("dyna_trans", "evol_noli")),
            MATR_RIGI=SIMP(statut="f", typ="matr_asse_depl_r"),
            MATR_AMOR=SIMP(statut="o", typ="matr_asse_depl_r"),
            INST=SIMP(statut="f", typ="R", max="**"),
            LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
            PRECISION=SIMP(statut="f", typ="R", defaut=1.0e-6),
            CRITERE=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=("RELATIF", "ABSOLU")),
        ),
    ),
    b_conv_resu=BLOC(
        condition=equal_to("OPERATION", "CONV_RESU")
        & is_in("TYPE_RESU", ("EVOL_CHAR", "DYNA_TRANS")),
        CONV_RESU=FACT(
            statut="o",
            regles=(
                UN_PARMI("MATR_RIGI", "NUME_DDL"),
                UN_PARMI("INST", "LIST_INST"),
                PRESENT_ABSENT("GROUP_NO_INTERF", "FONC_DX"),
            ),
            RESU_INIT=SIMP(statut="o", typ=("dyna_trans", "evol_char", "evol_noli")),
            NOM_CHAM_INIT=SIMP(
                statut="f", typ="TXM", into=("DEPL", "ACCE", "FORC_NODA", "REAC_NODA")
            ),
            DDL_EXCLUS=SIMP(statut="f", typ="TXM", into=("DX", "DY", "DZ", "DRX", "DRY", "DRZ")),
            MATR_RIGI=SIMP(statut="f", typ="matr_asse_depl_r"),
            NUME_DDL=SIMP(statut="f", typ="nume_ddl_sdaster"),
            INST=SIMP(statut="f", typ="R", max="**"),
            LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
            PRECISION=SIMP(statut="f", typ="R", defaut=1.0e-6),
            COEF=SIMP(statut="f", typ="R", defaut=1.0),
            CRITERE=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=("RELATIF", "ABSOLU")),
            GROUP_NO_INTERF=SIMP(statut="f", typ="grno"),
            b_group_no=BLOC(
                condition=exists("GROUP_NO_INTERF"),
                DIRECTION=SIMP(statut="o", typ="R", min=3, max=3),
                VITE_ONDE=SIMP(statut="o", typ="R", val_min=0.0),
                COOR_REFE=SIMP(statut="o", typ="R", min=3, max=3),
            ),
            FONC_DX=SIMP(statut="f", typ=("nappe_sdaster", "formule")),
            b_fonc_dx=BLOC(
                condition=exists("FONC_DX"),
                **{
                    f"FONC_{c}": SIMP(statut="f", typ=("nappe_sdaster", "formule"))
                    for c in ("DY", "DZ", "DRX", "DRY", "DRZ")
                },
            ),
        ),
    ),
    b_char_evol_char=BLOC(
        condition=equal_to("OPERATION", "CONV_CHAR")
        & is_in("TYPE_RESU", ("EVOL_CHAR", "DYNA_TRANS")),
        CONV_CHAR=FACT(
            statut="o",
            regles=(UN_PARMI("INST", "LIST_INST"),),
            CHARGE=SIMP(statut="o", typ="char_meca", max="**"),
            CHAM_MATER=SIMP(statut="o", typ="cham_mater"),
            CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
            MATR_RIGI=SIMP(statut="o", typ="matr_asse_depl_r"),
            INST=SIMP(statut="f", typ="R", max="**"),
            LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
            PRECISION=SIMP(statut="f", typ="R", defaut=1.0e-6),
            CRITERE=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=("RELATIF", "ABSOLU")),
        ),
    ),
)
