"""EXTR_RESU: keep some fields and instants of a result (or restrict it to a sub-mesh)."""

from asterlite.catalogues.common_post import NOM_CHAM, concept_is, precision_blocs

from asterlite.catalog import EXCLUS, FACT, OPER, SIMP, UN_PARMI

RESULT_TYPES = (
    "evol_elas", "dyna_trans", "dyna_harmo", "acou_harmo", "mode_meca", "mode_acou", "evol_ther",
    "evol_noli", "evol_varc", "mult_elas", "fourier_elas", "fourier_ther",
)  # fmt: skip


def extr_resu_type(kw) -> str:
    """The type of the input result."""
    resultat = kw.get("RESULTAT")
    for name in RESULT_TYPES:
        if concept_is(resultat, name):
            return name
    return "dyna_trans"  # the usual input here, when check mode does not know the type


EXTR_RESU = OPER(
    nom="EXTR_RESU",
    sd_prod=extr_resu_type,
    reentrant="n",
    fr="Extract fields and instants from a result",
    RESULTAT=SIMP(statut="o", typ=RESULT_TYPES),
    ARCHIVAGE=FACT(
        statut="f",
        regles=(
            UN_PARMI(
                "NUME_ORDRE",
                "INST",
                "FREQ",
                "NUME_MODE",
                "NOEUD_CMP",
                "LIST_INST",
                "LIST_FREQ",
                "LIST_ORDRE",
                "NOM_CAS",
                "LIST_ARCH",
                "PAS_ARCH",
            ),
            EXCLUS("CHAM_EXCLU", "NOM_CHAM"),
        ),
        CHAM_EXCLU=SIMP(statut="f", typ="TXM", max="**"),
        NOM_CHAM=SIMP(statut="f", typ="TXM", max="**", into=NOM_CHAM),
        **precision_blocs(),
        LIST_ARCH=SIMP(statut="f", typ="listis_sdaster"),
        PAS_ARCH=SIMP(statut="f", typ="I"),
        NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
        LIST_ORDRE=SIMP(statut="f", typ="listis_sdaster"),
        INST=SIMP(statut="f", typ="R", max="**"),
        LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
        FREQ=SIMP(statut="f", typ="R", max="**"),
        LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
        NUME_MODE=SIMP(statut="f", typ="I", max="**"),
        NOEUD_CMP=SIMP(statut="f", typ="TXM", max="**"),
        NOM_CAS=SIMP(statut="f", typ="TXM"),
    ),
    RESTREINT=FACT(
        statut="f",
        max=1,
        fr="Restrict the result to a reduced mesh or model",
        regles=(UN_PARMI("MAILLAGE", "MODELE"),),
        MAILLAGE=SIMP(statut="f", typ="maillage_sdaster"),
        MODELE=SIMP(statut="f", typ="modele_sdaster"),
        CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
        CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
    ),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
