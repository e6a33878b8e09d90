"""MACR_ELEM_STAT: a static superelement condensed on its external nodes."""

from asterlite.catalogues.common import noeud

from asterlite.catalog import AU_MOINS_UN, ENSEMBLE, FACT, OPER, PRESENT_PRESENT, SIMP

_SIZING = "sizes code_aster's storage of load cases"

MACR_ELEM_STAT = OPER(
    nom="MACR_ELEM_STAT",
    sd_prod="macr_elem_stat",
    reentrant="f",
    fr="Static superelement: stiffness, mass and damping condensed on external nodes",
    regles=(
        AU_MOINS_UN("DEFINITION", "RIGI_MECA", "MASS_MECA", "CAS_CHARGE"),
        ENSEMBLE("DEFINITION", "EXTERIEUR"),
    ),
    MACR_ELEM=SIMP(statut="f", typ="macr_elem_stat", fr="The superelement completed (reuse)"),
    DEFINITION=FACT(
        statut="f",
        regles=(PRESENT_PRESENT("PROJ_MESU", "MODE_MESURE"),),
        MODELE=SIMP(statut="o", typ="modele_sdaster"),
        CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
        CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
        CHAR_MACR_ELEM=SIMP(statut="f", typ="char_meca", fr="Conditions on the interior DOFs"),
        INST=SIMP(statut="f", typ="R", defaut=0.0),
        NMAX_CAS=SIMP(statut="f", typ="I", defaut=10, no_effect=_SIZING),
        NMAX_CHAR=SIMP(statut="f", typ="I", defaut=10, no_effect=_SIZING),
        PROJ_MESU=SIMP(statut="f", typ=("mode_gene", "tran_gene", "harm_gene")),
        MODE_MESURE=SIMP(statut="f", typ="mode_meca"),
    ),
    EXTERIEUR=FACT(
        statut="f",
        regles=(AU_MOINS_UN("NOEUD", "GROUP_NO"),),
        NOEUD=noeud(),
        GROUP_NO=SIMP(statut="f", typ="grno", max="**"),
    ),
    RIGI_MECA=FACT(statut="f"),
    MASS_MECA=FACT(statut="f"),
    AMOR_MECA=FACT(statut="f"),
    CAS_CHARGE=FACT(
        statut="f",
        max="**",
        NOM_CAS=SIMP(statut="o", typ="TXM"),
        SUIV=SIMP(statut="f", typ="TXM", defaut="OUI", into=("OUI", "NON")),
        CHARGE=SIMP(statut="f", typ="char_meca", max="**"),
        INST=SIMP(statut="f", typ="R", defaut=0.0),
    ),
)
