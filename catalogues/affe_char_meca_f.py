"""AFFE_CHAR_MECA_F: mechanical loads and boundary conditions given by functions."""

from asterlite.catalogues.affe_char_meca import mechanical_loads
from asterlite.catalogues.common import OUI_NON

from asterlite.catalog import AU_MOINS_UN, BLOC, FACT, OPER, SIMP, exists

FONCTION = ("fonction_sdaster", "nappe_sdaster", "formule")

AFFE_CHAR_MECA_F = OPER(
    nom="AFFE_CHAR_MECA_F",
    sd_prod="char_meca",
    reentrant="n",
    fr="Mechanical loads and boundary conditions given by functions",
    regles=(
        AU_MOINS_UN(
            "DDL_IMPO",
            "DDL_POUTRE",
            "FACE_IMPO",
            "LIAISON_DDL",
            "LIAISON_OBLIQUE",
            "LIAISON_GROUP",
            "LIAISON_SOLIDE",
            "LIAISON_UNIF",
            "FORCE_NODALE",
            "FORCE_FACE",
            "FORCE_ARETE",
            "FORCE_CONTOUR",
            "FORCE_INTERNE",
            "PRES_REP",
            "PRE_EPSI",
            "FORCE_POUTRE",
            "ONDE_PLANE",
        ),
    ),  # fmt: skip
    VERI_NORM=SIMP(statut="f", typ="TXM", defaut="OUI", into=OUI_NON),
    MODELE=SIMP(statut="o", typ="modele_sdaster"),
    DOUBLE_LAGRANGE=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="OUI"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    **mechanical_loads(FONCTION),
    ONDE_PLANE=FACT(
        statut="f",
        max=1,
        fr="Seismic plane wave on paraxial boundaries (3D_ABSO, D_PLAN_ABSO)",
        DIRECTION=SIMP(statut="o", typ="R", min=3, max=3),
        COOR_SOURCE=SIMP(statut="f", typ="R", min=2, max=3),
        c_reflection=BLOC(
            condition=exists("COOR_SOURCE"),
            COOR_REFLECHI=SIMP(statut="f", typ="R", min=2, max=3),
        ),
        TYPE_ONDE=SIMP(statut="o", typ="TXM", into=("S", "P", "SV", "SH")),
        FONC_SIGNAL=SIMP(statut="o", typ=FONCTION),
        DEPL_IMPO=SIMP(statut="f", typ=FONCTION),
        GROUP_MA=SIMP(statut="f", typ="grma", max="**"),
    ),
)
