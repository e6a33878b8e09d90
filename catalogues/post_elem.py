"""POST_ELEM: global quantities over elements (mass and inertia, energies...).

asterlite describes MASS_INER and ENER_CIN, the quantities dynamics decks
use; the other code_aster options are not described.
"""

from asterlite.catalogues.common import group_ma, tout

from asterlite.catalog import EXCLUS, FACT, MACRO, SIMP, UN_PARMI

POST_ELEM = MACRO(
    nom="POST_ELEM",
    sd_prod="table_sdaster",
    reentrant="n",
    fr="Compute global quantities over elements into a table",
    regles=(
        UN_PARMI("MASS_INER", "ENER_CIN"),
        EXCLUS("TOUT_ORDRE", "NUME_ORDRE", "LIST_ORDRE", "INST", "LIST_INST"),
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
    ENER_CIN=FACT(
        statut="f",
        max="**",
        fr="Kinetic energy of element groups",
        regles=(UN_PARMI("TOUT", "GROUP_MA"),),
        OPTION=SIMP(
            statut="f", typ="TXM", into=("MASS_MECA", "MASS_MECA_DIAG"), defaut="MASS_MECA"
        ),
        TOUT=tout(),
        GROUP_MA=group_ma(),
    ),
    TOUT_ORDRE=SIMP(statut="f", typ="TXM", into=("OUI",)),
    NUME_ORDRE=SIMP(statut="f", typ="I", max="**"),
    LIST_ORDRE=SIMP(statut="f", typ="listis_sdaster"),
    LIST_INST=SIMP(statut="f", typ="listr8_sdaster"),
    CRITERE=SIMP(statut="f", typ="TXM", defaut="RELATIF", into=("RELATIF", "ABSOLU")),
    PRECISION=SIMP(statut="f", typ="R", defaut=1.0e-6),
    ORIG_INER=SIMP(statut="f", typ="R", min=3, max=3, fr="Point where inertia is computed"),
    GEOMETRIE=SIMP(statut="f", typ="TXM", defaut="INITIALE", into=("INITIALE", "DEFORMEE")),
    CHAM_GD=SIMP(statut="f", typ="cham_no_sdaster"),
    INST=SIMP(statut="f", typ="R", max="**"),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
