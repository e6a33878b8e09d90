"""MECA_STATIQUE: linear static analysis, one solve per instant."""

from asterlite.catalogues.common import C_SOLVEUR

from asterlite.catalog import AU_MOINS_UN, BLOC, EXCLUS, FACT, OPER, SIMP, exists

FONCTION = ("fonction_sdaster", "nappe_sdaster", "formule")

MECA_STATIQUE = OPER(
    nom="MECA_STATIQUE",
    sd_prod="evol_elas",
    reentrant="f",
    fr="Linear static analysis",
    # INST is 0 when neither INST nor LIST_INST is given (code_aster's default)
    regles=(EXCLUS("INST", "LIST_INST"), AU_MOINS_UN("CHAM_MATER", "CARA_ELEM")),
    RESULTAT=SIMP(statut="f", typ="evol_elas"),
    MODELE=SIMP(statut="o", typ="modele_sdaster"),
    CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
    CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
    EXCIT=FACT(
        statut="f",
        max="**",
        CHARGE=SIMP(statut="o", typ=("char_meca", "char_cine_meca")),
        FONC_MULT=SIMP(statut="f", typ=FONCTION),
        TYPE_CHARGE=SIMP(statut="f", typ="TXM", defaut="FIXE_CSTE", into=("FIXE_CSTE",)),
    ),
    INST=SIMP(statut="f", typ="R"),
    LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
    b_list_inst=BLOC(
        condition=exists("LIST_INST"),
        INST_INIT=SIMP(statut="f", typ="R"),
        INST_FIN=SIMP(statut="f", typ="R"),
    ),
    OPTION=SIMP(statut="f", typ="TXM", defaut="SIEF_ELGA", into=("SIEF_ELGA", "SANS")),
    SOLVEUR=C_SOLVEUR("MECA_STATIQUE"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    TITRE=SIMP(statut="f", typ="TXM"),
)
