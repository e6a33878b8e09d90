"""MAC_MODES: modal assurance criterion (or IERI energy indicator) of two bases."""

from asterlite.catalog import OPER, PRESENT_PRESENT, SIMP

MAC_MODES = OPER(
    nom="MAC_MODES",
    sd_prod="table_sdaster",
    reentrant="n",
    fr="MAC (or IERI with a matrix) of every pair of modes of two bases",
    regles=(PRESENT_PRESENT("IERI", "MATR_ASSE"),),
    BASE_1=SIMP(statut="o", typ=("mode_meca", "mode_meca_c", "mode_flamb")),
    BASE_2=SIMP(statut="o", typ=("mode_meca", "mode_meca_c", "mode_flamb")),
    MATR_ASSE=SIMP(statut="f", typ=("matr_asse_depl_r", "matr_asse_depl_c")),
    IERI=SIMP(statut="f", typ="TXM", into=("OUI",)),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
