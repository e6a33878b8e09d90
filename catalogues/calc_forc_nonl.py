"""CALC_FORC_NONL: the nodal forces of non-linear behaviours (FONL_NOEU) along a result."""

from asterlite.catalog import BLOC, EXCLUS, FACT, OPER, SIMP, equal_to

CALC_FORC_NONL = OPER(
    nom="CALC_FORC_NONL",
    sd_prod="dyna_trans",
    reentrant="n",
    fr="A dyna_trans whose DEPL fields are the FONL_NOEU forces of the behaviours",
    regles=(
        EXCLUS(
            *("TOUT_ORDRE", "NUME_ORDRE", "INST", "FREQ", "NUME_MODE", "NOEUD_CMP"),
            *("LIST_INST", "LIST_FREQ", "LIST_ORDRE", "NOM_CAS"),
        ),
    ),
    RESULTAT=SIMP(statut="o", typ="resultat_sdaster"),
    TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
    NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
    NUME_MODE=SIMP(statut="f", typ="I", max="**"),
    NOEUD_CMP=SIMP(statut="f", typ="TXM", max="**"),
    NOM_CAS=SIMP(statut="f", typ="TXM"),
    INST=SIMP(statut="f", typ="R", max="**"),
    FREQ=SIMP(statut="f", typ="R", max="**"),
    LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
    LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
    LIST_ORDRE=SIMP(statut="f", typ="listis_sdaster"),
    CRITERE=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=("RELATIF", "ABSOLU")),
    b_prec_rela=BLOC(
        condition=equal_to("CRITERE", "RELATIF"),
        PRECISION=SIMP(statut="f", typ="R", defaut=1.0e-6),
    ),
    b_prec_abso=BLOC(condition=equal_to("CRITERE", "ABSOLU"), PRECISION=SIMP(statut="o", typ="R")),
    MODELE=SIMP(statut="o", typ="modele_sdaster"),
    CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
    CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
    COMPORTEMENT=FACT(
        statut="d",
        max="**",
        RELATION=SIMP(statut="f", typ="TXM", defaut="ELAS"),
        DEFORMATION=SIMP(statut="f", typ="TXM", defaut="PETIT"),
        TOUT=SIMP(statut="f", typ="TXM", into=("OUI",)),
        GROUP_MA=SIMP(statut="f", typ="grma", max="**"),
        MAILLE=SIMP(statut="c", typ="ma", max="**"),
    ),
)
