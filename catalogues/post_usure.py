"""POST_USURE: wear volumes and depths from the wear power of shocks (Archard and others)."""

from asterlite.catalogues.common_post import TABLE

from asterlite.catalog import (
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
)


def _wear_rules() -> tuple:
    return (
        UN_PARMI("MOBILE", "MATER_USURE"),
        EXCLUS("MATER_USURE", "OBSTACLE"),
        EXCLUS("MOBILE", "USURE_OBST"),
    )


def _kwu_coefficients(coef_usure: str) -> dict:
    return dict(
        COEF_FNOR=SIMP(statut="f", typ="R"),
        COEF_VTAN=SIMP(statut="f", typ="R"),
        COEF_USURE=SIMP(statut=coef_usure, typ="R"),
        COEF_K=SIMP(statut="f", typ="R", defaut=5.0),
        COEF_C=SIMP(statut="f", typ="R", defaut=10.0),
    )


def _edf_mz_coefficients() -> dict:
    return dict(
        COEF_USURE=SIMP(statut="f", typ="R", defaut=1.0e-13),
        COEF_B=SIMP(statut="f", typ="R", defaut=1.2),
        COEF_N=SIMP(statut="f", typ="R", defaut=2.44e-8),
        COEF_S=SIMP(statut="f", typ="R", defaut=1.14e-16),
    )


POST_USURE = OPER(
    nom="POST_USURE",
    sd_prod="table_sdaster",
    reentrant="f",
    fr="Wear volumes and wear depths from the wear power",
    regles=(
        UN_PARMI("TUBE_NEUF", "RESU_GENE", "PUIS_USURE"),
        UN_PARMI("TUBE_NEUF", "LOI_USURE"),
        PRESENT_ABSENT("TUBE_NEUF", "ETAT_INIT", "INST_FIN"),
        PRESENT_ABSENT("TUBE_NEUF", "RAYON_MOBILE", "RAYON_OBST", "LARGEUR_OBST", "CONTACT"),
        PRESENT_ABSENT("TUBE_NEUF", "ANGL_INCLI", "ANGL_ISTHME", "ANGL_IMPACT"),
        PRESENT_PRESENT("ANGL_INCLI", "CONTACT"),
        PRESENT_PRESENT("ANGL_ISTHME", "CONTACT"),
        PRESENT_PRESENT("ANGL_IMPACT", "CONTACT"),
    ),
    TUBE_NEUF=SIMP(statut="f", typ="TXM", into=("OUI",)),
    ETAT_INIT=FACT(
        statut="f",
        TABL_USURE=SIMP(statut="f", typ=TABLE),
        INST_INIT=SIMP(statut="f", typ="R"),
    ),
    RESU_GENE=SIMP(statut="f", typ="tran_gene"),
    INST_FIN=SIMP(statut="f", typ="R"),
    PUIS_USURE=SIMP(statut="f", typ="R"),
    LOI_USURE=SIMP(statut="f", typ="TXM", into=("ARCHARD", "KWU_EPRI", "EDF_MZ")),
    b_resu_gene=BLOC(
        condition=exists("RESU_GENE"),
        regles=(UN_PARMI("NOEUD", "GROUP_NO"),),
        NOEUD=SIMP(statut="c", typ="no"),
        GROUP_NO=SIMP(statut="f", typ="grno"),
    ),
    b_archard=BLOC(
        condition=equal_to("LOI_USURE", "ARCHARD"),
        regles=(
            UN_PARMI("MOBILE", "MATER_USURE", "SECTEUR"),
            EXCLUS("MATER_USURE", "OBSTACLE"),
            EXCLUS("MOBILE", "USURE_OBST"),
        ),
        MOBILE=FACT(statut="f", COEF_USURE=SIMP(statut="o", typ="R")),
        OBSTACLE=FACT(statut="f", COEF_USURE=SIMP(statut="o", typ="R")),
        SECTEUR=FACT(
            statut="f",
            max="**",
            COEF_USUR_MOBILE=SIMP(statut="f", typ="R"),
            COEF_USUR_OBST=SIMP(statut="f", typ="R"),
            ANGL_INIT=SIMP(statut="f", typ="R"),
            ANGL_FIN=SIMP(statut="f", typ="R"),
        ),
        MATER_USURE=SIMP(statut="f", typ="TXM"),
        USURE_OBST=SIMP(statut="f", typ="TXM", into=("OUI",)),
    ),
    b_kwu_epri=BLOC(
        condition=equal_to("LOI_USURE", "KWU_EPRI"),
        regles=_wear_rules(),
        MOBILE=FACT(statut="f", **_kwu_coefficients("f")),
        OBSTACLE=FACT(statut="f", **_kwu_coefficients("o")),
        MATER_USURE=SIMP(statut="f", typ="TXM"),
        USURE_OBST=SIMP(statut="f", typ="TXM", into=("OUI",)),
        FNOR_MAXI=SIMP(statut="f", typ="R"),
        VTAN_MAXI=SIMP(statut="f", typ="R"),
    ),
    b_edf_mz=BLOC(
        condition=equal_to("LOI_USURE", "EDF_MZ"),
        regles=_wear_rules(),
        MOBILE=FACT(statut="f", **_edf_mz_coefficients()),
        OBSTACLE=FACT(statut="f", **_edf_mz_coefficients()),
        MATER_USURE=SIMP(statut="f", typ="TXM"),
        USURE_OBST=SIMP(statut="f", typ="TXM", into=("OUI",)),
    ),
    CONTACT=SIMP(
        statut="f",
        typ="TXM",
        into=(
            "TUBE_BAV",
            "TUBE_ALESAGE",
            "TUBE_4_ENCO",
            "GRAPPE_ALESAGE",
            "TUBE_3_ENCO",
            "TUBE_TUBE",
            "GRAPPE_1_ENCO",
            "GRAPPE_2_ENCO",
        ),
    ),
    RAYON_MOBILE=SIMP(statut="f", typ="R"),
    RAYON_OBST=SIMP(statut="f", typ="R"),
    LARGEUR_OBST=SIMP(statut="f", typ="R"),
    ANGL_INCLI=SIMP(statut="f", typ="R"),
    ANGL_ISTHME=SIMP(statut="f", typ="R"),
    ANGL_IMPACT=SIMP(statut="f", typ="R"),
    b_not_tube_neuf=BLOC(
        condition=absent("TUBE_NEUF"),
        regles=(UN_PARMI("INST", "LIST_INST"),),
        INST_INIT=SIMP(statut="f", typ="R", defaut=-1.0),
        NB_BLOC=SIMP(statut="f", typ="I", defaut=1),
        COEF_INST=SIMP(statut="f", typ="R", defaut=1.0),
        INST=SIMP(statut="f", typ="R", max="**"),
        LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
    ),
    b_tube_neuf=BLOC(
        condition=exists("TUBE_NEUF"),
        INST=SIMP(statut="f", typ="R"),
        TABL_USURE=SIMP(statut="o", typ=TABLE),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    TITRE=SIMP(statut="f", typ="TXM"),
)
