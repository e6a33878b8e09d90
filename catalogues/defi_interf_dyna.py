"""DEFI_INTERF_DYNA: the interfaces of a substructure and their type."""

from asterlite.catalogues.common import noeud

from asterlite.catalog import ENSEMBLE, FACT, OPER, SIMP, UN_PARMI

DEFI_INTERF_DYNA = OPER(
    nom="DEFI_INTERF_DYNA",
    sd_prod="interf_dyna_clas",
    reentrant="n",
    fr="Define the interfaces of a substructure and give each a type",
    NUME_DDL=SIMP(statut="o", typ="nume_ddl_sdaster"),
    INTERFACE=FACT(
        statut="o",
        max="**",
        regles=(ENSEMBLE("NOM", "TYPE"), UN_PARMI("NOEUD", "GROUP_NO")),
        NOM=SIMP(statut="o", typ="TXM"),
        TYPE=SIMP(statut="o", typ="TXM", into=("MNEAL", "CRAIGB", "CB_HARMO", "AUCUN")),
        NOEUD=noeud(),
        GROUP_NO=SIMP(statut="f", typ="grno", max="**"),
        MASQUE=SIMP(statut="f", typ="TXM", max="**"),
    ),
    FREQ=SIMP(statut="f", typ="R", defaut=1.0),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
