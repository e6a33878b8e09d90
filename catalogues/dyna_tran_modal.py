"""DYNA_TRAN_MODAL (code_aster 10 to 12): transient response on a modal basis.

Legacy command, replaced by ``DYNA_VIBRA(TYPE_CALCUL='TRAN', BASE_CALCUL='GENE')``.
This catalogue accepts both of its historical forms as written: code_aster 10
(``METHODE``, ``MASS_GENE``, ``RIGI_GENE``, ``AMOR_GENE``, ``AMOR_REDUIT``)
and code_aster 11-12 (``SCHEMA_TEMPS``, ``MATR_MASS``, ``MATR_RIGI``,
``AMOR_MODAL``); its legacy form translates the call (see
``asterlite.legacy.dyna``), which the modern DYNA_VIBRA then runs.
"""

from asterlite.catalogues.common_legacy import LEGACY_SCHEMES, gene_transient_legacy

from asterlite.catalog import EXCLUS, OPER, PRESENT_ABSENT, SIMP, UN_PARMI

DYNA_TRAN_MODAL = OPER(
    nom="DYNA_TRAN_MODAL",
    sd_prod="tran_gene",
    reentrant="f",
    fr="Transient response on a modal basis (legacy: DYNA_VIBRA TRAN/GENE)",
    regles=(
        UN_PARMI("MATR_MASS", "MASS_GENE"),
        UN_PARMI("MATR_RIGI", "RIGI_GENE"),
        EXCLUS("METHODE", "SCHEMA_TEMPS"),
        EXCLUS("AMOR_MODAL", "MATR_AMOR", "AMOR_GENE", "AMOR_REDUIT", "LIST_AMOR"),
        PRESENT_ABSENT("MODE_STAT", "MODE_CORR"),
    ),
    # code_aster 10 spellings
    METHODE=SIMP(statut="f", typ="TXM", into=LEGACY_SCHEMES),
    MASS_GENE=SIMP(statut="f", typ="matr_asse_gene_r"),
    RIGI_GENE=SIMP(statut="f", typ="matr_asse_gene_r"),
    AMOR_GENE=SIMP(statut="f", typ="matr_asse_gene_r"),
    AMOR_REDUIT=SIMP(statut="f", typ="R", max="**"),
    LIST_AMOR=SIMP(statut="f", typ="listr8_sdaster"),
    # code_aster 11-12 spellings
    MATR_MASS=SIMP(statut="f", typ="matr_asse_gene_r"),
    MATR_RIGI=SIMP(statut="f", typ="matr_asse_gene_r"),
    **gene_transient_legacy(),
)
