"""MACRO_ELAS_MULT: linear static responses for several load cases."""

from asterlite.catalogues.common import C_SOLVEUR

from asterlite.catalog import FACT, MACRO, SIMP, UN_PARMI
from asterlite.lang.values import CO


def _sdprod(kw) -> str:
    numbering = kw.get("NUME_DDL")
    if isinstance(numbering, CO):  # typed as code_aster's macro_elas_mult_prod does
        numbering.produced_type = "nume_ddl_sdaster"
    cases = kw.get("CAS_CHARGE") or ()
    if cases and cases[0].get("NOM_CAS") is None and cases[0].get("MODE_FOURIER") is not None:
        return "fourier_elas"
    return "mult_elas"


MACRO_ELAS_MULT = MACRO(
    nom="MACRO_ELAS_MULT",
    sd_prod=_sdprod,
    reentrant="f",
    fr="Linear static responses for several load cases or Fourier modes",
    regles=(UN_PARMI("CHAR_MECA_GLOBAL", "LIAISON_DISCRET"),),
    RESULTAT=SIMP(statut="f", typ=("mult_elas", "fourier_elas"), fr="Result to enrich"),
    MODELE=SIMP(statut="o", typ="modele_sdaster"),
    CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
    CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
    NUME_DDL=SIMP(statut="f", typ=("nume_ddl_sdaster", "CO")),
    CHAR_MECA_GLOBAL=SIMP(statut="f", typ="char_meca", max="**"),
    LIAISON_DISCRET=SIMP(statut="f", typ="TXM", into=("OUI",)),
    CAS_CHARGE=FACT(
        statut="o",
        max="**",
        regles=(UN_PARMI("NOM_CAS", "MODE_FOURIER"), UN_PARMI("CHAR_MECA", "VECT_ASSE")),
        NOM_CAS=SIMP(statut="f", typ="TXM"),
        MODE_FOURIER=SIMP(statut="f", typ="I"),
        TYPE_MODE=SIMP(statut="f", typ="TXM", defaut="SYME", into=("SYME", "ANTI", "TOUS")),
        CHAR_MECA=SIMP(statut="f", typ="char_meca", max="**"),
        OPTION=SIMP(statut="f", typ="TXM", into=("SIEF_ELGA", "SANS"), defaut="SIEF_ELGA"),
        SOUS_TITRE=SIMP(statut="f", typ="TXM"),
        VECT_ASSE=SIMP(statut="f", typ="cham_no_sdaster"),
    ),
    SOLVEUR=C_SOLVEUR("MACRO_ELAS_MULT"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    TITRE=SIMP(statut="f", typ="TXM"),
)
