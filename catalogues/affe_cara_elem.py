"""AFFE_CARA_ELEM: structural element properties (beams, bars, shells, discrete elements)."""

from asterlite.catalogues.common import OUI_NON, group_ma, group_no, tout

from asterlite.catalog import (
    AU_MOINS_UN,
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

FONCTION = ("fonction_sdaster", "nappe_sdaster", "formule")

# Number of values VALE holds for each CARA of a discrete element:
# {symmetric matrices: {CARA: count}, non-symmetric matrices: {CARA: count}}.
# K_ stiffness, M_ mass, A_ damping; T translations, TR translations+rotations;
# D diagonal; N on a node (POI1), L on a segment (SEG2).
DISCRET_3D_SIZES = (
    {
        "K_T_D_N": 3, "A_T_D_N": 3, "K_T_D_L": 3, "A_T_D_L": 3,
        "K_TR_D_N": 6, "A_TR_D_N": 6, "K_TR_D_L": 6, "A_TR_D_L": 6,
        "K_T_N": 6, "A_T_N": 6, "M_T_N": 6,
        "K_T_L": 21, "A_T_L": 21, "M_T_L": 21,
        "K_TR_N": 21, "A_TR_N": 21, "M_TR_N": 21,
        "K_TR_L": 78, "A_TR_L": 78, "M_TR_L": 78,
        "M_T_D_N": 1, "M_T_D_L": 1, "M_TR_D_N": 10, "M_TR_D_L": 4,
    },
    {
        "K_T_N": 9, "A_T_N": 9, "M_T_N": 9,
        "K_T_L": 36, "A_T_L": 36, "M_T_L": 36,
        "K_TR_N": 36, "A_TR_N": 36, "M_TR_N": 36,
        "K_TR_L": 144, "A_TR_L": 144, "M_TR_L": 144,
    },
)  # fmt: skip
DISCRET_2D_SIZES = (
    {
        "K_T_D_N": 2, "A_T_D_N": 2, "K_T_D_L": 2, "A_T_D_L": 2,
        "K_TR_D_N": 3, "A_TR_D_N": 3, "K_TR_D_L": 3, "A_TR_D_L": 3,
        "K_T_N": 3, "A_T_N": 3, "M_T_N": 3,
        "K_T_L": 10, "A_T_L": 10, "M_T_L": 10,
        "K_TR_N": 6, "A_TR_N": 6, "M_TR_N": 6,
        "K_TR_L": 21, "A_TR_L": 21, "M_TR_L": 21,
        "M_T_D_N": 1, "M_T_D_L": 1, "M_TR_D_N": 4, "M_TR_D_L": 2,
    },
    {
        "K_T_N": 4, "A_T_N": 4, "M_T_N": 4,
        "K_T_L": 16, "A_T_L": 16, "M_T_L": 16,
        "K_TR_N": 9, "A_TR_N": 9, "M_TR_N": 9,
        "K_TR_L": 36, "A_TR_L": 36, "M_TR_L": 36,
    },
)  # fmt: skip


def _matrix_blocs(sizes: dict[str, int]) -> dict:
    """CARA with one block per VALE size: GROUP_MA and VALE of the right length."""
    by_size: dict[int, list[str]] = {}
    for cara, size in sizes.items():
        by_size.setdefault(size, []).append(cara)
    blocs = {
        f"b_vale_{size}": BLOC(
            condition=equal_to("CARA", tuple(caras)),
            GROUP_MA=group_ma("o"),
            VALE=SIMP(statut="o", typ="R", min=size, max=size),
        )
        for size, caras in sorted(by_size.items())
    }
    return dict(CARA=SIMP(statut="f", typ="TXM", into=tuple(sizes)), **blocs)


def _discret(sizes: tuple[dict, dict], fr: str) -> FACT:
    symmetric, full = sizes
    return FACT(
        statut="f",
        max="**",
        fr=fr,
        REPERE=SIMP(statut="f", typ="TXM", into=("LOCAL", "GLOBAL"), defaut="GLOBAL"),
        AMOR_HYST=SIMP(statut="f", typ="R"),
        SYME=SIMP(statut="f", typ="TXM", defaut="OUI", into=OUI_NON),
        b_SYME_OUI=BLOC(condition=equal_to("SYME", "OUI"), **_matrix_blocs(symmetric)),
        b_SYME_NON=BLOC(condition=equal_to("SYME", "NON"), **_matrix_blocs(full)),
    )


def _orientation(cara: str, count: int, on_nodes: bool = False) -> BLOC:
    where = {"GROUP_NO": group_no("o")} if on_nodes else {"GROUP_MA": group_ma("o")}
    return BLOC(
        condition=equal_to("CARA", cara),
        **where,
        VALE=SIMP(statut="o", typ="R", min=count, max=count),
        PRECISION=SIMP(statut="f", typ="R"),
    )


POUTRE = FACT(
    statut="f",
    max="**",
    fr="Beam cross-sections",
    SECTION=SIMP(statut="o", typ="TXM", into=("GENERALE", "RECTANGLE", "CERCLE", "COUDE")),
    b_generale=BLOC(
        condition=equal_to("SECTION", "GENERALE"),
        GROUP_MA=group_ma("o"),
        VARI_SECT=SIMP(statut="f", typ="TXM", into=("CONSTANT", "HOMOTHETIQUE"), defaut="CONSTANT"),
        b_constant=BLOC(
            condition=equal_to("VARI_SECT", "CONSTANT"),
            regles=(
                PRESENT_ABSENT("TABLE_CARA", "CARA"),
                PRESENT_PRESENT("TABLE_CARA", "NOM_SEC"),
                PRESENT_PRESENT("CARA", "VALE"),
            ),
            TABLE_CARA=SIMP(statut="f", typ="table_sdaster"),
            NOM_SEC=SIMP(statut="f", typ="TXM"),
            CARA=SIMP(
                statut="f",
                typ="TXM",
                min=4,
                max=15,
                fr="A, IY, IZ and JX are required",
                into=(
                    "A",
                    "IY",
                    "IZ",
                    "AY",
                    "AZ",
                    "EY",
                    "EZ",
                    "JX",
                    "RY",
                    "RZ",
                    "RT",
                    "JG",
                    "IYR2",
                    "IZR2",
                    "AI",
                ),
            ),  # fmt: skip
            VALE=SIMP(statut="f", typ="R", min=4, max=15),
        ),
        b_homothetique=BLOC(
            condition=equal_to("VARI_SECT", "HOMOTHETIQUE"),
            CARA=SIMP(
                statut="o",
                typ="TXM",
                min=8,
                max=28,
                into=tuple(
                    f"{name}{end}"
                    for end in ("1", "2")
                    for name in (
                        "A",
                        "IY",
                        "IZ",
                        "AY",
                        "AZ",
                        "EY",
                        "EZ",
                        "JX",
                        "RY",
                        "RZ",
                        "RT",
                        "JG",
                        "IYR2",
                        "IZR2",
                    )
                ),  # fmt: skip
            ),
            VALE=SIMP(statut="o", typ="R", min=8, max=30),
        ),
    ),
    b_rectangle=BLOC(
        condition=equal_to("SECTION", "RECTANGLE"),
        GROUP_MA=group_ma("o"),
        VARI_SECT=SIMP(
            statut="f", typ="TXM", into=("CONSTANT", "HOMOTHETIQUE", "AFFINE"), defaut="CONSTANT"
        ),
        b_constant=BLOC(
            condition=equal_to("VARI_SECT", "CONSTANT"),
            CARA=SIMP(
                statut="o", typ="TXM", min=1, max=4, into=("H", "EP", "HY", "HZ", "EPY", "EPZ")
            ),
            VALE=SIMP(statut="o", typ="R", min=1, max=4),
        ),
        b_homothetique=BLOC(
            condition=equal_to("VARI_SECT", "HOMOTHETIQUE"),
            CARA=SIMP(
                statut="o",
                typ="TXM",
                min=2,
                max=8,
                into=(
                    "H1",
                    "HZ1",
                    "HY1",
                    "EP1",
                    "EPY1",
                    "EPZ1",
                    "H2",
                    "HZ2",
                    "HY2",
                    "EP2",
                    "EPY2",
                    "EPZ2",
                ),
            ),  # fmt: skip
            VALE=SIMP(statut="o", typ="R", min=2, max=8),
        ),
        b_affine=BLOC(
            condition=equal_to("VARI_SECT", "AFFINE"),
            CARA=SIMP(
                statut="o",
                typ="TXM",
                min=3,
                max=6,
                into=("HY", "EPY", "HZ1", "EPZ1", "HZ2", "EPZ2"),
            ),
            VALE=SIMP(statut="o", typ="R", min=3, max=6),
        ),
    ),
    b_cercle=BLOC(
        condition=equal_to("SECTION", "CERCLE"),
        VARI_SECT=SIMP(statut="f", typ="TXM", into=("CONSTANT", "HOMOTHETIQUE"), defaut="CONSTANT"),
        b_constant=BLOC(
            condition=equal_to("VARI_SECT", "CONSTANT"),
            GROUP_MA=group_ma("o"),
            CARA=SIMP(statut="o", typ="TXM", min=1, max=2, into=("R", "EP"), fr="R is required"),
            VALE=SIMP(statut="o", typ="R", min=1, max=2),
        ),
        b_homothetique=BLOC(
            condition=equal_to("VARI_SECT", "HOMOTHETIQUE"),
            GROUP_MA=group_ma("o"),
            CARA=SIMP(
                statut="o", typ="TXM", min=2, max=4, into=("R_DEBUT", "R_FIN", "EP_DEBUT", "EP_FIN")
            ),
            VALE=SIMP(statut="o", typ="R", min=2, max=4),
        ),
        MODI_METRIQUE=SIMP(statut="f", typ="TXM", defaut="NON", into=OUI_NON),
        FCX=SIMP(statut="f", typ=FONCTION),
        TUYAU_NSEC=SIMP(statut="f", typ="I", val_max=32, val_min=8, defaut=16),
        TUYAU_NCOU=SIMP(statut="f", typ="I", val_max=10, val_min=1, defaut=3),
    ),
    b_coude=BLOC(
        condition=equal_to("SECTION", "COUDE"),
        regles=(
            EXCLUS("COEF_FLEX", "COEF_FLEX_XY"),
            EXCLUS("COEF_FLEX", "COEF_FLEX_XZ"),
            EXCLUS("INDI_SIGM", "INDI_SIGM_XY"),
            EXCLUS("INDI_SIGM", "INDI_SIGM_XZ"),
            PRESENT_PRESENT("COEF_FLEX_XY", "COEF_FLEX_XZ"),
            PRESENT_PRESENT("INDI_SIGM_XY", "INDI_SIGM_XZ"),
        ),
        GROUP_MA=group_ma("o"),
        COEF_FLEX=SIMP(statut="f", typ="R", val_min=0.0),
        INDI_SIGM=SIMP(statut="f", typ="R", val_min=0.0),
        COEF_FLEX_XY=SIMP(statut="f", typ="R", val_min=0.0),
        INDI_SIGM_XY=SIMP(statut="f", typ="R", val_min=0.0),
        COEF_FLEX_XZ=SIMP(statut="f", typ="R", val_min=0.0),
        INDI_SIGM_XZ=SIMP(statut="f", typ="R", val_min=0.0),
    ),
)

BARRE = FACT(
    statut="f",
    max="**",
    fr="Bar cross-sections",
    GROUP_MA=group_ma("o"),
    SECTION=SIMP(statut="o", typ="TXM", into=("GENERALE", "RECTANGLE", "CERCLE")),
    b_generale=BLOC(
        condition=equal_to("SECTION", "GENERALE"),
        regles=(
            PRESENT_ABSENT("TABLE_CARA", "CARA"),
            PRESENT_PRESENT("TABLE_CARA", "NOM_SEC"),
            PRESENT_PRESENT("CARA", "VALE"),
        ),
        TABLE_CARA=SIMP(statut="f", typ="table_sdaster"),
        NOM_SEC=SIMP(statut="f", typ="TXM"),
        CARA=SIMP(statut="f", typ="TXM", into=("A",)),
        VALE=SIMP(statut="f", typ="R", min=1, max=1),
    ),
    b_rectangle=BLOC(
        condition=equal_to("SECTION", "RECTANGLE"),
        CARA=SIMP(statut="o", typ="TXM", min=1, max=4, into=("H", "EP", "HZ", "HY", "EPY", "EPZ")),
        VALE=SIMP(statut="o", typ="R", min=1, max=4),
    ),
    b_cercle=BLOC(
        condition=equal_to("SECTION", "CERCLE"),
        CARA=SIMP(statut="o", typ="TXM", min=1, max=2, into=("R", "EP")),
        VALE=SIMP(statut="o", typ="R", min=1, max=2),
    ),
    FCX=SIMP(statut="f", typ=FONCTION),
)

COQUE = FACT(
    statut="f",
    max="**",
    fr="Shell thickness and orientation",
    regles=(
        EXCLUS("ANGL_REP", "VECTEUR"),
        PRESENT_PRESENT("EXCENTREMENT", "INER_ROTA"),
        PRESENT_PRESENT("EXCENTREMENT_FO", "INER_ROTA"),
        UN_PARMI("EPAIS", "EPAIS_FO"),
        EXCLUS("EXCENTREMENT", "EXCENTREMENT_FO"),
    ),
    GROUP_MA=group_ma("o"),
    EPAIS=SIMP(statut="f", typ="R"),
    EPAIS_FO=SIMP(statut="f", typ=FONCTION),
    ANGL_REP=SIMP(statut="f", typ="R", min=2, max=2),
    VECTEUR=SIMP(statut="f", typ="R", min=3, max=3),
    A_CIS=SIMP(statut="f", typ="R", defaut=0.8333333),
    COEF_RIGI_DRZ=SIMP(statut="f", typ="R", defaut=1.0e-5),
    COQUE_NCOU=SIMP(statut="f", typ="I", defaut=1),
    EXCENTREMENT=SIMP(statut="f", typ="R"),
    EXCENTREMENT_FO=SIMP(statut="f", typ=FONCTION),
    INER_ROTA=SIMP(statut="f", typ="TXM", into=("OUI",)),
    MODI_METRIQUE=SIMP(statut="f", typ="TXM", defaut="NON", into=OUI_NON),
)

ORIENTATION = FACT(
    statut="f",
    max="**",
    fr="Local axes of beams and discrete elements",
    CARA=SIMP(
        statut="o",
        typ="TXM",
        into=(
            "VECT_Y",
            "VECT_Z",
            "ANGL_VRIL",
            "VECT_X_Y",
            "ANGL_NAUT",
            "GENE_TUYAU",
            "VECT_MAIL_Y",
            "VECT_MAIL_Z",
        ),
    ),  # fmt: skip
    b_cara_vect_y=_orientation("VECT_Y", 3),
    b_cara_vect_z=_orientation("VECT_Z", 3),
    b_cara_vect_mail_y=BLOC(
        condition=equal_to("CARA", "VECT_MAIL_Y"),
        GROUP_MA=group_ma("o"),
        TABLE_CARA=SIMP(statut="o", typ="table_sdaster"),
        NOM_SEC=SIMP(statut="o", typ="TXM"),
        VALE=SIMP(statut="o", typ="R", min=3, max=3),
        PRECISION=SIMP(statut="f", typ="R"),
    ),
    b_cara_vect_mail_z=BLOC(
        condition=equal_to("CARA", "VECT_MAIL_Z"),
        GROUP_MA=group_ma("o"),
        TABLE_CARA=SIMP(statut="o", typ="table_sdaster"),
        NOM_SEC=SIMP(statut="o", typ="TXM"),
        VALE=SIMP(statut="o", typ="R", min=3, max=3),
        PRECISION=SIMP(statut="f", typ="R"),
    ),
    b_cara_angl_vril=_orientation("ANGL_VRIL", 1),
    b_cara_vect_x_y=_orientation("VECT_X_Y", 6),
    b_cara_angl_naut=_orientation("ANGL_NAUT", 3),
    b_cara_gene_tuyau=BLOC(
        condition=equal_to("CARA", "GENE_TUYAU"),
        GROUP_NO=group_no("o"),
        VALE=SIMP(statut="o", typ="R", min=3, max=3),
        PRECISION=SIMP(statut="f", typ="R", defaut=1.0e-4),
        CRITERE=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=("RELATIF", "ABSOLU")),
    ),
)

AFFE_CARA_ELEM = OPER(
    nom="AFFE_CARA_ELEM",
    sd_prod="cara_elem",
    reentrant="n",
    fr="Assign properties to structural elements",
    regles=(
        AU_MOINS_UN(
            "POUTRE",
            "BARRE",
            "COQUE",
            "CABLE",
            "DISCRET",
            "DISCRET_2D",
            "MASSIF",
            "GRILLE",
            "MEMBRANE",
            "MULTIFIBRE",
            "RIGI_PARASOL",
            "MASS_REP",
        ),
        PRESENT_PRESENT("MULTIFIBRE", "GEOM_FIBRE"),
        EXCLUS("DISCRET", "DISCRET_2D"),
    ),  # fmt: skip
    MODELE=SIMP(statut="o", typ="modele_sdaster"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    VERIF=SIMP(statut="f", typ="TXM", max="**", into=("MAILLE",)),
    POUTRE=POUTRE,
    BARRE=BARRE,
    COQUE=COQUE,
    CABLE=FACT(
        statut="f",
        max="**",
        GROUP_MA=group_ma("o"),
        N_INIT=SIMP(statut="o", typ="R"),
        SECTION=SIMP(statut="o", typ="R"),
        FCX=SIMP(statut="f", typ=FONCTION),
    ),
    DISCRET=_discret(DISCRET_3D_SIZES, "Stiffness, mass or damping of 3D discrete elements"),
    DISCRET_2D=_discret(DISCRET_2D_SIZES, "Stiffness, mass or damping of 2D discrete elements"),
    ORIENTATION=ORIENTATION,
    MASSIF=FACT(
        statut="f",
        max="**",
        regles=(
            UN_PARMI("GROUP_MA", "TOUT"),
            UN_PARMI("ANGL_REP", "ORIG_AXE", "ANGL_EULER", "CHAM_ORIE"),
            PRESENT_PRESENT("ANGL_AXE", "ORIG_AXE"),
            ENSEMBLE("TOUT", "CHAM_ORIE"),
        ),
        GROUP_MA=group_ma(),
        TOUT=tout(),
        CHAM_ORIE=SIMP(statut="f", typ=("cham_no_sdaster", "carte_sdaster")),
        ANGL_REP=SIMP(statut="f", typ="R", min=1, max=3),
        ANGL_EULER=SIMP(statut="f", typ="R", min=1, max=3),
        ANGL_AXE=SIMP(statut="f", typ="R", min=2, max=2),
        ORIG_AXE=SIMP(statut="f", typ="R", min=2, max=3),
    ),
    GRILLE=FACT(
        statut="f",
        max="**",
        regles=(
            UN_PARMI("ANGL_REP_1", "ANGL_REP_2", "VECT_1", "VECT_2"),
            UN_PARMI("SECTION", "SECTION_FO"),
            EXCLUS("EXCENTREMENT", "EXCENTREMENT_FO"),
        ),
        GROUP_MA=group_ma("o"),
        SECTION=SIMP(statut="f", typ="R"),
        SECTION_FO=SIMP(statut="f", typ=FONCTION),
        ANGL_REP_1=SIMP(statut="f", typ="R", min=2, max=2),
        ANGL_REP_2=SIMP(statut="f", typ="R", min=2, max=2),
        EXCENTREMENT=SIMP(statut="f", typ="R"),
        EXCENTREMENT_FO=SIMP(statut="f", typ=FONCTION),
        VECT_1=SIMP(statut="f", typ="R", min=3, max=3),
        VECT_2=SIMP(statut="f", typ="R", min=3, max=3),
        REPERE=SIMP(statut="f", typ="TXM", into=("CYLINDRIQUE", "GLOBAL"), defaut="GLOBAL"),
        b_repere=BLOC(
            condition=equal_to("REPERE", "CYLINDRIQUE"),
            ORIGINE=SIMP(statut="o", typ="R", min=3, max=3),
            AXE_Z=SIMP(statut="o", typ="R", min=3, max=3),
        ),
        COEF_RIGI_DRZ=SIMP(statut="f", typ="R", defaut=1.0e-10),
    ),
    MEMBRANE=FACT(
        statut="f",
        max="**",
        regles=(EXCLUS("ANGL_REP_1", "ANGL_REP_2", "VECT_1", "VECT_2"),),
        GROUP_MA=group_ma("o"),
        EPAIS=SIMP(statut="o", typ="R", val_min=0.0),
        ANGL_REP_1=SIMP(statut="f", typ="R", min=2, max=2),
        ANGL_REP_2=SIMP(statut="f", typ="R", min=2, max=2),
        VECT_1=SIMP(statut="f", typ="R", min=3, max=3),
        VECT_2=SIMP(statut="f", typ="R", min=3, max=3),
        N_INIT=SIMP(statut="f", typ="R", defaut=0.0, val_min=0.0),
    ),
    RIGI_PARASOL=FACT(
        statut="f",
        max="**",
        fr="Spring mats spread over a foundation surface",
        regles=(
            UN_PARMI("COEF_GROUP", "FONC_GROUP"),
            UN_PARMI("COOR_CENTRE", "GROUP_NO_CENTRE"),
            UN_PARMI("GROUP_MA_POI1", "GROUP_MA_SEG2"),
        ),
        GROUP_MA=group_ma("o"),
        GROUP_MA_POI1=SIMP(statut="f", typ="grma"),
        GROUP_MA_SEG2=SIMP(statut="f", typ="grma"),
        FONC_GROUP=SIMP(statut="f", typ=FONCTION, max="**"),
        COEF_GROUP=SIMP(statut="f", typ="R", max="**"),
        REPERE=SIMP(statut="f", typ="TXM", into=("LOCAL", "GLOBAL"), defaut="GLOBAL"),
        CARA=SIMP(
            statut="o",
            typ="TXM",
            max=2,
            into=(
                "K_TR_D_N",
                "K_T_D_N",
                "K_TR_D_L",
                "K_T_D_L",
                "A_TR_D_N",
                "A_T_D_N",
                "A_TR_D_L",
                "A_T_D_L",
            ),
        ),  # fmt: skip
        b_cara=BLOC(condition=exists("CARA"), VALE=SIMP(statut="o", typ="R", max="**")),
        GROUP_NO_CENTRE=SIMP(statut="f", typ="grno"),
        COOR_CENTRE=SIMP(statut="f", typ="R", min=2, max=3),
        UNITE=SIMP(statut="f", typ="I"),
    ),
    MASS_REP=FACT(
        statut="f",
        max="**",
        fr="Mass spread over POI1 cells",
        GROUP_MA=SIMP(statut="o", typ="grma"),
        GROUP_MA_POI1=SIMP(statut="o", typ="grma"),
        VALE=SIMP(statut="o", typ="R"),
        TYPE=SIMP(statut="o", typ="TXM", into=("TOTALE", "LINEIQUE", "SURFACIQUE")),
        FONC_MULT=SIMP(statut="f", typ=FONCTION),
    ),
    GEOM_FIBRE=SIMP(statut="f", typ="gfibre_sdaster"),
    MULTIFIBRE=FACT(
        statut="f",
        max="**",
        GROUP_MA=group_ma("o"),
        GROUP_FIBRE=SIMP(statut="o", typ="TXM", max="**"),
        PREC_AIRE=SIMP(statut="f", typ="R", defaut=0.01),
        PREC_INERTIE=SIMP(statut="f", typ="R", defaut=0.1),
    ),
)
