"""POST_DECOLLEMENT: the share of a foundation surface whose nodes have lifted off."""

from asterlite.catalog import MACRO, SIMP

POST_DECOLLEMENT = MACRO(
    nom="POST_DECOLLEMENT",
    sd_prod="table_sdaster",
    reentrant="n",
    fr="Percentage of a surface whose nodes have a positive component, at each instant",
    RESULTAT=SIMP(statut="o", typ=("evol_noli", "dyna_trans")),
    NOM_CHAM=SIMP(statut="f", typ="TXM", defaut="DEPL"),
    NOM_CMP=SIMP(statut="f", typ="TXM", defaut="DZ"),
    GROUP_MA=SIMP(statut="o", typ="grma"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
