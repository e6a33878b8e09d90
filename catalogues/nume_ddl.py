"""NUME_DDL: numbering of the degrees of freedom and matrix storage."""

from asterlite.catalog import BLOC, MACRO, SIMP, UN_PARMI, exists

MATR_ELEM_TYPES = ("matr_elem_depl_r", "matr_elem_depl_c", "matr_elem_temp_r", "matr_elem_pres_c")

NUME_DDL = MACRO(
    nom="NUME_DDL",
    sd_prod="nume_ddl_sdaster",
    reentrant="n",
    fr="Number the degrees of freedom",
    regles=(UN_PARMI("MATR_RIGI", "MODELE"),),
    MATR_RIGI=SIMP(statut="f", typ=MATR_ELEM_TYPES, max=100),
    MODELE=SIMP(statut="f", typ="modele_sdaster"),
    b_modele=BLOC(
        condition=exists("MODELE"),
        CHARGE=SIMP(statut="f", typ=("char_meca", "char_ther", "char_acou"), max="**"),
    ),
    INFO=SIMP(statut="f", typ="I", into=(1, 2), defaut=1),
)
