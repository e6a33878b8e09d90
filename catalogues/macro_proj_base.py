"""MACRO_PROJ_BASE (code_aster 10 to 11): project assembled matrices and vectors
on a modal basis at once.

Legacy command, replaced by ``PROJ_BASE``, which runs it (its legacy form,
asterlite.legacy.macros_v11). As in code_aster 11, one
generalized numbering is built on ``BASE`` (its first ``NB_VECT`` vectors,
storage ``PROFIL``, which defaulted to 'DIAG': projected matrices keep only
their diagonal), then each MATR_ASSE_GENE occurrence is a PROJ_MATR_BASE and
each VECT_ASSE_GENE occurrence a PROJ_VECT_BASE (TYPE_VECT defaulted to
'FORC'); every result is bound to its CO("NAME").
"""

from asterlite.catalog import FACT, MACRO, SIMP, UN_PARMI
from asterlite.lang.values import CO


def _type_output(value, type_name: str) -> None:
    """Type a CO("NAME") output as code_aster's sd_prod did (``type_sdprod``)."""
    if isinstance(value, CO):
        value.produced_type = type_name


def _sdprod(kw) -> None:
    """Types of the CO outputs (code_aster 11's macro_proj_base_prod)."""
    for occurrence in kw.get("MATR_ASSE_GENE") or ():
        _type_output(occurrence.get("MATRICE"), "matr_asse_gene_r")
    for occurrence in kw.get("VECT_ASSE_GENE") or ():
        _type_output(occurrence.get("VECTEUR"), "vect_asse_gene")
    return None


MACRO_PROJ_BASE = MACRO(
    nom="MACRO_PROJ_BASE",
    sd_prod=_sdprod,
    fr="Project assembled matrices and vectors on a modal basis (legacy: PROJ_BASE)",
    BASE=SIMP(statut="o", typ=("mode_meca", "mode_stat", "base_modale", "mode_gene")),
    NB_VECT=SIMP(statut="f", typ="I", defaut=9999),
    PROFIL=SIMP(statut="f", typ="TXM", defaut="DIAG", into=("PLEIN", "DIAG")),
    MATR_ASSE_GENE=FACT(
        statut="f",
        max="**",
        regles=(UN_PARMI("MATR_ASSE", "MATR_ASSE_GENE"),),
        MATRICE=SIMP(statut="o", typ=("CO", "matr_asse")),
        MATR_ASSE=SIMP(statut="f", typ="matr_asse_depl_r"),
        MATR_ASSE_GENE=SIMP(statut="f", typ="matr_asse_gene_r"),
    ),
    VECT_ASSE_GENE=FACT(
        statut="f",
        max="**",
        regles=(UN_PARMI("VECT_ASSE", "VECT_ASSE_GENE"),),
        VECTEUR=SIMP(statut="o", typ=("CO", "vect_asse")),
        TYPE_VECT=SIMP(statut="f", typ="TXM", defaut="FORC"),
        VECT_ASSE=SIMP(statut="f", typ="cham_no_sdaster"),
        VECT_ASSE_GENE=SIMP(statut="f", typ="vect_asse_gene"),
    ),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
