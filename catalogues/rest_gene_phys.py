"""REST_GENE_PHYS: bring a generalized (modal) result back to physical degrees of freedom."""

from asterlite.catalogues.common_post import FONCTION_OU_FORMULE, concept_is, precision_blocs

from asterlite.catalog import BLOC, EXCLUS, OPER, PRESENT_PRESENT, SIMP, absent


def rest_gene_phys_type(kw) -> str:
    """dyna_trans for a transient, mode_meca for modes, dyna_harmo for a harmonic result."""
    resu = kw.get("RESU_GENE")
    if concept_is(resu, "mode_gene", "mode_meca"):
        return "mode_meca"
    if concept_is(resu, "harm_gene"):
        return "dyna_harmo"
    return "dyna_trans"  # tran_gene, and the usual case when the input is unknown


REST_GENE_PHYS = OPER(
    nom="REST_GENE_PHYS",
    sd_prod=rest_gene_phys_type,
    reentrant="n",
    fr="Restore a result in generalized coordinates on the physical basis",
    regles=(
        EXCLUS("INST", "LIST_INST", "TOUT_INST", "TOUT_ORDRE", "NUME_ORDRE", "NUME_MODE"),
        EXCLUS("FREQ", "LIST_FREQ"),
        EXCLUS("MULT_APPUI", "CORR_STAT"),
        EXCLUS("MULT_APPUI", "NOEUD", "GROUP_NO"),
        EXCLUS("CORR_STAT", "NOEUD", "GROUP_NO"),
        EXCLUS("NOEUD", "GROUP_NO"),
        EXCLUS("MAILLE", "GROUP_MA"),
        PRESENT_PRESENT("ACCE_MONO_APPUI", "DIRECTION"),
    ),
    RESU_GENE=SIMP(statut="o", typ=("tran_gene", "mode_gene", "harm_gene", "mode_meca")),
    MODE_MECA=SIMP(statut="f", typ="mode_meca", fr="Modal basis, when not the one projected on"),
    NUME_DDL=SIMP(statut="f", typ="nume_ddl_sdaster"),
    TOUT_INST=SIMP(statut="f", typ="TXM", into=("OUI",)),
    INST=SIMP(statut="f", typ="R", max="**"),
    LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
    TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
    NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
    NUME_MODE=SIMP(statut="f", typ="I", max="**"),
    FREQ=SIMP(statut="f", typ="R", max="**"),
    LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
    **precision_blocs(),
    INTERPOL=SIMP(statut="f", typ="TXM", defaut="NON", into=("NON", "LIN")),
    MULT_APPUI=SIMP(statut="f", typ="TXM", into=("OUI",)),
    CORR_STAT=SIMP(statut="f", typ="TXM", into=("OUI",)),
    TOUT_CHAM=SIMP(statut="f", typ="TXM", into=("OUI",)),
    b_nom_cham=BLOC(
        condition=absent("TOUT_CHAM"),
        NOM_CHAM=SIMP(
            statut="f",
            typ="TXM",
            max=8,
            defaut="ACCE",
            into=(
                "DEPL",
                "VITE",
                "ACCE",
                "ACCE_ABSOLU",
                "EFGE_ELNO",
                "SIPO_ELNO",
                "SIGM_ELNO",
                "FORC_NODA",
            ),
        ),
    ),
    GROUP_NO=SIMP(statut="f", typ="grno", max="**"),
    NOEUD=SIMP(statut="c", typ="no", max="**"),
    GROUP_MA=SIMP(statut="f", typ="grma", max="**"),
    MAILLE=SIMP(statut="c", typ="ma", max="**"),
    ACCE_MONO_APPUI=SIMP(statut="f", typ=FONCTION_OU_FORMULE, max=3),
    DIRECTION=SIMP(statut="f", typ="R", min=3, max=9),
    TITRE=SIMP(statut="f", typ="TXM"),
)
