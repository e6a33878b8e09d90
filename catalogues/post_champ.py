"""POST_CHAMP: fields of a result extracted on one sub-point (EXTR_COQUE: a
layer and level of plates); the other extractions are declared so that the
command refuses them by name."""

from asterlite.catalogues.extr_resu import extr_resu_type

from asterlite.catalog import EXCLUS, FACT, OPER, SIMP, UN_PARMI

_EXTRACTED = (
    "EPEQ_ELGA", "EPEQ_ELNO", "EPSI_ELGA", "EPSI_ELNO", "SIEF_ELGA", "SIEF_ELNO", "SIEQ_ELGA",
    "SIEQ_ELNO", "SIGM_ELGA", "SIGM_ELNO", "VARC_ELGA", "VARC_ELNO", "VARI_ELGA", "VARI_ELNO",
    "EPVC_ELGA", "EPVC_ELNO", "EPME_ELGA", "EPME_ELNO", "EPSP_ELGA", "EPSP_ELNO",
)  # fmt: skip

POST_CHAMP = OPER(
    nom="POST_CHAMP",
    sd_prod=extr_resu_type,
    reentrant="n",
    fr="Extract fields on a sub-point",
    regles=(
        UN_PARMI("EXTR_COQUE", "EXTR_TUYAU", "EXTR_PMF", "MIN_MAX_SP", "COQU_EXCENT"),
        EXCLUS("TOUT", "GROUP_MA"),
    ),
    RESULTAT=SIMP(statut="o", typ="resultat_sdaster"),
    TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
    NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
    INST=SIMP(statut="f", typ="R", max="**"),
    FREQ=SIMP(statut="f", typ="R", max="**"),
    TOUT=SIMP(statut="f", typ="TXM", into=("OUI",)),
    GROUP_MA=SIMP(statut="f", typ="grma", max="**"),
    EXTR_COQUE=FACT(
        statut="f",
        max=1,
        NOM_CHAM=SIMP(statut="o", typ="TXM", max=20, into=_EXTRACTED),
        NUME_COUCHE=SIMP(statut="f", typ="I", defaut=1),
        NIVE_COUCHE=SIMP(statut="f", typ="TXM", defaut="MOY", into=("SUP", "INF", "MOY")),
    ),
    EXTR_TUYAU=FACT(statut="f", max=1, NOM_CHAM=SIMP(statut="o", typ="TXM", max=20)),
    EXTR_PMF=FACT(statut="f", max=1, NOM_CHAM=SIMP(statut="o", typ="TXM", max=20)),
    MIN_MAX_SP=FACT(statut="f", max="**", NOM_CHAM=SIMP(statut="o", typ="TXM")),
    COQU_EXCENT=FACT(statut="f", max=2, NOM_CHAM=SIMP(statut="o", typ="TXM")),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
