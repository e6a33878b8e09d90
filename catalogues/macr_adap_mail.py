"""MACR_ADAP_MAIL: mesh adaptation by HOMARD (here its uniform refinement)."""

from asterlite.catalog import MACRO, SIMP
from asterlite.lang.values import CO


def _sdprod(kw):
    """The refined mesh is the CO output MAILLAGE_NP1; the command makes nothing."""
    output = kw.get("MAILLAGE_NP1")
    if isinstance(output, CO):
        output.produced_type = "maillage_sdaster"
    return None


MACR_ADAP_MAIL = MACRO(
    nom="MACR_ADAP_MAIL",
    sd_prod=_sdprod,
    fr="Adapt a mesh: uniform refinement",
    MAILLAGE_N=SIMP(statut="o", typ="maillage_sdaster"),
    MAILLAGE_NP1=SIMP(statut="o", typ="CO"),
    ADAPTATION=SIMP(statut="o", typ="TXM", into=("RAFFINEMENT_UNIFORME",)),
    # HOMARD's reports on the meshes: asterlite logs the counts (NOMBRE)
    NOMBRE=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
    QUALITE=SIMP(statut="f", typ="TXM", defaut="NON", into=("NON",)),
    CONNEXITE=SIMP(statut="f", typ="TXM", defaut="NON", into=("NON",)),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2, 3, 4)),
)
