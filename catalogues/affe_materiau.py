"""AFFE_MATERIAU: assign materials to zones of a mesh."""

from asterlite.catalogues.common import group_ma, tout

from asterlite.catalog import AU_MOINS_UN, FACT, MACRO, SIMP, UN_PARMI

AFFE_MATERIAU = MACRO(
    nom="AFFE_MATERIAU",
    sd_prod="cham_mater",
    reentrant="n",
    fr="Assign materials to zones of a mesh",
    regles=(AU_MOINS_UN("MAILLAGE", "MODELE"), UN_PARMI("AFFE", "CHAM_MATER")),
    MAILLAGE=SIMP(statut="f", typ="maillage_sdaster"),
    MODELE=SIMP(statut="f", typ="modele_sdaster"),
    AFFE=FACT(
        statut="f",
        max="**",
        regles=(UN_PARMI("TOUT", "GROUP_MA"),),
        TOUT=tout(),
        GROUP_MA=group_ma(),
        MATER=SIMP(statut="o", typ="mater_sdaster", max=30),
    ),
    CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
    AFFE_COMPOR=FACT(
        statut="f",
        max="**",
        regles=(UN_PARMI("TOUT", "GROUP_MA"),),
        TOUT=tout(),
        GROUP_MA=group_ma(),
        COMPOR=SIMP(statut="o", typ="compor_sdaster"),
    ),
    AFFE_VARC=FACT(
        statut="f",
        max="**",
        fr="External state variables (simplified)",
        regles=(UN_PARMI("TOUT", "GROUP_MA"),),
        TOUT=tout(),
        GROUP_MA=group_ma(),
        NOM_VARC=SIMP(
            statut="o",
            typ="TXM",
            into=(
                "TEMP",
                "CORR",
                "IRRA",
                "HYDR",
                "SECH",
                "EPSA",
                "M_ACIER",
                "M_ZIRC",
                "NEUT1",
                "NEUT2",
                "NEUT3",
                "PTOT",
            ),
        ),  # fmt: skip
        CHAM_GD=SIMP(statut="f", typ=("cham_no_sdaster", "cham_elem", "carte_sdaster")),
        EVOL=SIMP(statut="f", typ=("evol_ther", "evol_varc", "evol_noli", "evol_elas")),
        NOM_CHAM=SIMP(statut="f", typ="TXM"),
        VALE_REF=SIMP(statut="f", typ="R"),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
