"""REST_SOUS_STRUC: restore substructured results on physical DOFs."""

from asterlite.catalogues.common import noeud

from asterlite.catalog import BLOC, EXCLUS, FACT, OPER, PRESENT_PRESENT, SIMP, UN_PARMI, equal_to

# type of the restored result, by type of RESU_GENE / RESULTAT
_PRODUCED = {
    "tran_gene": "dyna_trans",
    "mode_gene": "mode_meca",
    "mode_cycl": "mode_meca",
    "harm_gene": "dyna_harmo",
    "evol_noli": "evol_noli",
    "dyna_trans": "dyna_trans",
    "mode_meca": "mode_meca",
}


def _sdprod(kw) -> str:
    given = kw.get("RESU_GENE") or kw.get("RESULTAT")
    for name in getattr(given, "aster_types", ()):
        if name in _PRODUCED:
            return _PRODUCED[name]
    raise TypeError("REST_SOUS_STRUC: the type of the result to restore is not known")


REST_SOUS_STRUC = OPER(
    nom="REST_SOUS_STRUC",
    sd_prod=_sdprod,
    reentrant="n",
    fr="Restore on physical DOFs the results of a substructured computation",
    regles=(
        UN_PARMI("RESU_GENE", "RESULTAT"),
        EXCLUS(
            "TOUT_ORDRE",
            "NUME_ORDRE",
            "INST",
            "LIST_INST",
            "TOUT_INST",
            "NUME_MODE",
            "FREQ",
            "LIST_FREQ",
        ),
        EXCLUS("NOEUD", "GROUP_NO"),
        PRESENT_PRESENT("RESULTAT", "SQUELETTE"),
        UN_PARMI("SQUELETTE", "SOUS_STRUC", "SECTEUR"),
    ),
    RESULTAT=SIMP(statut="f", typ=("evol_noli", "dyna_trans", "mode_meca")),
    RESU_GENE=SIMP(statut="f", typ=("tran_gene", "mode_gene", "mode_cycl", "harm_gene")),
    NUME_DDL=SIMP(statut="f", typ="nume_ddl_sdaster"),
    MODE_MECA=SIMP(statut="f", typ="mode_meca"),
    TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
    NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
    NUME_MODE=SIMP(statut="f", typ="I", max="**"),
    TOUT_INST=SIMP(statut="f", typ="TXM", into=("OUI",)),
    INST=SIMP(statut="f", typ="R", max="**"),
    LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
    FREQ=SIMP(statut="f", typ="R", max="**"),
    LIST_FREQ=SIMP(statut="f", typ="listr8_sdaster"),
    CRITERE=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=("ABSOLU", "RELATIF")),
    b_prec_rela=BLOC(
        condition=equal_to("CRITERE", "RELATIF"),
        PRECISION=SIMP(statut="f", typ="R", defaut=1.0e-6),
    ),
    b_prec_abso=BLOC(condition=equal_to("CRITERE", "ABSOLU"), PRECISION=SIMP(statut="o", typ="R")),
    INTERPOL=SIMP(statut="f", typ="TXM", defaut="NON", into=("NON", "LIN")),
    TOUT_CHAM=SIMP(statut="f", typ="TXM", into=("OUI",)),
    NOM_CHAM=SIMP(
        statut="f",
        typ="TXM",
        max=8,
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
    GROUP_NO=SIMP(statut="f", typ="grno", max="**"),
    NOEUD=noeud(),
    GROUP_MA=SIMP(statut="f", typ="grma", max="**"),
    CYCLIQUE=FACT(
        statut="f",
        NB_SECTEUR=SIMP(statut="f", typ="I", max=1),
        NUME_DIAMETRE=SIMP(statut="f", typ="I", max=1),
        RESULTAT2=SIMP(
            statut="f", typ=("evol_elas", "evol_noli", "dyna_trans", "evol_char", "mode_meca")
        ),
    ),
    SQUELETTE=SIMP(statut="f", typ="squelette"),
    SOUS_STRUC=SIMP(statut="f", typ="TXM"),
    SECTEUR=SIMP(statut="f", typ="I"),
    TITRE=SIMP(statut="f", typ="TXM"),
)
