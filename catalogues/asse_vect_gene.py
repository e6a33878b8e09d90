"""ASSE_VECT_GENE: project loads on the substructures' bases."""

from asterlite.catalog import BLOC, FACT, OPER, SIMP, equal_to

ASSE_VECT_GENE = OPER(
    nom="ASSE_VECT_GENE",
    sd_prod="vect_asse_gene",
    reentrant="n",
    fr="Project loads on the modal bases of substructures",
    NUME_DDL_GENE=SIMP(statut="o", typ="nume_ddl_gene"),
    METHODE=SIMP(statut="f", typ="TXM", defaut="CLASSIQUE", into=("CLASSIQUE", "INITIAL")),
    b_nume=BLOC(
        condition=equal_to("METHODE", "CLASSIQUE"),
        CHAR_SOUS_STRUC=FACT(
            statut="o",
            max="**",
            SOUS_STRUC=SIMP(statut="o", typ="TXM"),
            VECT_ASSE=SIMP(statut="o", typ="cham_no_sdaster"),
        ),
    ),
)
