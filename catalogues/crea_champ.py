"""CREA_CHAMP: create a field (assign, assemble, combine, extract from a result...)."""

from asterlite.catalogues.common import (
    NOM_CHAM_INTO,
    OUI_NON,
    TYPE_CHAM_INTO,
    critere_precision,
    group_ma,
    group_no,
    noeud,
    tout,
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
    absent,
    equal_to,
    exists,
    is_in,
)

CHAM_GD = ("cham_no_sdaster", "cham_elem", "carte_sdaster", "cham_gd_sdaster")
FONCTION = ("fonction_sdaster", "nappe_sdaster", "formule")
RESULTAT = ("resultat_sdaster", "mode_meca", "dyna_trans", "evol_elas", "mult_elas", "evol_noli")
ELEMENT_FIELDS = tuple(t for t in TYPE_CHAM_INTO if t.startswith("EL"))


def _sdprod(kw) -> str:
    location = str(kw.get("TYPE_CHAM") or "NOEU").split("_")[0]
    if location == "CART":
        return "carte_sdaster"
    if location.startswith("EL"):
        return "cham_elem"
    return "cham_no_sdaster"


CREA_CHAMP = OPER(
    nom="CREA_CHAMP",
    sd_prod=_sdprod,
    reentrant="f",
    fr="Create a field",
    regles=(EXCLUS("NUME_DDL", "CHAM_NO"),),
    b_reuse=BLOC(
        condition=is_in("OPERATION", ("ASSE", "COMB")),
        CHAM_GD=SIMP(statut="f", typ=CHAM_GD, fr="Field reused for the result"),
    ),
    TYPE_CHAM=SIMP(statut="o", typ="TXM", into=TYPE_CHAM_INTO),
    NUME_DDL=SIMP(statut="f", typ="nume_ddl_sdaster"),
    CHAM_NO=SIMP(statut="f", typ="cham_no_sdaster"),
    b_prol_zero=BLOC(
        condition=exists("NUME_DDL") | exists("CHAM_NO") | is_in("TYPE_CHAM", ELEMENT_FIELDS),
        PROL_ZERO=SIMP(statut="f", typ="TXM", defaut="NON", into=OUI_NON),
    ),
    OPTION=SIMP(statut="f", typ="TXM"),
    AFFE_SP=FACT(statut="f", CARA_ELEM=SIMP(statut="o", typ="cara_elem")),
    OPERATION=SIMP(
        statut="o",
        typ="TXM",
        into=("AFFE", "ASSE", "ASSE_DEPL", "EVAL", "EXTR", "DISC", "NORMALE", "R2C", "C2R", "COMB"),
    ),
    b_norm=BLOC(
        condition=equal_to("OPERATION", "NORMALE"),
        MODELE=SIMP(statut="o", typ="modele_sdaster"),
        GROUP_MA=group_ma("o"),
    ),
    b_affe=BLOC(
        condition=equal_to("OPERATION", "AFFE"),
        regles=(UN_PARMI("MAILLAGE", "MODELE"),),
        MAILLAGE=SIMP(statut="f", typ="maillage_sdaster"),
        MODELE=SIMP(statut="f", typ="modele_sdaster"),
        AFFE=FACT(
            statut="o",
            max="**",
            regles=(
                AU_MOINS_UN("TOUT", "GROUP_MA", "GROUP_NO", "NOEUD"),
                UN_PARMI("VALE", "VALE_I", "VALE_C", "VALE_F"),
            ),
            TOUT=tout(),
            GROUP_MA=group_ma(),
            GROUP_NO=group_no(),
            NOEUD=noeud(),
            NOM_CMP=SIMP(statut="o", typ="TXM", max="**"),
            VALE=SIMP(statut="f", typ="R", max="**"),
            VALE_I=SIMP(statut="f", typ="I", max="**"),
            VALE_C=SIMP(statut="f", typ="C", max="**"),
            VALE_F=SIMP(statut="f", typ=FONCTION, max="**"),
        ),
    ),
    b_asse=BLOC(
        condition=equal_to("OPERATION", "ASSE"),
        regles=(UN_PARMI("MAILLAGE", "MODELE"),),
        MAILLAGE=SIMP(statut="f", typ="maillage_sdaster"),
        MODELE=SIMP(statut="f", typ="modele_sdaster"),
        ASSE=FACT(
            statut="o",
            max="**",
            regles=(
                AU_MOINS_UN("TOUT", "GROUP_MA", "GROUP_NO"),
                PRESENT_PRESENT("NOM_CMP_RESU", "NOM_CMP"),
            ),
            TOUT=tout(),
            GROUP_MA=group_ma(),
            GROUP_NO=group_no(),
            CHAM_GD=SIMP(statut="o", typ=CHAM_GD),
            NOM_CMP=SIMP(statut="f", typ="TXM", max="**"),
            NOM_CMP_RESU=SIMP(statut="f", typ="TXM", max="**"),
            CUMUL=SIMP(statut="f", typ="TXM", defaut="NON", into=OUI_NON),
            COEF_R=SIMP(statut="f", typ="R", defaut=1.0),
            COEF_C=SIMP(statut="f", typ="C"),
        ),
    ),
    b_comb=BLOC(
        condition=equal_to("OPERATION", "COMB"),
        COMB=FACT(
            statut="o",
            max="**",
            CHAM_GD=SIMP(statut="o", typ="cham_no_sdaster"),
            COEF_R=SIMP(statut="o", typ="R"),
        ),
    ),
    b_eval=BLOC(
        condition=equal_to("OPERATION", "EVAL"),
        CHAM_F=SIMP(statut="o", typ=CHAM_GD),
        CHAM_PARA=SIMP(statut="o", typ=CHAM_GD, max="**"),
    ),
    b_xfem=BLOC(
        condition=equal_to("OPERATION", "ASSE_DEPL"),
        CHAM_GD=SIMP(statut="o", typ=CHAM_GD),
        MODELE=SIMP(statut="o", typ="modele_sdaster"),
        CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
    ),
    b_r2c=BLOC(condition=equal_to("OPERATION", "R2C"), CHAM_GD=SIMP(statut="o", typ=CHAM_GD)),
    b_c2r=BLOC(
        condition=equal_to("OPERATION", "C2R"),
        CHAM_GD=SIMP(statut="o", typ=CHAM_GD),
        PARTIE=SIMP(statut="o", typ="TXM", into=("REEL", "IMAG", "MODULE", "PHASE")),
    ),
    b_disc=BLOC(
        condition=equal_to("OPERATION", "DISC"),
        MODELE=SIMP(statut="f", typ="modele_sdaster"),
        CHAM_GD=SIMP(statut="o", typ=CHAM_GD),
    ),
    b_extr=BLOC(
        condition=equal_to("OPERATION", "EXTR"),
        regles=(
            AU_MOINS_UN("MAILLAGE", "FISSURE", "RESULTAT", "TABLE", "CARA_ELEM", "CHARGE"),
            PRESENT_ABSENT("MAILLAGE", "FISSURE", "RESULTAT", "CARA_ELEM", "CHARGE"),
            PRESENT_ABSENT("FISSURE", "MAILLAGE", "RESULTAT", "TABLE", "CARA_ELEM", "CHARGE"),
            PRESENT_ABSENT("RESULTAT", "FISSURE", "MAILLAGE", "TABLE", "CARA_ELEM", "CHARGE"),
            PRESENT_ABSENT("TABLE", "RESULTAT", "FISSURE", "CARA_ELEM", "CHARGE"),
            PRESENT_ABSENT("CARA_ELEM", "MAILLAGE", "TABLE", "RESULTAT", "FISSURE", "CHARGE"),
            PRESENT_ABSENT("CHARGE", "MAILLAGE", "TABLE", "RESULTAT", "FISSURE", "CARA_ELEM"),
        ),
        MAILLAGE=SIMP(statut="f", typ="maillage_sdaster"),
        FISSURE=SIMP(statut="f", typ="fiss_xfem"),
        RESULTAT=SIMP(statut="f", typ=RESULTAT),
        TABLE=SIMP(statut="f", typ="table_sdaster"),
        CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
        CHARGE=SIMP(statut="f", typ="char_meca"),
        b_extr_maillage=BLOC(
            condition=exists("MAILLAGE") & absent("TABLE"),
            NOM_CHAM=SIMP(statut="o", typ="TXM", into=("GEOMETRIE", "ABSC_CURV")),
        ),
        b_extr_cara_elem=BLOC(
            condition=exists("CARA_ELEM"),
            NOM_CHAM=SIMP(
                statut="o",
                typ="TXM",
                into=(
                    ".CARGENBA",
                    ".CARMASSI",
                    ".CARCABLE",
                    ".CARCOQUE",
                    ".CARGEOBA",
                    ".CARDISCK",
                    ".CARARCPO",
                    ".CARGENPO",
                    ".CARDISCM",
                    ".CARORIEN",
                    ".CARDISCA",
                    ".CVENTCXF",
                    ".CARPOUFL",
                    ".CARGEOPO",
                    ".CARDINFO",
                    ".CAFIBR",
                    ".CANBSP",
                ),
            ),  # fmt: skip
        ),
        b_extr_charge=BLOC(
            condition=exists("CHARGE"),
            NOM_CHAM=SIMP(
                statut="o",
                typ="TXM",
                into=(
                    ".CHME.EPSIN",
                    ".CHME.F1D1D",
                    ".CHME.F1D2D",
                    ".CHME.F1D3D",
                    ".CHME.F2D2D",
                    ".CHME.F2D3D",
                    ".CHME.F3D3D",
                    ".CHME.FCO2D",
                    ".CHME.FCO3D",
                    ".CHME.FELEC",
                    ".CHME.FL101",
                    ".CHME.FL102",
                    ".CHME.FLUX",
                    ".CHME.FORNO",
                    ".CHME.IMPE",
                    ".CHME.ONDE",
                    ".CHME.ONDPL",
                    ".CHME.ONDPR",
                    ".CHME.PESAN",
                    ".CHME.PRESS",
                    ".CHME.ROTAT",
                    ".CHME.SIGIN",
                    ".CHME.SIINT",
                    ".CHME.VFACE",
                ),
            ),  # fmt: skip
        ),
        b_extr_fissure=BLOC(
            condition=exists("FISSURE"),
            NOM_CHAM=SIMP(
                statut="o",
                typ="TXM",
                into=(
                    "LTNO",
                    "LNNO",
                    "GRLTNO",
                    "GRLNNO",
                    "STNO",
                    "BASLOC",
                    "GRI.LNNO",
                    "GRI.LTNO",
                    "GRI.GRLNNO",
                    "GRI.GRLTNO",
                ),
            ),  # fmt: skip
        ),
        b_extr_table=BLOC(condition=exists("TABLE"), MODELE=SIMP(statut="f", typ="modele_sdaster")),
        b_extr_resultat=BLOC(
            condition=exists("RESULTAT"),
            NOM_CHAM=SIMP(statut="o", typ="TXM", into=NOM_CHAM_INTO),
            TYPE_MAXI=SIMP(
                statut="f", typ="TXM", into=("MAXI", "MINI", "MAXI_ABS", "MINI_ABS", "NORM_TRAN")
            ),
            b_type_abs=BLOC(
                condition=is_in("TYPE_MAXI", ("MAXI_ABS", "MINI_ABS")),
                TYPE_RESU=SIMP(
                    statut="f",
                    typ="TXM",
                    defaut="VALE",
                    into=("VALE", "INST", "VALE_ABS", "NUME_ORDRE"),
                ),
            ),
            b_type_non_abs=BLOC(
                condition=is_in("TYPE_MAXI", ("MAXI", "MINI", "NORM_TRAN")),
                TYPE_RESU=SIMP(
                    statut="f", typ="TXM", defaut="VALE", into=("VALE", "INST", "NUME_ORDRE")
                ),
            ),
            b_type_maxi=BLOC(
                condition=exists("TYPE_MAXI"),
                regles=(
                    EXCLUS(
                        "TOUT_ORDRE",
                        "LIST_INST",
                        "LIST_FREQ",
                        "NUME_ORDRE",
                        "INST",
                        "FREQ",
                        "NUME_MODE",
                        "NOEUD_CMP",
                        "NOM_CAS",
                        "ANGLE",
                    ),
                ),  # fmt: skip
                TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
                LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
                LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
                NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
                INST=SIMP(statut="f", typ="R", max="**"),
                FREQ=SIMP(statut="f", typ="R", max="**"),
                NUME_MODE=SIMP(statut="f", typ="I", max="**"),
                NOEUD_CMP=SIMP(statut="f", typ="TXM", max="**"),
                NOM_CAS=SIMP(statut="f", typ="TXM", max="**"),
                ANGLE=SIMP(statut="f", typ="R", max="**"),
            ),
            b_non_type_maxi=BLOC(
                condition=absent("TYPE_MAXI"),
                regles=(
                    UN_PARMI(
                        "NUME_ORDRE", "INST", "FREQ", "NUME_MODE", "NOEUD_CMP", "NOM_CAS", "ANGLE"
                    ),
                ),
                NUME_ORDRE=SIMP(statut="f", typ="I"),
                INST=SIMP(statut="f", typ="R"),
                FREQ=SIMP(statut="f", typ="R"),
                NUME_MODE=SIMP(statut="f", typ="I"),
                NOEUD_CMP=SIMP(statut="f", typ="TXM", max=2),
                NOM_CAS=SIMP(statut="f", typ="TXM"),
                ANGLE=SIMP(statut="f", typ="R"),
                b_inst=BLOC(
                    condition=exists("INST"),
                    INTERPOL=SIMP(statut="f", typ="TXM", defaut="NON", into=("NON", "LIN")),
                ),
            ),
            **critere_precision(),
        ),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    TITRE=SIMP(statut="f", typ="TXM"),
)
