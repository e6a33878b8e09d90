"""DEFI_GEOM_FIBRE: fibre groups of multifibre beam sections."""

from asterlite.catalog import (
    AU_MOINS_UN,
    FACT,
    OPER,
    PRESENT_ABSENT,
    PRESENT_PRESENT,
    SIMP,
    UN_PARMI,
)

DEFI_GEOM_FIBRE = OPER(
    nom="DEFI_GEOM_FIBRE",
    sd_prod="gfibre_sdaster",
    reentrant="n",
    fr="Fibre groups of multifibre beams, from section meshes or given points",
    regles=(AU_MOINS_UN("SECTION", "FIBRE"),),
    INFO=SIMP(
        statut="f", typ="I", defaut=1, into=(1, 2), no_effect="messages of code_aster's run only"
    ),
    SECTION=FACT(
        statut="f",
        max="**",
        regles=(
            AU_MOINS_UN("TOUT_SECT", "GROUP_MA_SECT"),
            PRESENT_ABSENT("TOUT_SECT", "GROUP_MA_SECT"),
            UN_PARMI("COOR_AXE_POUTRE", "TABLE_CARA"),
            PRESENT_PRESENT("TABLE_CARA", "NOM_SEC"),
        ),
        GROUP_FIBRE=SIMP(statut="o", typ="TXM"),
        TOUT_SECT=SIMP(statut="f", typ="TXM", into=("OUI",)),
        GROUP_MA_SECT=SIMP(statut="f", typ="grma", max="**"),
        MAILLAGE_SECT=SIMP(statut="o", typ="maillage_sdaster"),
        COOR_AXE_POUTRE=SIMP(statut="f", typ="R", min=2, max=2),
        ANGLE=SIMP(statut="f", typ="R", defaut=0.0),
        TABLE_CARA=SIMP(statut="f", typ="table_sdaster"),
        NOM_SEC=SIMP(statut="f", typ="TXM"),
    ),
    FIBRE=FACT(
        statut="f",
        max="**",
        regles=(
            UN_PARMI("COOR_AXE_POUTRE", "TABLE_CARA"),
            PRESENT_PRESENT("TABLE_CARA", "NOM_SEC"),
        ),
        GROUP_FIBRE=SIMP(statut="o", typ="TXM"),
        CARA=SIMP(statut="f", typ="TXM", defaut="SURFACE", into=("SURFACE", "DIAMETRE")),
        VALE=SIMP(statut="o", typ="R", max="**"),
        COOR_AXE_POUTRE=SIMP(statut="f", typ="R", min=2, max=2),
        ANGLE=SIMP(statut="f", typ="R", defaut=0.0),
        TABLE_CARA=SIMP(statut="f", typ="table_sdaster"),
        NOM_SEC=SIMP(statut="f", typ="TXM"),
    ),
    ASSEMBLAGE_FIBRE=FACT(
        statut="f",
        max="**",
        GROUP_ASSE_FIBRE=SIMP(statut="o", typ="TXM"),
        GROUP_FIBRE=SIMP(statut="o", typ="TXM", max="**"),
        COOR_GROUP_FIBRE=SIMP(statut="o", typ="R", min=2, max="**"),
        GX_GROUP_FIBRE=SIMP(statut="o", typ="R", max="**"),
    ),
)
