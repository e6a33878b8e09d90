"""POST_ELEM: global quantities over elements (mass and inertia, energies...).

asterlite describes MASS_INER, the quantity dynamics decks use; the other
code_aster options are not described.
"""

from asterlite.catalogues.common import group_ma, tout

from asterlite.catalog import FACT, MACRO, SIMP, UN_PARMI

POST_ELEM = MACRO(
    nom="POST_ELEM",
    sd_prod="table_sdaster",
    reentrant="n",
    fr="Compute global quantities over elements into a table",
    regles=(
        UN_PARMI(
            "MASS_INER",
        ),
    ),
    MODELE=SIMP(statut="f", typ="modele_sdaster"),
    CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
    CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
    RESULTAT=SIMP(statut="f", typ=("resultat_sdaster", "mode_meca", "dyna_trans", "evol_elas")),
    MASS_INER=FACT(
        statut="f",
        max="**",
        fr="Mass, centre of gravity and inertia",
        regles=(UN_PARMI("TOUT", "GROUP_MA"),),
        TOUT=tout(),
        GROUP_MA=group_ma(),
    ),
    ORIG_INER=SIMP(statut="f", typ="R", min=3, max=3, fr="Point where inertia is computed"),
    GEOMETRIE=SIMP(statut="f", typ="TXM", defaut="INITIALE", into=("INITIALE", "DEFORMEE")),
    CHAM_GD=SIMP(statut="f", typ="cham_no_sdaster"),
    INST=SIMP(statut="f", typ="R", defaut=0.0),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
