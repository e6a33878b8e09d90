"""IMPR_MACR_ELEM: write a dynamic macro-element (I-DEAS or MISS3D)."""

from asterlite.catalog import BLOC, EXCLUS, PROC, SIMP, equal_to

IMPR_MACR_ELEM = PROC(
    nom="IMPR_MACR_ELEM",
    fr="Write a MACR_ELEM_DYNA in I-DEAS universal or MISS3D format",
    MACR_ELEM_DYNA=SIMP(statut="o", typ="macr_elem_dyna"),
    FORMAT=SIMP(statut="f", typ="TXM", defaut="IDEAS", into=("MISS_3D", "IDEAS")),
    b_ideas=BLOC(
        condition=equal_to("FORMAT", "IDEAS"),
        UNITE=SIMP(statut="f", typ="I", defaut=30),
        VERSION=SIMP(statut="f", typ="I", defaut=5, into=(5,)),
    ),
    b_miss_3d=BLOC(
        condition=equal_to("FORMAT", "MISS_3D"),
        regles=(EXCLUS("AMOR_REDUIT", "LIST_AMOR"),),
        UNITE=SIMP(statut="f", typ="I", defaut=26),
        SOUS_TITRE=SIMP(statut="f", typ="TXM"),
        AMOR_REDUIT=SIMP(statut="f", typ="R", max="**"),
        LIST_AMOR=SIMP(statut="f", typ="listr8_sdaster"),
        GROUP_MA_INTERF=SIMP(statut="o", typ="grma", max="**"),
        GROUP_MA_FLU_STR=SIMP(statut="f", typ="grma", max="**"),
        GROUP_MA_FLU_SOL=SIMP(statut="f", typ="grma", max="**"),
        GROUP_MA_SOL_SOL=SIMP(statut="f", typ="grma", max="**"),
        GROUP_MA_CONTROL=SIMP(statut="f", typ="grma", max="**"),
        FORMAT_R=SIMP(statut="f", typ="TXM", defaut="1PE12.5", into=("1PE12.5", "1PE16.9")),
        IMPR_MODE_MECA=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
        IMPR_MODE_STAT=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
    ),
)
