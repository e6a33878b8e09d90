"""ASSE_VECTEUR: assemble elementary vectors into a nodal field."""

from asterlite.catalog import MACRO, SIMP

ASSE_VECTEUR = MACRO(
    nom="ASSE_VECTEUR",
    sd_prod="cham_no_sdaster",
    reentrant="n",
    fr="Assemble elementary vectors into a nodal field",
    VECT_ELEM=SIMP(
        statut="o",
        typ=("vect_elem", "vect_elem_depl_r", "vect_elem_temp_r", "vect_elem_pres_c"),
        max="**",
    ),
    NUME_DDL=SIMP(statut="o", typ="nume_ddl_sdaster"),
    INFO=SIMP(statut="f", typ="I", into=(1, 2), defaut=1),
)
