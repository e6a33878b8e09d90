"""RECU_TABLE: the parameters of a result, or a table stored inside another concept."""

from asterlite.catalog import OPER, SIMP, UN_PARMI

#: any concept (code_aster's ``assd``); the others spell out the usual ones
SOURCES = (
    "assd", "resultat_sdaster", "mode_meca", "mode_meca_c", "dyna_trans", "dyna_harmo",
    "evol_elas", "mult_elas", "tran_gene", "harm_gene", "table_sdaster", "table_fonction",
    "table_container", "maillage_sdaster", "matr_asse_gene_r", "fonction_sdaster",
    "nappe_sdaster",
)  # fmt: skip

RECU_TABLE = OPER(
    nom="RECU_TABLE",
    sd_prod="table_sdaster",
    reentrant="n",
    fr="Get the parameters of a result or a table held by another concept",
    regles=(UN_PARMI("NOM_TABLE", "NOM_PARA", "TOUT_PARA"),),
    CO=SIMP(statut="o", typ=SOURCES),
    NOM_TABLE=SIMP(statut="f", typ="TXM"),
    NOM_PARA=SIMP(statut="f", typ="TXM", max="**"),
    TOUT_PARA=SIMP(statut="f", typ="TXM", into=("OUI",)),
    TITRE=SIMP(statut="f", typ="TXM"),
)
