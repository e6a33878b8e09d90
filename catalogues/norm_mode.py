"""NORM_MODE: normalise eigenmodes by a chosen criterion."""

from asterlite.catalogues.common import noeud

from asterlite.catalog import BLOC, FACT, OPER, SIMP, UN_PARMI, exists


def _sdprod(kw) -> str:
    mode = kw.get("MODE")
    for name in ("mode_meca_c", "mode_flamb"):
        if getattr(mode, "satisfies", lambda _t: False)(name):
            return name
    return "mode_meca"


NORM_MODE = OPER(
    nom="NORM_MODE",
    sd_prod=_sdprod,
    reentrant="f",
    fr="Normalise eigenmodes",
    regles=(UN_PARMI("NORME", "GROUP_NO", "AVEC_CMP", "SANS_CMP"),),
    MODE=SIMP(statut="o", typ=("mode_meca", "mode_flamb")),
    NORME=SIMP(
        statut="f",
        typ="TXM",
        fr="Predefined norm: generalised mass, euclidean...",
        into=("MASS_GENE", "RIGI_GENE", "EUCL", "EUCL_TRAN", "TRAN", "TRAN_ROTA"),
    ),
    GROUP_NO=SIMP(statut="f", typ="grno", fr="One-node group whose component becomes 1"),
    b_noeud=BLOC(condition=exists("GROUP_NO"), NOM_CMP=SIMP(statut="o", typ="TXM")),
    AVEC_CMP=SIMP(statut="f", typ="TXM", max="**"),
    SANS_CMP=SIMP(statut="f", typ="TXM", max="**"),
    MODE_SIGNE=FACT(
        statut="f",
        fr="Impose the sign of one component",
        regles=(UN_PARMI("GROUP_NO", "NOEUD"),),
        NOEUD=noeud(max=1),
        GROUP_NO=SIMP(statut="f", typ="grno"),
        NOM_CMP=SIMP(statut="o", typ="TXM"),
        SIGNE=SIMP(statut="f", typ="TXM", defaut="POSITIF", into=("NEGATIF", "POSITIF")),
    ),
    MASSE=SIMP(statut="f", typ=("matr_asse_depl_r", "matr_asse_gene_r", "matr_asse_pres_r")),
    RAIDE=SIMP(
        statut="f",
        typ=("matr_asse_depl_r", "matr_asse_depl_c", "matr_asse_gene_r", "matr_asse_pres_r"),
    ),
    AMOR=SIMP(statut="f", typ=("matr_asse_depl_r", "matr_asse_gene_r")),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
