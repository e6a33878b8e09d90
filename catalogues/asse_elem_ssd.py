"""ASSE_ELEM_SSD: DEFI_MODELE_GENE, NUME_DDL_GENE and ASSE_MATR_GENE in one
command, each result bound to its CO("NAME") of RESU_ASSE_SSD."""

from asterlite.catalogues.defi_modele_gene import interface_links

from asterlite.catalog import FACT, MACRO, PRESENT_PRESENT, SIMP
from asterlite.lang.values import CO

_OUTPUTS = {
    "MODELE": "modele_gene",
    "NUME_DDL_GENE": "nume_ddl_gene",
    "RIGI_GENE": "matr_asse_gene_r",
    "MASS_GENE": "matr_asse_gene_r",
}


def _sdprod(kw) -> None:
    for occurrence in kw.get("RESU_ASSE_SSD") or ():
        for keyword, type_name in _OUTPUTS.items():
            value = occurrence.get(keyword)
            if isinstance(value, CO):
                value.produced_type = type_name
    return None


ASSE_ELEM_SSD = MACRO(
    nom="ASSE_ELEM_SSD",
    sd_prod=_sdprod,
    reentrant="n",
    fr="DEFI_MODELE_GENE, NUME_DDL_GENE and ASSE_MATR_GENE in sequence",
    RESU_ASSE_SSD=FACT(
        statut="o",
        regles=(
            PRESENT_PRESENT("RIGI_GENE", "NUME_DDL_GENE"),
            PRESENT_PRESENT("MASS_GENE", "NUME_DDL_GENE"),
        ),
        MODELE=SIMP(statut="o", typ="CO"),
        NUME_DDL_GENE=SIMP(statut="o", typ="CO"),
        RIGI_GENE=SIMP(statut="o", typ="CO"),
        MASS_GENE=SIMP(statut="o", typ="CO"),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
    SOUS_STRUC=FACT(
        statut="o",
        max="**",
        NOM=SIMP(statut="o", typ="TXM"),
        MACR_ELEM_DYNA=SIMP(statut="o", typ="macr_elem_dyna"),
        ANGL_NAUT=SIMP(statut="f", typ="R", max=3),
        TRANS=SIMP(statut="f", typ="R", max=3),
    ),
    LIAISON=interface_links(),
    VERIF=FACT(
        statut="d",
        max=1,
        STOP_ERREUR=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
        PRECISION=SIMP(statut="f", typ="R", defaut=1.0e-3),
        CRITERE=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=("RELATIF", "ABSOLU")),
    ),
    METHODE=SIMP(statut="f", typ="TXM", defaut="CLASSIQUE", into=("CLASSIQUE", "ELIMINE")),
    STOCKAGE=SIMP(statut="f", typ="TXM", defaut="LIGN_CIEL", into=("LIGN_CIEL", "PLEIN")),
)
