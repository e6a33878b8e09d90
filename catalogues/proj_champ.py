"""PROJ_CHAMP: fields of one mesh projected on another."""

from asterlite.catalogues.common_post import NOM_CHAM, concept_is, precision_blocs

from asterlite.catalog import (
    AU_MOINS_UN,
    BLOC,
    EXCLUS,
    FACT,
    OPER,
    SIMP,
    UN_PARMI,
    equal_to,
    exists,
    is_in,
)

RESULTS = (
    "evol_elas", "evol_noli", "evol_ther", "dyna_trans", "dyna_harmo", "mode_meca",
    "mult_elas", "resultat_sdaster",
)  # fmt: skip
GEOM_FUNCTIONS = ("fonction_sdaster", "nappe_sdaster", "formule")


def proj_champ_type(kw) -> str:
    """The type of the projected result or field (a correspondence without either)."""
    source = kw.get("RESULTAT")
    if source is not None:
        for name in RESULTS:
            if concept_is(source, name):
                return name
        return "dyna_trans"  # check mode: the usual input here
    field = kw.get("CHAM_GD")
    if field is not None:
        if kw.get("METHODE") == "SOUS_POINT" or concept_is(field, "cham_elem"):
            return "cham_elem"
        return "cham_no_sdaster"
    return "corresp_2_mailla"


def _geometry(mesh_1=True):
    return {
        "TRANSF_GEOM_1": SIMP(statut="f", typ=GEOM_FUNCTIONS, min=2, max=3),
        "TRANSF_GEOM_2": SIMP(statut="f", typ=GEOM_FUNCTIONS, min=2, max=3),
    }


def _result_selection():
    return BLOC(
        condition=exists("RESULTAT"),
        regles=(
            EXCLUS(
                "TOUT_ORDRE", "NUME_ORDRE", "INST", "FREQ", "LIST_INST", "LIST_FREQ", "LIST_ORDRE"
            ),
            EXCLUS("TOUT_CHAM", "NOM_CHAM"),
        ),
        NOM_PARA=SIMP(statut="f", typ="TXM", max="**"),
        TOUT_CHAM=SIMP(statut="f", typ="TXM", into=("OUI",)),
        NOM_CHAM=SIMP(statut="f", typ="TXM", max="**", into=NOM_CHAM),
        NUME_DDL=SIMP(statut="f", typ="nume_ddl_sdaster"),
        TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
        NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
        LIST_ORDRE=SIMP(statut="f", typ="listis_sdaster"),
        INST=SIMP(statut="f", typ="R", max="**"),
        LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
        FREQ=SIMP(statut="f", typ="R", max="**"),
        LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
        NUME_MODE=SIMP(statut="f", typ="I", max="**"),
        NOEUD_CMP=SIMP(statut="f", typ="TXM", max="**"),
        b_acce_reel=BLOC(
            condition=exists("FREQ") | exists("LIST_FREQ") | exists("INST") | exists("LIST_INST"),
            **precision_blocs(),
        ),
    )


def _vis_a_vis(with_node_1: bool):
    first = ("TOUT_1", "GROUP_MA_1", "MAILLE_1", "GROUP_NO_1") + (
        ("NOEUD_1",) if with_node_1 else ()
    )
    extra = {"NOEUD_1": SIMP(statut="c", typ="no", max="**")} if with_node_1 else {}
    return FACT(
        statut="f",
        max="**",
        regles=(
            AU_MOINS_UN(*first),
            AU_MOINS_UN("TOUT_2", "GROUP_MA_2", "GROUP_NO_2", "NOEUD_2"),
        ),
        TOUT_1=SIMP(statut="f", typ="TXM", into=("OUI",)),
        GROUP_MA_1=SIMP(statut="f", typ="grma", max="**"),
        MAILLE_1=SIMP(statut="c", typ="ma", max="**"),
        GROUP_NO_1=SIMP(statut="f", typ="grno", max="**"),
        **extra,
        TOUT_2=SIMP(statut="f", typ="TXM", into=("OUI",)),
        GROUP_MA_2=SIMP(statut="f", typ="grma", max="**"),
        GROUP_NO_2=SIMP(statut="f", typ="grno", max="**"),
        NOEUD_2=SIMP(statut="c", typ="no", max="**"),
        CAS_FIGURE=SIMP(statut="f", typ="TXM", into=("2D", "3D", "2.5D", "1.5D", "0D")),
        **_geometry(),
        b_0D=BLOC(
            condition=equal_to("CAS_FIGURE", "0D"),
            DISTANCE_0D=SIMP(statut="o", typ="R", val_min=0.0),
        ),
    )


def _meshes():
    return dict(
        MODELE_1=SIMP(statut="f", typ="modele_sdaster"),
        MAILLAGE_1=SIMP(statut="f", typ=("maillage_sdaster", "squelette")),
        MODELE_2=SIMP(statut="f", typ="modele_sdaster"),
        MAILLAGE_2=SIMP(statut="f", typ="maillage_sdaster"),
    )


_PROJECTING = equal_to("PROJECTION", "OUI") & ~exists("MATR_PROJECTION")

PROJ_CHAMP = OPER(
    nom="PROJ_CHAMP",
    sd_prod=proj_champ_type,
    reentrant="f",
    fr="Project fields of one mesh on another",
    PROJECTION=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
    MATR_PROJECTION=SIMP(statut="f", typ="corresp_2_mailla"),
    b_1_et_2=BLOC(
        condition=_PROJECTING,
        regles=(
            UN_PARMI("RESULTAT", "CHAM_GD"),
            UN_PARMI("MODELE_1", "MAILLAGE_1"),
            UN_PARMI("MODELE_2", "MAILLAGE_2"),
        ),
        RESULTAT=SIMP(statut="f", typ=RESULTS),
        CHAM_GD=SIMP(statut="f", typ=("cham_no_sdaster", "cham_elem")),
        METHODE=SIMP(
            statut="f",
            typ="TXM",
            defaut="AUTO",
            into=("NUAGE_DEG_0", "NUAGE_DEG_1", "AUTO", "COLLOCATION", "ECLA_PG", "SOUS_POINT"),
        ),
        **_meshes(),
        b_nuage=BLOC(
            condition=is_in("METHODE", ("NUAGE_DEG_0", "NUAGE_DEG_1")),
            CHAM_NO_REFE=SIMP(statut="o", typ="cham_no_sdaster"),
        ),
        b_elem=BLOC(
            condition=is_in("METHODE", ("COLLOCATION", "ECLA_PG", "AUTO")),
            CAS_FIGURE=SIMP(statut="f", typ="TXM", into=("2D", "3D", "2.5D", "1.5D")),
            DISTANCE_MAX=SIMP(statut="f", typ="R"),
            DISTANCE_ALARME=SIMP(statut="f", typ="R"),
            **_geometry(),
            ALARME=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
            TYPE_CHAM=SIMP(statut="f", typ="TXM", into=("NOEU",)),
            PROL_VALE=SIMP(statut="f", typ="R"),
        ),
        b_sous_point=BLOC(
            condition=equal_to("METHODE", "SOUS_POINT"),
            CARA_ELEM=SIMP(statut="o", typ="cara_elem"),
            PROL_VALE=SIMP(statut="f", typ="R"),
            DISTANCE_MAX=SIMP(statut="f", typ="R"),
            DISTANCE_ALARME=SIMP(statut="f", typ="R"),
            **_geometry(),
        ),
        b_resultat=_result_selection(),
        VIS_A_VIS=_vis_a_vis(with_node_1=False),
    ),
    b_1=BLOC(
        condition=equal_to("PROJECTION", "NON"),
        regles=(UN_PARMI("MODELE_1", "MAILLAGE_1"), UN_PARMI("MODELE_2", "MAILLAGE_2")),
        METHODE=SIMP(statut="f", typ="TXM", defaut="COLLOCATION", into=("COLLOCATION", "COUPLAGE")),
        **_meshes(),
        b_elem=BLOC(
            condition=equal_to("METHODE", "COLLOCATION"),
            CAS_FIGURE=SIMP(statut="f", typ="TXM", into=("2D", "3D", "2.5D", "1.5D")),
            DISTANCE_MAX=SIMP(statut="f", typ="R"),
            DISTANCE_ALARME=SIMP(statut="f", typ="R"),
            **_geometry(),
            ALARME=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
        ),
        VIS_A_VIS=_vis_a_vis(with_node_1=True),
    ),
    b_2=BLOC(
        condition=exists("MATR_PROJECTION"),
        regles=(UN_PARMI("RESULTAT", "CHAM_GD"),),
        RESULTAT=SIMP(statut="f", typ=RESULTS),
        CHAM_GD=SIMP(statut="f", typ=("cham_no_sdaster", "cham_elem")),
        TYPE_CHAM=SIMP(statut="f", typ="TXM", into=("NOEU",)),
        NUME_DDL=SIMP(statut="f", typ="nume_ddl_sdaster"),
        MODELE_2=SIMP(statut="f", typ="modele_sdaster"),
        PROL_VALE=SIMP(statut="f", typ="R"),
        b_resultat=_result_selection(),
    ),
    # deprecated by code_aster 17, whose compat_syntax turns 'OUI' into PROL_VALE=0.0
    PROL_ZERO=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
