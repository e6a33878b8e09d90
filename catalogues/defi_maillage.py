"""DEFI_MAILLAGE: a mesh of static superelements (super-cells)."""

from asterlite.catalogues.common import tout

from asterlite.catalog import (
    AU_MOINS_UN,
    BLOC,
    ENSEMBLE,
    FACT,
    OPER,
    SIMP,
    UN_PARMI,
    equal_to,
    exists,
)

DEFI_MAILLAGE = OPER(
    nom="DEFI_MAILLAGE",
    sd_prod="super_mesh",
    reentrant="n",
    fr="Mesh whose cells are superelements (MACR_ELEM_STAT)",
    DEFI_SUPER_MAILLE=FACT(
        statut="o",
        max="**",
        MACR_ELEM=SIMP(statut="o", typ=("macr_elem_stat", "macr_elem_dyna"), max="**"),
        SUPER_MAILLE=SIMP(statut="f", typ="ma", max="**"),
        TRAN=SIMP(statut="f", typ="R", max=3),
        ANGL_NAUT=SIMP(statut="f", typ="R", max=3),
        b_angl_naut=BLOC(condition=exists("ANGL_NAUT"), CENTRE=SIMP(statut="f", typ="R", max=3)),
    ),
    RECO_GLOBAL=FACT(
        statut="f",
        regles=(UN_PARMI("TOUT", "SUPER_MAILLE"),),
        TOUT=tout(),
        SUPER_MAILLE=SIMP(statut="f", typ="ma", max="**"),
        CRITERE=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=("RELATIF", "ABSOLU")),
        PRECISION=SIMP(statut="f", typ="R", defaut=1.0e-3),
    ),
    RECO_SUPER_MAILLE=FACT(
        statut="f",
        max="**",
        SUPER_MAILLE=SIMP(statut="o", typ="ma", max="**"),
        GROUP_NO=SIMP(statut="o", typ="grno", max="**"),
        OPTION=SIMP(
            statut="f",
            typ="TXM",
            defaut="GEOMETRIQUE",
            into=("GEOMETRIQUE", "NOEUD_A_NOEUD", "INVERSE"),
        ),
        geometrique=BLOC(
            condition=equal_to("OPTION", "GEOMETRIQUE"),
            CRITERE=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=("RELATIF", "ABSOLU")),
            PRECISION=SIMP(statut="f", typ="R", defaut=1.0e-3),
        ),
    ),
    DEFI_NOEUD=FACT(
        statut="c",
        max="**",
        regles=(UN_PARMI("TOUT", "NOEUD_INIT"),),
        TOUT=tout(),
        NOEUD_INIT=SIMP(statut="f", typ="no"),
        b_tout=BLOC(
            condition=exists("TOUT"),
            PREFIXE=SIMP(statut="f", typ="TXM"),
            INDEX=SIMP(statut="o", typ="I", max="**"),
        ),
        b_noeud_init=BLOC(
            condition=exists("NOEUD_INIT"),
            SUPER_MAILLE=SIMP(statut="o", typ="ma"),
            NOEUD_FIN=SIMP(statut="o", typ="no"),
        ),
    ),
    DEFI_GROUP_NO=FACT(
        statut="f",
        max="**",
        regles=(
            UN_PARMI("TOUT", "SUPER_MAILLE"),
            AU_MOINS_UN("INDEX", "GROUP_NO_FIN"),
            ENSEMBLE("GROUP_NO_INIT", "GROUP_NO_FIN"),
        ),
        TOUT=tout(),
        SUPER_MAILLE=SIMP(statut="f", typ="ma"),
        GROUP_NO_INIT=SIMP(statut="f", typ="grno"),
        PREFIXE=SIMP(statut="f", typ="TXM"),
        INDEX=SIMP(statut="f", typ="I", max="**"),
        GROUP_NO_FIN=SIMP(statut="f", typ="grno"),
    ),
)
