"""POST_DYNA_MODA_T: shock statistics (impacts, wear power) of a modal transient, as a table."""

from asterlite.catalog import EXCLUS, FACT, OPER, SIMP, UN_PARMI

POST_DYNA_MODA_T = OPER(
    nom="POST_DYNA_MODA_T",
    sd_prod="table_sdaster",
    reentrant="n",
    fr="Post-process the nonlinearities of a transient computed on a modal basis",
    regles=(UN_PARMI("CHOC", "RELA_EFFO_DEPL"),),
    RESU_GENE=SIMP(statut="o", typ="tran_gene"),
    CHOC=FACT(
        statut="f",
        max="**",
        fr="Shock statistics: impacts, forces, wear power",
        INST_INIT=SIMP(statut="f", typ="R", defaut=-1.0),
        INST_FIN=SIMP(statut="f", typ="R", defaut=999.0),
        NB_BLOC=SIMP(statut="f", typ="I", defaut=1),
        SEUIL_FORCE=SIMP(statut="f", typ="R", defaut=0.0),
        DUREE_REPOS=SIMP(statut="f", typ="R", defaut=0.0),
        OPTION=SIMP(statut="f", typ="TXM", defaut="USURE", into=("IMPACT", "USURE")),
        NB_CLASSE=SIMP(statut="f", typ="I", defaut=10),
    ),
    RELA_EFFO_DEPL=FACT(
        statut="f",
        fr="Statistics of a force-displacement nonlinearity",
        regles=(UN_PARMI("NOEUD", "GROUP_NO"), EXCLUS("NOEUD", "GROUP_NO")),
        NOEUD=SIMP(statut="c", typ="no"),
        GROUP_NO=SIMP(statut="f", typ="grno"),
        NOM_CMP=SIMP(statut="o", typ="TXM"),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    TITRE=SIMP(statut="f", typ="TXM"),
)
