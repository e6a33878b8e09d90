"""CALC_CHAR_CINE: the nodal field of the values kinematic loads impose."""

from asterlite.catalog import OPER, SIMP

CALC_CHAR_CINE = OPER(
    nom="CALC_CHAR_CINE",
    sd_prod="cham_no_sdaster",
    reentrant="n",
    fr="Field of the values imposed by kinematic loads",
    NUME_DDL=SIMP(statut="o", typ="nume_ddl_sdaster"),
    CHAR_CINE=SIMP(statut="o", typ="char_cine_meca", max="**"),
    INST=SIMP(statut="f", typ="R", defaut=0.0),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
