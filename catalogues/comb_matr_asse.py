"""COMB_MATR_ASSE: linear combination of assembled matrices."""

from asterlite.catalog import FACT, OPER, SIMP, UN_PARMI

MATR_ASSE_TYPES = (
    "matr_asse_depl_r", "matr_asse_depl_c", "matr_asse_temp_r", "matr_asse_temp_c",
    "matr_asse_pres_r", "matr_asse_pres_c", "matr_asse_gene_r", "matr_asse_gene_c",
)  # fmt: skip


def _satisfied_type(matrix) -> str:
    """The most specific matrix type a concept satisfies (depl_r when unknown)."""
    satisfies = getattr(matrix, "satisfies", None)
    for name in MATR_ASSE_TYPES:
        if satisfies is not None and satisfies(name):
            return name
    return "matr_asse_depl_r"


def _sdprod(kw) -> str:
    if kw.get("COMB_C"):
        family = _satisfied_type(kw["COMB_C"][0].get("MATR_ASSE")).rsplit("_", 1)[0]
        return family + "_c"
    if kw.get("COMB_R"):
        family = _satisfied_type(kw["COMB_R"][0].get("MATR_ASSE")).rsplit("_", 1)[0]
        return family + "_r"
    return "matr_asse_gene_r"  # CALC_AMOR_GENE


COMB_MATR_ASSE = OPER(
    nom="COMB_MATR_ASSE",
    sd_prod=_sdprod,
    reentrant="f",
    fr="Linear combination of assembled matrices",
    regles=(UN_PARMI("COMB_R", "COMB_C", "CALC_AMOR_GENE"),),
    MATR_ASSE=SIMP(statut="f", typ=MATR_ASSE_TYPES, fr="Matrix reused for the result"),
    COMB_R=FACT(
        statut="f",
        max="**",
        PARTIE=SIMP(statut="f", typ="TXM", into=("REEL", "IMAG")),
        MATR_ASSE=SIMP(statut="o", typ=MATR_ASSE_TYPES),
        COEF_R=SIMP(statut="o", typ="R"),
    ),
    COMB_C=FACT(
        statut="f",
        max="**",
        regles=(UN_PARMI("COEF_R", "COEF_C"),),
        MATR_ASSE=SIMP(statut="o", typ=MATR_ASSE_TYPES),
        COEF_R=SIMP(statut="f", typ="R"),
        COEF_C=SIMP(statut="f", typ="C"),
    ),
    CALC_AMOR_GENE=FACT(
        statut="f",
        regles=(UN_PARMI("AMOR_REDUIT", "LIST_AMOR"),),
        RIGI_GENE=SIMP(statut="o", typ="matr_asse_gene_r"),
        MASS_GENE=SIMP(statut="o", typ="matr_asse_gene_r"),
        AMOR_REDUIT=SIMP(statut="f", typ="R", max="**"),
        LIST_AMOR=SIMP(statut="f", typ="listr8_sdaster"),
    ),
    SANS_CMP=SIMP(statut="f", typ="TXM", into=("LAGR",)),
)
