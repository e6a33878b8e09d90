"""CREA_MAILLAGE: build a new mesh from an existing one (POI1 cells, restriction...)."""

from asterlite.catalogues.common import NOM_CHAM_INTO, group_ma, group_no, maille, noeud, tout

from asterlite.catalog import AU_MOINS_UN, BLOC, FACT, OPER, SIMP, UN_PARMI, equal_to


def _all_or_groups(fr: str) -> FACT:
    return FACT(
        statut="f",
        fr=fr,
        regles=(UN_PARMI("TOUT", "GROUP_MA"),),
        TOUT=tout(),
        GROUP_MA=group_ma(),
    )


CREA_MAILLAGE = OPER(
    nom="CREA_MAILLAGE",
    sd_prod="maillage_sdaster",
    reentrant="n",
    fr="Create a mesh from an existing mesh",
    regles=(
        UN_PARMI(
            "COQU_VOLU",
            "CREA_FISS",
            "CREA_MAILLE",
            "CREA_POI1",
            "ECLA_PG",
            "HEXA20_27",
            "LINE_QUAD",
            "MODI_MAILLE",
            "QUAD_LINE",
            "REPERE",
            "RESTREINT",
            "PENTA15_18",
            "GEOM_FIBRE",
            "DECOUPE_LAC",
            "MODI_HHO",
            "COQUE_SOLIDE",
            "RAFFINEMENT",
        ),
    ),  # fmt: skip
    MAILLAGE=SIMP(statut="f", typ="maillage_sdaster"),
    GEOM_FIBRE=SIMP(statut="f", typ="gfibre_sdaster"),
    CREA_POI1=FACT(
        statut="f",
        max="**",
        fr="Create POI1 cells on nodes",
        regles=(AU_MOINS_UN("TOUT", "GROUP_MA", "GROUP_NO", "NOEUD"),),
        NOM_GROUP_MA=group_ma(),
        TOUT=tout(),
        GROUP_MA=group_ma(),
        GROUP_NO=group_no(),
        NOEUD=noeud(),
    ),
    CREA_MAILLE=FACT(
        statut="f",
        max="**",
        fr="Duplicate cells",
        regles=(UN_PARMI("TOUT", "GROUP_MA"),),
        NOM=SIMP(statut="o", typ="TXM"),
        TOUT=tout(),
        GROUP_MA=group_ma(),
    ),
    RESTREINT=FACT(
        statut="f",
        fr="Restrict a mesh to some element groups",
        GROUP_MA=group_ma("o"),
        TOUT_GROUP_MA=SIMP(statut="f", typ="TXM", defaut="NON", into=("OUI", "NON")),
        GROUP_NO=group_no(),
        TOUT_GROUP_NO=SIMP(statut="f", typ="TXM", defaut="NON", into=("OUI", "NON")),
    ),
    COQU_VOLU=FACT(
        statut="f",
        fr="Volume cells from shell cells",
        NOM=SIMP(statut="o", typ="TXM"),
        GROUP_MA=group_ma("o"),
        EPAIS=SIMP(statut="o", typ="R"),
        PLAN=SIMP(statut="o", typ="TXM", into=("SUP", "MOY", "INF")),
        b_MOY=BLOC(
            condition=equal_to("PLAN", "MOY"),
            TRANSLATION=SIMP(statut="o", typ="TXM", into=("SUP", "INF")),
        ),
    ),
    MODI_MAILLE=FACT(
        statut="f",
        max="**",
        fr="Change the cell type",
        regles=(AU_MOINS_UN("TOUT", "MAILLE", "GROUP_MA"),),
        TOUT=tout(),
        MAILLE=maille(),
        GROUP_MA=group_ma(),
        OPTION=SIMP(statut="o", typ="TXM", into=("TRIA6_7", "QUAD8_9", "SEG3_4", "QUAD_TRIA3")),
    ),
    RAFFINEMENT=FACT(
        statut="f",
        fr="Uniform refinement",
        TOUT=SIMP(statut="f", typ="TXM", into=("OUI",), defaut="OUI"),
        NIVEAU=SIMP(statut="f", typ="I", defaut=1),
    ),
    CREA_FISS=FACT(
        statut="f",
        max="**",
        NOM=SIMP(statut="o", typ="TXM"),
        GROUP_NO_1=SIMP(statut="o", typ="grno"),
        GROUP_NO_2=SIMP(statut="o", typ="grno"),
    ),
    LINE_QUAD=FACT(
        statut="f",
        fr="Linear to quadratic cells",
        regles=(UN_PARMI("TOUT", "GROUP_MA"),),
        TOUT=tout(),
        GROUP_MA=group_ma(),
        # code_aster 15 and older named the new nodes PREF_NOEUD + number from
        # PREF_NUME (defaults NS, 1); 17 numbers them: hidden, for those decks
        PREF_NOEUD=SIMP(statut="c", typ="TXM"),
        PREF_NUME=SIMP(statut="c", typ="I"),
    ),
    HEXA20_27=_all_or_groups("HEXA20 to HEXA27"),
    PENTA15_18=_all_or_groups("PENTA15 to PENTA18"),
    QUAD_LINE=_all_or_groups("Quadratic to linear cells"),
    MODI_HHO=FACT(statut="f", TOUT=tout()),
    COQUE_SOLIDE=FACT(statut="f", max="**", GROUP_MA=group_ma("o"), GROUP_MA_SURF=group_ma()),
    REPERE=FACT(
        statut="f",
        TABLE=SIMP(statut="o", typ="table_sdaster"),
        NOM_ORIG=SIMP(statut="f", typ="TXM", into=("CDG", "TORSION")),
        NOM_ROTA=SIMP(statut="f", typ="TXM", into=("INERTIE",)),
        b_cdg=BLOC(condition=equal_to("NOM_ORIG", "CDG"), GROUP_MA=SIMP(statut="f", typ="grma")),
    ),
    DECOUPE_LAC=FACT(
        statut="f",
        GROUP_MA_ESCL=group_ma("o"),
        DECOUPE_HEXA=SIMP(statut="f", typ="TXM", into=("PYRA", "HEXA"), defaut="PYRA"),
    ),
    ECLA_PG=FACT(
        statut="f",
        fr="Split cells around their Gauss points",
        MODELE=SIMP(statut="o", typ="modele_sdaster"),
        TOUT=tout(),
        GROUP_MA=group_ma(),
        SHRINK=SIMP(statut="f", typ="R", defaut=0.9),
        TAILLE_MIN=SIMP(statut="f", typ="R", defaut=0.0),
        NOM_CHAM=SIMP(
            statut="o", typ="TXM", max="**", into=tuple(n for n in NOM_CHAM_INTO if "ELGA" in n)
        ),
    ),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
