"""CALC_CHAR_SEISME: seismic load vector (mass times drive direction)."""

from asterlite.catalog import BLOC, OPER, SIMP, UN_PARMI, exists

CALC_CHAR_SEISME = OPER(
    nom="CALC_CHAR_SEISME",
    sd_prod="cham_no_sdaster",
    reentrant="n",
    fr="Seismic load for a support motion",
    regles=(UN_PARMI("MONO_APPUI", "MODE_STAT"),),
    MATR_MASS=SIMP(statut="o", typ="matr_asse_depl_r", fr="Mass matrix"),
    DIRECTION=SIMP(statut="o", typ="R", max=6, fr="Direction of the seismic motion"),
    MONO_APPUI=SIMP(statut="f", typ="TXM", into=("OUI",)),
    MODE_STAT=SIMP(statut="f", typ="mode_meca"),
    b_mode_stat=BLOC(
        condition=exists("MODE_STAT"), GROUP_NO=SIMP(statut="o", typ="grno", max="**")
    ),
    TITRE=SIMP(statut="f", typ="TXM"),
)
