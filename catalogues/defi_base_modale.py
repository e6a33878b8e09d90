"""DEFI_BASE_MODALE: build a modal basis (Ritz vectors, classical basis...)."""

from asterlite.catalogues.common import C_SOLVEUR, OUI_NON

from asterlite.catalog import BLOC, FACT, OPER, SIMP, UN_PARMI, equal_to, exists

MATRICES = ("matr_asse_depl_r", "matr_asse_depl_c", "matr_asse_gene_r", "matr_asse_pres_r")

DEFI_BASE_MODALE = OPER(
    nom="DEFI_BASE_MODALE",
    sd_prod="mode_meca",
    reentrant="f",
    fr="Define a modal basis for substructuring or modal recombination",
    regles=(UN_PARMI("CLASSIQUE", "RITZ", "DIAG_MASS", "ORTHO_BASE"),),
    CLASSIQUE=FACT(
        statut="f",
        INTERF_DYNA=SIMP(statut="o", typ="interf_dyna_clas"),
        MODE_MECA=SIMP(statut="o", typ="mode_meca", max="**"),
        NMAX_MODE=SIMP(statut="f", typ="I", max="**"),
    ),
    RITZ=FACT(
        statut="f",
        max=2,
        regles=(UN_PARMI("MODE_MECA", "BASE_MODALE", "MODE_INTF"),),
        MODE_MECA=SIMP(statut="f", typ="mode_meca", max="**"),
        NMAX_MODE=SIMP(statut="f", typ="I", max="**"),
        BASE_MODALE=SIMP(statut="f", typ="mode_meca"),
        MODE_INTF=SIMP(statut="f", typ=("mode_meca", "mult_elas")),
    ),
    b_ritz=BLOC(
        condition=exists("RITZ"),
        INTERF_DYNA=SIMP(statut="f", typ="interf_dyna_clas"),
        NUME_REF=SIMP(statut="f", typ="nume_ddl_sdaster"),
        ORTHO=SIMP(
            statut="f", typ="TXM", defaut="NON", into=OUI_NON, fr="Orthonormalise the basis"
        ),
        LIST_AMOR=SIMP(statut="f", typ="listr8_sdaster"),
        b_ortho=BLOC(condition=equal_to("ORTHO", "OUI"), MATRICE=SIMP(statut="o", typ=MATRICES)),
    ),
    DIAG_MASS=FACT(
        statut="f",
        MODE_MECA=SIMP(statut="o", typ="mode_meca", max="**"),
        MODE_STAT=SIMP(statut="o", typ="mode_meca"),
    ),
    ORTHO_BASE=FACT(
        statut="f",
        BASE=SIMP(statut="o", typ=("mode_meca", "mult_elas")),
        MATRICE=SIMP(statut="o", typ=MATRICES),
    ),
    SOLVEUR=C_SOLVEUR("DEFI_BASE_MODALE"),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
