"""MODI_MAILLAGE: modify a mesh in place (deformation, translation, rotation...)."""

from asterlite.catalogues.common import group_ma, tout

from asterlite.catalog import (
    AU_MOINS_UN,
    BLOC,
    EXCLUS,
    FACT,
    OPER,
    PRESENT_ABSENT,
    SIMP,
    UN_PARMI,
    exists,
)

# the orientation/deformation operations are exclusive of each other
_SINGLE_OPS = (
    "ORIE_FISSURE", "DEFORME", "ORIE_PEAU", "ORIE_PEAU_2D", "ORIE_PEAU_3D",
    "ORIE_NORM_COQUE", "MODI_MAILLE", "ORIE_LIGNE",
)  # fmt: skip


def _single(name: str) -> PRESENT_ABSENT:
    return PRESENT_ABSENT(name, *(op for op in _SINGLE_OPS if op != name))


def _oriented_lines(vector: str) -> FACT:
    return FACT(
        statut="f",
        max="**",
        GROUP_MA=group_ma("o"),
        **{vector: SIMP(statut="f", typ="R", max=3)},
        b_vect=BLOC(
            condition=exists(vector),
            regles=(UN_PARMI("NOEUD", "GROUP_NO"),),
            NOEUD=SIMP(statut="c", typ="no"),
            GROUP_NO=SIMP(statut="f", typ="grno"),
        ),
    )


MODI_MAILLAGE = OPER(
    nom="MODI_MAILLAGE",
    sd_prod="maillage_sdaster",
    reentrant="o",
    fr="Modify an existing mesh",
    regles=(
        AU_MOINS_UN(
            *_SINGLE_OPS,
            "TRANSLATION",
            "ROTATION",
            "MODI_BASE",
            "ECHELLE",
            "ORIE_SHB",
            "SYMETRIE",
            "ABSC_CURV",
        ),
        *(_single(op) for op in _SINGLE_OPS),
        EXCLUS("ROTATION", "MODI_BASE"),
        EXCLUS("SYMETRIE", "ROTATION"),
        EXCLUS("SYMETRIE", "TRANSLATION"),
        EXCLUS("SYMETRIE", "MODI_BASE"),
        EXCLUS("SYMETRIE", "ECHELLE"),
    ),  # fmt: skip
    MAILLAGE=SIMP(statut="o", typ="maillage_sdaster"),
    ORIE_FISSURE=FACT(statut="f", GROUP_MA=group_ma("o")),
    DEFORME=FACT(
        statut="f",
        regles=(UN_PARMI("DEPL", "ALEA"),),
        OPTION=SIMP(statut="o", typ="TXM", into=("TRAN",)),
        DEPL=SIMP(statut="f", typ="cham_no_sdaster"),
        ALEA=SIMP(statut="f", typ="R"),
    ),
    ORIE_PEAU=FACT(
        statut="f",
        max="**",
        GROUP_MA_PEAU=group_ma("o"),
        GROUP_MA_INTERNE=group_ma(),
    ),
    ORIE_PEAU_2D=FACT(statut="f", max="**", GROUP_MA=group_ma("o"), GROUP_MA_SURF=group_ma()),
    ORIE_PEAU_3D=FACT(statut="f", max="**", GROUP_MA=group_ma("o"), GROUP_MA_VOLU=group_ma()),
    ORIE_SHB=FACT(statut="f", GROUP_MA=group_ma("o")),
    ORIE_NORM_COQUE=_oriented_lines("VECT_NORM"),
    ORIE_LIGNE=_oriented_lines("VECT_TANG"),
    MODI_MAILLE=FACT(
        statut="f",
        regles=(AU_MOINS_UN("GROUP_MA_FOND", "MAILLE_FOND", "GROUP_NO_FOND", "NOEUD_FOND"),),
        OPTION=SIMP(statut="o", typ="TXM", into=("NOEUD_QUART",)),
        GROUP_MA_FOND=SIMP(statut="f", typ="grma"),
        MAILLE_FOND=SIMP(statut="c", typ="ma"),
        GROUP_NO_FOND=SIMP(statut="f", typ="grno"),
        NOEUD_FOND=SIMP(statut="c", typ="no"),
    ),
    MODI_BASE=FACT(
        statut="f",
        VECT_X=SIMP(statut="o", typ="R", min=2, max=3),
        VECT_Y=SIMP(statut="f", typ="R", min=2, max=3),
    ),
    ECHELLE=SIMP(statut="f", typ="R"),
    TRANSLATION=SIMP(statut="f", typ="R", min=2, max=3),
    ROTATION=FACT(
        statut="f",
        max="**",
        regles=(EXCLUS("DIR", "POIN_2"),),
        POIN_1=SIMP(statut="o", typ="R", min=2, max=3),
        ANGLE=SIMP(statut="o", typ="R", defaut=0.0),
        POIN_2=SIMP(statut="f", typ="R", min=2, max=3),
        DIR=SIMP(statut="f", typ="R", min=2, max=3),
    ),
    SYMETRIE=FACT(
        statut="f",
        fr="Mirror the mesh about a plane (3D) or a line (2D)",
        POINT=SIMP(statut="o", typ="R", min=2, max=3),
        AXE_1=SIMP(statut="o", typ="R", min=2, max=3),
        AXE_2=SIMP(statut="f", typ="R", min=3, max=3),
    ),
    ABSC_CURV=FACT(
        statut="f",
        regles=(
            AU_MOINS_UN("TOUT", "GROUP_MA", "MAILLE"),
            UN_PARMI("GROUP_NO_ORIG", "NOEUD_ORIG"),
            EXCLUS("TOUT", "GROUP_MA"),
            EXCLUS("TOUT", "MAILLE"),
        ),
        TOUT=tout(),
        GROUP_MA=group_ma(),
        MAILLE=SIMP(statut="c", typ="ma", max="**"),
        GROUP_NO_ORIG=SIMP(statut="f", typ="grno"),
        NOEUD_ORIG=SIMP(statut="c", typ="no"),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
