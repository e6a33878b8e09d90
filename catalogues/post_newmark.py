"""POST_NEWMARK: permanent displacement of a sliding block (Newmark's method)
in an embankment under a 2D dynamic result."""

from asterlite.catalog import AU_MOINS_UN, BLOC, FACT, MACRO, SIMP, UN_PARMI, equal_to, exists
from asterlite.lang.values import CO


def _sdprod(kw):
    """A table; MAILLAGE_RESU/MAILLAGE is a mesh."""
    for occurrence in kw.get("MAILLAGE_RESU") or ():
        output = occurrence.get("MAILLAGE")
        if isinstance(output, CO):
            output.produced_type = "maillage_sdaster"
    return "table_sdaster"


POST_NEWMARK = MACRO(
    nom="POST_NEWMARK",
    sd_prod=_sdprod,
    reentrant="n",
    fr="Newmark sliding-block displacement of a circular or given sliding zone",
    regles=(UN_PARMI("RAYON", "MAILLAGE_GLIS"), AU_MOINS_UN("RESULTAT", "RESULTAT_PESANTEUR")),
    MAILLAGE_GLIS=SIMP(statut="f", typ="maillage_sdaster"),
    RAYON=SIMP(statut="f", typ="R"),
    b_RAYON=BLOC(
        condition=exists("RAYON"),
        CENTRE_X=SIMP(statut="o", typ="R"),
        CENTRE_Y=SIMP(statut="o", typ="R"),
        RAFF_CERCLE=SIMP(statut="f", typ="I"),
    ),
    b_MAIL_GLIS=BLOC(
        condition=exists("MAILLAGE_GLIS"),
        GROUP_MA_GLIS=SIMP(statut="f", typ="grma", max="**"),
        GROUP_MA_LIGNE=SIMP(statut="f", typ="grma", max="**"),
    ),
    POSITION=SIMP(statut="f", typ="TXM", into=("AMONT", "AVAL"), defaut="AVAL"),
    RESULTAT=SIMP(statut="f", typ="dyna_trans"),
    b_RESULTAT=BLOC(
        condition=exists("RESULTAT"),
        # the zone's mass on meshes HOMARD refines (code_aster's catalogue
        # writes "default=" for RESI_RELA and ITER_MAXI, so they have none)
        VERI_MASSE=SIMP(statut="f", typ="TXM", into=("OUI", "NON"), defaut="NON"),
        b_VERI_MASS=BLOC(
            condition=equal_to("VERI_MASSE", "OUI"),
            RESI_RELA=SIMP(statut="f", typ="R", val_min=0.0),
            ITER_MAXI=SIMP(statut="f", typ="I", val_min=1),
            CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
        ),
    ),
    RESULTAT_PESANTEUR=SIMP(statut="f", typ=("evol_elas", "evol_noli")),
    b_RESULTAT_PESANTEUR=BLOC(
        condition=exists("RESULTAT_PESANTEUR"),
        CHAM_PHI=SIMP(statut="o", typ="cham_no_sdaster"),
        CHAM_COHESION=SIMP(statut="o", typ="cham_no_sdaster"),
        CHAM_FS=SIMP(statut="f", typ="CO"),
        NB_ECART_TYPE=SIMP(statut="f", typ="R", val_min=0.0, val_max=6.0, defaut=3.0),
        METHODE=SIMP(statut="f", typ="TXM", into=("ECLA_PG", "COLLOCATION"), defaut="ECLA_PG"),
    ),
    KY=SIMP(statut="f", typ="R"),
    GROUP_MA_CALC=SIMP(statut="o", typ="grma", max="**"),
    MAILLAGE_RESU=FACT(
        statut="f",
        max=1,
        NOM_GROUP=SIMP(statut="f", typ="TXM"),
        MAILLAGE=SIMP(statut="f", typ="CO"),
        # the last refined mesh of VERI_MASSE='OUI'
        MAILLAGE_MASSE=SIMP(statut="f", typ="CO"),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)

# evol_noli as RESULTAT is left out of this catalogue: asterlite refuses it
