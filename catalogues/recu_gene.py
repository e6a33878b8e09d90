"""RECU_GENE: extract the generalized field of a modal result at one instant."""

from asterlite.catalogues.common_post import precision_blocs

from asterlite.catalog import BLOC, OPER, SIMP, UN_PARMI, absent, exists

RECU_GENE = OPER(
    nom="RECU_GENE",
    sd_prod="vect_asse_gene",
    reentrant="n",
    fr="Extract a generalized displacement, velocity or acceleration vector",
    regles=(UN_PARMI("FREQ", "INST"),),
    RESU_GENE=SIMP(statut="o", typ=("tran_gene", "harm_gene")),
    INST=SIMP(statut="f", typ="R"),
    FREQ=SIMP(statut="f", typ="R"),
    NOM_CHAM=SIMP(statut="f", typ="TXM", defaut="DEPL", into=("DEPL", "VITE", "ACCE")),
    b_interp_temp=BLOC(
        condition=exists("INST") & absent("FREQ"),
        INTERPOL=SIMP(statut="f", typ="TXM", defaut="NON", into=("NON", "LIN")),
        **precision_blocs(),
    ),
)
