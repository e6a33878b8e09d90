"""AFFE_CHAR_MECA_C: mechanical loads and boundary conditions with complex values
(harmonic responses)."""

from asterlite.catalogues.affe_char_meca import mechanical_loads
from asterlite.catalogues.common import OUI_NON

from asterlite.catalog import AU_MOINS_UN, OPER, SIMP

_LOADS = mechanical_loads("C")

AFFE_CHAR_MECA_C = OPER(
    nom="AFFE_CHAR_MECA_C",
    sd_prod="char_meca",
    reentrant="n",
    fr="Mechanical loads and boundary conditions with complex values",
    regles=(AU_MOINS_UN("DDL_IMPO", "FORCE_POUTRE", "LIAISON_DDL"),),
    MODELE=SIMP(statut="o", typ="modele_sdaster"),
    DOUBLE_LAGRANGE=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="OUI"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    DDL_IMPO=_LOADS["DDL_IMPO"],
    FORCE_POUTRE=_LOADS["FORCE_POUTRE"],
    LIAISON_DDL=_LOADS["LIAISON_DDL"],
)
