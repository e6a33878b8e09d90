"""IMPR_GENE: print a result in generalized coordinates (RESULTAT text format)."""

from asterlite.catalogues.common_post import NOM_CHAM, precision_blocs

from asterlite.catalog import EXCLUS, FACT, PROC, SIMP

_ACCESS = (
    "TOUT_ORDRE", "NUME_ORDRE", "INST", "FREQ", "NUME_MODE", "LIST_INST", "LIST_FREQ",
    "TOUT_MODE", "TOUT_INST", "LIST_ORDRE",
)  # fmt: skip

IMPR_GENE = PROC(
    nom="IMPR_GENE",
    fr="Print a generalized result or vector",
    FORMAT=SIMP(statut="f", typ="TXM", defaut="RESULTAT", into=("RESULTAT",)),
    UNITE=SIMP(statut="f", typ="I", defaut=8),
    GENE=FACT(
        statut="o",
        max="**",
        regles=(
            EXCLUS(*_ACCESS),
            EXCLUS("TOUT_CMP_GENE", "NUME_CMP_GENE"),
            EXCLUS("TOUT_CHAM", "NOM_CHAM"),
            EXCLUS("TOUT_PARA", "NOM_PARA"),
        ),
        RESU_GENE=SIMP(statut="o", typ=("vect_asse_gene", "tran_gene", "mode_gene", "harm_gene")),
        TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
        NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
        LIST_ORDRE=SIMP(statut="f", typ="listis_sdaster"),
        INST=SIMP(statut="f", typ="R", max="**"),
        LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
        TOUT_INST=SIMP(statut="f", typ="TXM", into=("OUI",)),
        FREQ=SIMP(statut="f", typ="R", max="**"),
        LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
        TOUT_MODE=SIMP(statut="f", typ="TXM", into=("OUI",)),
        NUME_MODE=SIMP(statut="f", typ="I", max="**"),
        **precision_blocs(),
        TOUT_CMP_GENE=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
        NUME_CMP_GENE=SIMP(statut="f", typ="I", max="**"),
        TOUT_CHAM=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
        NOM_CHAM=SIMP(statut="f", typ="TXM", max="**", into=NOM_CHAM),
        TOUT_PARA=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
        NOM_PARA=SIMP(statut="f", typ="TXM", max="**"),
        SOUS_TITRE=SIMP(statut="f", typ="TXM"),
        INFO_CMP_GENE=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
        INFO_GENE=SIMP(statut="f", typ="TXM", into=("OUI", "NON")),
    ),
)
