"""POST_GENE_PHYS: physical values of a modal result at chosen nodes/elements, as a table."""

from asterlite.catalogues.common_post import FONCTION_OU_FORMULE, any_given, precision_blocs

from asterlite.catalog import AU_MOINS_UN, BLOC, EXCLUS, FACT, OPER, PRESENT_PRESENT, SIMP, equal_to

POST_GENE_PHYS = OPER(
    nom="POST_GENE_PHYS",
    sd_prod="table_sdaster",
    reentrant="n",
    fr="Post-process a generalized dynamic result on the physical basis, into a table",
    RESU_GENE=SIMP(statut="o", typ=("tran_gene", "harm_gene")),
    MODE_MECA=SIMP(statut="f", typ="mode_meca"),
    OBSERVATION=FACT(
        statut="o",
        min=1,
        max="**",
        regles=(
            EXCLUS(
                "INST", "LIST_INST", "TOUT_INST", "NUME_ORDRE", "TOUT_ORDRE", "FREQ", "LIST_FREQ"
            ),
            EXCLUS("NOEUD", "GROUP_NO", "MAILLE", "GROUP_MA"),
            AU_MOINS_UN("NOEUD", "GROUP_NO", "MAILLE", "GROUP_MA"),
        ),
        NOM_CHAM=SIMP(
            statut="f",
            typ="TXM",
            defaut="DEPL",
            into=(
                "DEPL",
                "VITE",
                "ACCE",
                "DEPL_ABSOLU",
                "VITE_ABSOLU",
                "ACCE_ABSOLU",
                "FORC_NODA",
                "EFGE_ELNO",
                "EGRU_ELNO",
                "SIPO_ELNO",
                "SIGM_ELNO",
                "EFGE_ELGA",
                "SIGM_ELGA",
            ),
        ),
        NOM_CMP=SIMP(statut="f", typ="TXM", max=20),
        INST=SIMP(statut="f", typ="R", max="**"),
        TOUT_INST=SIMP(statut="f", typ="TXM", into=("OUI",)),
        LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
        NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
        TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
        FREQ=SIMP(statut="f", typ="R", max="**"),
        LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
        b_prec=BLOC(
            condition=any_given("INST", "LIST_INST", "FREQ", "LIST_FREQ"),
            **precision_blocs(),
        ),
        NOEUD=SIMP(statut="c", typ="no", max="**"),
        GROUP_NO=SIMP(statut="f", typ="grno", max="**"),
        MAILLE=SIMP(statut="c", typ="ma", max="**"),
        GROUP_MA=SIMP(statut="f", typ="grma", max="**"),
        b_acce_abs=BLOC(
            condition=equal_to("NOM_CHAM", "ACCE_ABSOLU"),
            regles=(PRESENT_PRESENT("ACCE_MONO_APPUI", "DIRECTION"),),
            ACCE_MONO_APPUI=SIMP(statut="f", typ=FONCTION_OU_FORMULE, max=3),
            DIRECTION=SIMP(statut="f", typ="R", min=3, max=9),
        ),
    ),
    TITRE=SIMP(statut="f", typ="TXM"),
)
