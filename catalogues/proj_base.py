"""PROJ_BASE: project assembled matrices and vectors on a modal basis.

Outputs are named with CO("NAME"): NUME_DDL_GENE (nume_ddl_gene),
MATR_ASSE_GENE/MATRICE (matr_asse_gene_r), VECT_ASSE_GENE/VECTEUR
(vect_asse_gene) and RESU_GENE/RESULTAT (tran_gene).
"""

from asterlite.catalog import AU_MOINS_UN, FACT, MACRO, SIMP, UN_PARMI
from asterlite.lang.values import CO

TYPE_VECT = ("FORC", "DEPL", "VITE", "ACCE")


def _type_output(value, type_name: str) -> None:
    """Give a CO("NAME") output its concept type, as code_aster's sd_prod does
    (``self.type_sdprod``): ``asterlite check`` binds the name to that type."""
    if isinstance(value, CO):
        value.produced_type = type_name


def _sdprod(kw) -> None:
    """Types of the CO outputs (code_aster's proj_base_prod): every projected
    matrix is real, whatever it was projected from."""
    _type_output(kw.get("NUME_DDL_GENE"), "nume_ddl_gene")
    for occurrence in kw.get("MATR_ASSE_GENE") or ():
        _type_output(occurrence.get("MATRICE"), "matr_asse_gene_r")
    for occurrence in kw.get("VECT_ASSE_GENE") or ():
        _type_output(occurrence.get("VECTEUR"), "vect_asse_gene")
    for occurrence in kw.get("RESU_GENE") or ():
        _type_output(occurrence.get("RESULTAT"), "tran_gene")
    return None


PROJ_BASE = MACRO(
    nom="PROJ_BASE",
    sd_prod=_sdprod,
    fr="Project assembled matrices and vectors on a modal or Ritz basis",
    regles=(AU_MOINS_UN("MATR_ASSE_GENE", "VECT_ASSE_GENE", "RESU_GENE"),),
    BASE=SIMP(statut="o", typ=("mode_meca", "mode_gene")),
    NB_VECT=SIMP(statut="f", typ="I"),
    STOCKAGE=SIMP(statut="f", typ="TXM", defaut="PLEIN", into=("PLEIN", "DIAG")),
    NUME_DDL_GENE=SIMP(statut="f", typ=("nume_ddl_gene", "CO")),
    MATR_ASSE_GENE=FACT(
        statut="f",
        max="**",
        regles=(UN_PARMI("MATR_ASSE", "MATR_ASSE_GENE"),),
        MATRICE=SIMP(statut="o", typ="CO"),
        MATR_ASSE=SIMP(statut="f", typ="matr_asse_depl_r"),
        MATR_ASSE_GENE=SIMP(statut="f", typ="matr_asse_gene_r"),
    ),
    VECT_ASSE_GENE=FACT(
        statut="f",
        max="**",
        regles=(UN_PARMI("VECT_ASSE", "VECT_ASSE_GENE"),),
        VECTEUR=SIMP(statut="o", typ="CO"),
        TYPE_VECT=SIMP(statut="o", typ="TXM", into=TYPE_VECT),
        VECT_ASSE=SIMP(statut="f", typ="cham_no_sdaster"),
        VECT_ASSE_GENE=SIMP(statut="f", typ="vect_asse_gene"),
    ),
    RESU_GENE=FACT(
        statut="f",
        max="**",
        RESULTAT=SIMP(statut="o", typ="CO"),
        TYPE_VECT=SIMP(statut="o", typ="TXM", into=TYPE_VECT),
        RESU=SIMP(statut="o", typ="dyna_trans"),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
