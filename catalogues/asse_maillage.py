"""ASSE_MAILLAGE: join two meshes."""

from asterlite.catalog import BLOC, FACT, OPER, SIMP, equal_to


def _sdprod(kw) -> str:
    return "super_mesh" if kw.get("OPERATION") == "SOUS_STR" else "maillage_sdaster"


ASSE_MAILLAGE = OPER(
    nom="ASSE_MAILLAGE",
    sd_prod=_sdprod,
    reentrant="n",
    fr="Join two meshes (SOUS_STR: superelements and cells, nodes of the same name merged)",
    MAILLAGE_1=SIMP(statut="o", typ="maillage_sdaster"),
    MAILLAGE_2=SIMP(statut="o", typ="maillage_sdaster"),
    OPERATION=SIMP(statut="o", typ="TXM", into=("SOUS_STR", "SUPERPOSE", "COLLAGE")),
    b_collage=BLOC(
        condition=equal_to("OPERATION", "COLLAGE"),
        COLLAGE=FACT(
            statut="o",
            GROUP_MA_1=SIMP(statut="o", typ="grma"),
            GROUP_MA_2=SIMP(statut="o", typ="grma"),
        ),
    ),
)
