"""AFFE_CHAR_MECA_F: mechanical loads and boundary conditions given by functions."""

from asterlite.catalogues.affe_char_meca import mechanical_loads
from asterlite.catalogues.common import OUI_NON

from asterlite.catalog import AU_MOINS_UN, OPER, SIMP

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
        ),
    ),  # fmt: skip
    VERI_NORM=SIMP(statut="f", typ="TXM", defaut="OUI", into=OUI_NON),
    MODELE=SIMP(statut="o", typ="modele_sdaster"),
    DOUBLE_LAGRANGE=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="OUI"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    **mechanical_loads(FONCTION),
)
