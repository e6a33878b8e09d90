"""MACR_ADAP_MAIL: mesh adaptation by HOMARD (here its uniform refinement
and its refinement by zones)."""

from asterlite.catalog import AU_MOINS_UN, BLOC, EXCLUS, FACT, MACRO, SIMP, equal_to
from asterlite.lang.values import CO


def _sdprod(kw):
    """The refined mesh is the CO output MAILLAGE_NP1; the command makes nothing."""
    output = kw.get("MAILLAGE_NP1")
    if isinstance(output, CO):
        output.produced_type = "maillage_sdaster"
    return None


def _real(**kwargs):
    return SIMP(statut="f", typ="R", **kwargs)


MACR_ADAP_MAIL = MACRO(
    nom="MACR_ADAP_MAIL",
    sd_prod=_sdprod,
    fr="Adapt a mesh: uniform refinement or refinement in zones",
    MAILLAGE_N=SIMP(statut="o", typ="maillage_sdaster"),
    MAILLAGE_NP1=SIMP(statut="o", typ="CO"),
    ADAPTATION=SIMP(statut="o", typ="TXM", into=("RAFFINEMENT_UNIFORME", "RAFF_DERA_ZONE")),
    b_zone=BLOC(
        condition=equal_to("ADAPTATION", "RAFF_DERA_ZONE"),
        ZONE=FACT(
            statut="o",
            min=1,
            max="**",
            regles=(
                AU_MOINS_UN("X_MINI", "X_CENTRE", "HAUTEUR"),
                EXCLUS("X_MINI", "X_CENTRE", "HAUTEUR"),
                EXCLUS("Z_MINI", "X_CENTRE", "HAUTEUR"),
                EXCLUS("X_MINI", "Z_CENTRE", "HAUTEUR"),
                EXCLUS("Z_MINI", "Z_CENTRE", "HAUTEUR"),
                EXCLUS("X_MINI", "RAYON"),
                EXCLUS("Z_MINI", "RAYON"),
                EXCLUS("RAYON", "RAYON_INT"),
            ),
            TYPE=SIMP(
                statut="o",
                typ="TXM",
                into=(
                    "RECTANGLE",
                    "BOITE",
                    "DISQUE",
                    "SPHERE",
                    "CYLINDRE",
                    "DISQUE_PERCE",
                    "TUYAU",
                ),
            ),
            # DERAFFINEMENT needs HOMARD's refinement history: refused
            USAGE=SIMP(statut="f", typ="TXM", into=("RAFFINEMENT",), defaut="RAFFINEMENT"),
            X_MINI=_real(),
            X_MAXI=_real(),
            Y_MINI=_real(),
            Y_MAXI=_real(),
            Z_MINI=_real(),
            Z_MAXI=_real(),
            RAYON=_real(val_min=0.0),
            X_CENTRE=_real(),
            Y_CENTRE=_real(),
            Z_CENTRE=_real(),
            RAYON_INT=_real(val_min=0.0),
            RAYON_EXT=_real(val_min=0.0),
            X_AXE=_real(),
            Y_AXE=_real(),
            Z_AXE=_real(),
            X_BASE=_real(),
            Y_BASE=_real(),
            Z_BASE=_real(),
            HAUTEUR=_real(val_min=0.0),
        ),
        # the deepest level a zone refines: cells at it are not cut
        NIVE_MAX=SIMP(statut="f", typ="I", val_min=1),
    ),
    # HOMARD's reports on the meshes: asterlite logs the counts (NOMBRE)
    NOMBRE=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
    QUALITE=SIMP(statut="f", typ="TXM", defaut="NON", into=("NON",)),
    CONNEXITE=SIMP(statut="f", typ="TXM", defaut="NON", into=("NON",)),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2, 3, 4)),
)
