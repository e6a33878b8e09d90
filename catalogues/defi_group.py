"""DEFI_GROUP: add (or remove) node and element groups of a mesh, in place."""

from asterlite.catalogues.common import OUI_NON, group_ma, group_no, maille, noeud, tout

from asterlite.catalog import (
    AU_MOINS_UN,
    BLOC,
    EXCLUS,
    FACT,
    OPER,
    SIMP,
    UN_PARMI,
    absent,
    equal_to,
    exists,
)

TYPE_MAILLE = (
    "TOUT", "1D", "2D", "3D", "POI1", "SEG2", "SEG3", "SEG4", "TRIA3", "TRIA6", "TRIA7",
    "QUAD4", "QUAD8", "QUAD9", "TETRA4", "TETRA10", "PENTA6", "PENTA15", "PENTA18",
    "HEXA8", "HEXA20", "HEXA27", "PYRAM5", "PYRAM13",
)  # fmt: skip
CRIT_NOEUD = SIMP(
    statut="f", typ="TXM", defaut="AU_MOINS_UN", into=("TOUS", "AU_MOINS_UN", "MAJORITE")
)


def _center_and_axis(**extra) -> dict:
    """POINT / node centre, and a normal given by angles or a vector."""
    return dict(
        POINT=SIMP(statut="f", typ="R", max=3),
        NOEUD_CENTRE=SIMP(statut="c", typ="no"),
        GROUP_NO_CENTRE=SIMP(statut="f", typ="grno"),
        **extra,
    )


def _sdprod(kw) -> str:
    if kw.get("GRILLE") is not None:
        return "grille_sdaster"
    # a skeleton (DEFI_SQUELETTE) stays one, as in code_aster's defi_group_prod
    types = getattr(kw.get("MAILLAGE"), "aster_types", ())
    return "squelette" if "squelette" in types else "maillage_sdaster"


DEFI_GROUP = OPER(
    nom="DEFI_GROUP",
    sd_prod=_sdprod,
    # code_aster 17 changes MAILLAGE in place whether reuse= is given or not
    # (its DEFI_GROUP takes the mesh as result); decks call it bare too
    reentrant="f",
    fr="Define new node and element groups in a mesh",
    regles=(
        AU_MOINS_UN("CREA_GROUP_MA", "CREA_GROUP_NO", "DETR_GROUP_NO", "DETR_GROUP_MA"),
        UN_PARMI("MAILLAGE", "GRILLE"),
    ),
    MAILLAGE=SIMP(statut="f", typ=("maillage_sdaster", "squelette")),
    GRILLE=SIMP(statut="f", typ="grille_sdaster"),
    DETR_GROUP_MA=FACT(statut="f", max="**", NOM=SIMP(statut="o", typ="TXM", max="**")),
    DETR_GROUP_NO=FACT(statut="f", max="**", NOM=SIMP(statut="o", typ="TXM", max="**")),
    CREA_GROUP_MA=FACT(
        statut="f",
        max="**",
        regles=(UN_PARMI("TOUT", "GROUP_MA", "MAILLE", "INTERSEC", "UNION", "DIFFE", "OPTION"),),
        NOM=SIMP(statut="o", typ="TXM"),
        TOUT=tout(),
        GROUP_MA=SIMP(statut="f", typ="grma"),
        MAILLE=maille(),
        INTERSEC=group_ma(),
        UNION=group_ma(),
        DIFFE=group_ma(),
        TYPE_MAILLE=SIMP(statut="f", typ="TXM", defaut="TOUT", into=TYPE_MAILLE),
        OPTION=SIMP(
            statut="f",
            typ="TXM",
            into=("FACE_NORMALE", "SPHERE", "CYLINDRE", "BANDE", "APPUI", "FISS_XFEM"),
        ),
        b_group_ma=BLOC(
            condition=exists("GROUP_MA"),
            regles=(EXCLUS("POSITION", "NUME_INIT"),),
            NUME_INIT=SIMP(statut="f", typ="I", val_min=1),
            POSITION=SIMP(statut="f", typ="TXM", into=("INIT", "FIN", "MILIEU")),
            b_nume_init=BLOC(
                condition=exists("NUME_INIT"), NUME_FIN=SIMP(statut="f", typ="I", val_min=1)
            ),
        ),
        b_face_normale=BLOC(
            condition=equal_to("OPTION", "FACE_NORMALE"),
            regles=(UN_PARMI("ANGL_NAUT", "VECT_NORMALE"),),
            ANGL_NAUT=SIMP(statut="f", typ="R", max=2),
            VECT_NORMALE=SIMP(statut="f", typ="R", max=3),
            ANGL_PREC=SIMP(statut="f", typ="R", defaut=0.5),
            VERI_SIGNE=SIMP(statut="f", typ="TXM", defaut="OUI", into=OUI_NON),
        ),
        b_sphere=BLOC(
            condition=equal_to("OPTION", "SPHERE"),
            regles=(UN_PARMI("POINT", "NOEUD_CENTRE", "GROUP_NO_CENTRE"),),
            **_center_and_axis(RAYON=SIMP(statut="o", typ="R"), CRIT_NOEUD=CRIT_NOEUD),
        ),
        b_cylindre=BLOC(
            condition=equal_to("OPTION", "CYLINDRE"),
            regles=(
                UN_PARMI("POINT", "NOEUD_CENTRE", "GROUP_NO_CENTRE"),
                UN_PARMI("ANGL_NAUT", "VECT_NORMALE"),
            ),
            **_center_and_axis(
                RAYON=SIMP(statut="o", typ="R"),
                ANGL_NAUT=SIMP(statut="f", typ="R", max=2),
                VECT_NORMALE=SIMP(statut="f", typ="R", max=3),
                CRIT_NOEUD=CRIT_NOEUD,
            ),
        ),
        b_bande=BLOC(
            condition=equal_to("OPTION", "BANDE"),
            regles=(
                UN_PARMI("POINT", "NOEUD_CENTRE", "GROUP_NO_CENTRE"),
                UN_PARMI("ANGL_NAUT", "VECT_NORMALE"),
            ),
            **_center_and_axis(
                DIST=SIMP(statut="o", typ="R"),
                ANGL_NAUT=SIMP(statut="f", typ="R", max=2),
                VECT_NORMALE=SIMP(statut="f", typ="R", max=3),
                CRIT_NOEUD=CRIT_NOEUD,
            ),
        ),
        b_appui=BLOC(
            condition=equal_to("OPTION", "APPUI"),
            regles=(UN_PARMI("NOEUD", "GROUP_NO"),),
            NOEUD=noeud(),
            GROUP_NO=group_no(),
            TYPE_APPUI=SIMP(
                statut="o", typ="TXM", into=("AU_MOINS_UN", "TOUT", "SOMMET", "MAJORITE")
            ),
        ),
        b_fiss_xfem=BLOC(
            condition=equal_to("OPTION", "FISS_XFEM"),
            TYPE_GROUP=SIMP(
                statut="f",
                typ="TXM",
                defaut="XFEM",
                into=("HEAVISIDE", "CRACKTIP", "MIXTE", "FISSUREE", "XFEM"),
            ),
            FISSURE=SIMP(statut="o", typ="fiss_xfem", max="**"),
        ),
    ),
    CREA_GROUP_NO=FACT(
        statut="f",
        max="**",
        OPTION=SIMP(
            statut="f",
            typ="TXM",
            into=(
                "ENV_SPHERE",
                "ENV_CYLINDRE",
                "PLAN",
                "SEGM_DROI_ORDO",
                "NOEUD_ORDO",
                "TUNNEL",
                "INCLUSION",
                "FISS_XFEM",
                "INTERVALLE_VALE",
                "RELA_CINE_BP",
            ),
        ),
        b_option=BLOC(
            condition=absent("OPTION"),
            regles=(
                UN_PARMI(
                    "TOUT_GROUP_MA", "GROUP_MA", "GROUP_NO", "NOEUD", "INTERSEC", "UNION", "DIFFE"
                ),
            ),
            TOUT_GROUP_MA=SIMP(statut="f", typ="TXM", into=("OUI",)),
            GROUP_MA=group_ma(),
            GROUP_NO=group_no(),
            NOEUD=noeud(),
            INTERSEC=group_no(),
            UNION=group_no(),
            DIFFE=group_no(),
            b_nom_group_ma=BLOC(
                condition=exists("GROUP_MA"),
                NOM=SIMP(statut="f", typ="TXM", max="**"),
                CRIT_NOEUD=SIMP(
                    statut="f",
                    typ="TXM",
                    defaut="TOUS",
                    into=("TOUS", "SOMMET", "MILIEU", "CENTRE"),
                ),
            ),
            b_group_no=BLOC(
                condition=exists("GROUP_NO"),
                regles=(EXCLUS("POSITION", "NUME_INIT"),),
                NUME_INIT=SIMP(statut="f", typ="I", val_min=1),
                POSITION=SIMP(statut="f", typ="TXM", into=("INIT", "FIN", "MILIEU")),
                b_nume_init=BLOC(
                    condition=exists("NUME_INIT"), NUME_FIN=SIMP(statut="f", typ="I", val_min=1)
                ),
            ),
            b_nom=BLOC(
                condition=absent("GROUP_MA") & absent("TOUT_GROUP_MA"),
                NOM=SIMP(statut="o", typ="TXM"),
            ),
        ),
        b_env_sphere=BLOC(
            condition=equal_to("OPTION", "ENV_SPHERE"),
            regles=(UN_PARMI("POINT", "NOEUD_CENTRE", "GROUP_NO_CENTRE"),),
            NOM=SIMP(statut="o", typ="TXM"),
            **_center_and_axis(
                RAYON=SIMP(statut="o", typ="R"), PRECISION=SIMP(statut="o", typ="R")
            ),
        ),
        b_env_cylindre=BLOC(
            condition=equal_to("OPTION", "ENV_CYLINDRE"),
            regles=(
                UN_PARMI("POINT", "NOEUD_CENTRE", "GROUP_NO_CENTRE"),
                UN_PARMI("ANGL_NAUT", "VECT_NORMALE"),
            ),
            NOM=SIMP(statut="o", typ="TXM"),
            **_center_and_axis(
                RAYON=SIMP(statut="o", typ="R"),
                ANGL_NAUT=SIMP(statut="f", typ="R", max=3),
                VECT_NORMALE=SIMP(statut="f", typ="R", max=3),
                PRECISION=SIMP(statut="o", typ="R"),
            ),
        ),
        b_env_plan=BLOC(
            condition=equal_to("OPTION", "PLAN"),
            regles=(
                UN_PARMI("POINT", "NOEUD_CENTRE", "GROUP_NO_CENTRE"),
                UN_PARMI("ANGL_NAUT", "VECT_NORMALE"),
            ),
            NOM=SIMP(statut="o", typ="TXM"),
            **_center_and_axis(
                ANGL_NAUT=SIMP(statut="f", typ="R", max=3),
                VECT_NORMALE=SIMP(statut="f", typ="R", max=3),
                PRECISION=SIMP(statut="o", typ="R"),
            ),
        ),
        b_segm_droi_ordo=BLOC(
            condition=equal_to("OPTION", "SEGM_DROI_ORDO"),
            NOM=SIMP(statut="o", typ="TXM"),
            GROUP_NO=group_no(),
            GROUP_NO_ORIG=SIMP(statut="o", typ="grno"),
            GROUP_NO_EXTR=SIMP(statut="o", typ="grno"),
            PRECISION=SIMP(statut="o", typ="R"),
            CRITERE=SIMP(statut="o", typ="TXM", into=("ABSOLU", "RELATIF")),
        ),
        b_noeud_ordo=BLOC(
            condition=equal_to("OPTION", "NOEUD_ORDO"),
            NOM=SIMP(statut="o", typ="TXM"),
            GROUP_MA=group_ma("o"),
            GROUP_NO_ORIG=SIMP(statut="f", typ="grno"),
            GROUP_NO_EXTR=SIMP(statut="f", typ="grno"),
            VECT_ORIE=SIMP(statut="f", typ="R", max=3),
            ORIGINE=SIMP(statut="f", typ="TXM", into=("SANS",)),
        ),
        b_tunnel=BLOC(
            condition=equal_to("OPTION", "TUNNEL"),
            regles=(AU_MOINS_UN("TOUT", "GROUP_MA", "MAILLE"),),
            NOM=SIMP(statut="o", typ="TXM"),
            TOUT=tout(),
            GROUP_MA=group_ma(),
            MAILLE=maille(),
            GROUP_MA_AXE=group_ma(),
            GROUP_NO_ORIG=SIMP(statut="f", typ="grno"),
            RAYON=SIMP(statut="o", typ="R"),
            LONGUEUR=SIMP(statut="f", typ="R"),
        ),
        b_inclusion=BLOC(
            condition=equal_to("OPTION", "INCLUSION"),
            NOM=SIMP(statut="o", typ="TXM"),
            CAS_FIGURE=SIMP(statut="o", typ="TXM", into=("2D", "3D", "2.5D")),
            DISTANCE_MAX=SIMP(statut="f", typ="R"),
            GROUP_MA=group_ma("o"),
            GROUP_MA_INCL=group_ma("o"),
            MAILLAGE_INCL=SIMP(statut="f", typ="maillage_sdaster"),
        ),
        b_fiss_xfem=BLOC(
            condition=equal_to("OPTION", "FISS_XFEM"),
            NOM=SIMP(statut="o", typ="TXM"),
            TYPE_GROUP=SIMP(
                statut="o",
                typ="TXM",
                into=("HEAVISIDE", "CRACKTIP", "MIXTE", "XFEM", "ZONE_MAJ", "TORE"),
            ),
            FISSURE=SIMP(statut="o", typ="fiss_xfem", max="**"),
            b_rayon=BLOC(
                condition=equal_to("TYPE_GROUP", "TORE"),
                RAYON_TORE=SIMP(statut="o", typ="R", val_min=0.0),
            ),
        ),
        b_intervalle_vale=BLOC(
            condition=equal_to("OPTION", "INTERVALLE_VALE"),
            NOM=SIMP(statut="o", typ="TXM"),
            CHAM_GD=SIMP(statut="o", typ="cham_no_sdaster"),
            NOM_CMP=SIMP(statut="o", typ="TXM"),
            VALE=SIMP(statut="o", typ="R", min=2, max=2),
        ),
        b_rela_cine_bp=BLOC(
            condition=equal_to("OPTION", "RELA_CINE_BP"),
            CABLE_BP=SIMP(statut="o", typ="cabl_precont"),
            PREF_GRNO=SIMP(statut="f", typ="TXM", defaut="RCBP"),
        ),
    ),
    ALARME=SIMP(statut="f", typ="TXM", defaut="OUI", into=OUI_NON),
    INFO=SIMP(statut="f", typ="I", into=(1, 2)),
)
