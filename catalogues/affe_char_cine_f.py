"""AFFE_CHAR_CINE_F: imposed DOF values given by functions of X, Y, Z and INST."""

from asterlite.catalogues.affe_char_cine import kinematic_loads

from asterlite.catalog import OPER

AFFE_CHAR_CINE_F = OPER(
    nom="AFFE_CHAR_CINE_F",
    sd_prod="char_cine_meca",
    reentrant="n",
    fr="Imposed DOF values, functions of space and time, eliminated from the system",
    **kinematic_loads(("fonction_sdaster", "nappe_sdaster", "formule")),
)
