"""ASSEMBLAGE: numbering, assembled matrices and vectors in one command.

Outputs are named with CO("NAME"): NUME_DDL (nume_ddl_sdaster unless an
existing numbering is given), MATR_ASSE/MATRICE (matr_asse_depl_r, or
matr_asse_depl_c for RIGI_MECA_HYST) and VECT_ASSE/VECTEUR (cham_no_sdaster).
"""

from asterlite.catalogues.common import OUI_NON, group_ma

from asterlite.catalog import AU_MOINS_UN, BLOC, FACT, MACRO, SIMP, equal_to, is_in
from asterlite.lang.values import CO

MATRIX_OPTIONS = (
    "RIGI_MECA", "MASS_MECA", "MASS_MECA_DIAG", "AMOR_MECA", "RIGI_MECA_HYST", "IMPE_MECA",
    "ONDE_FLUI", "RIGI_FLUI_STRU", "MASS_FLUI_STRU", "RIGI_ROTA", "RIGI_GEOM", "MECA_GYRO",
    "RIGI_GYRO", "RIGI_THER", "RIGI_ACOU", "MASS_ACOU", "AMOR_ACOU",
)  # fmt: skip

# assembled type of each matrix option (the others give matr_asse_depl_r)
MATRIX_TYPES = {
    "RIGI_MECA_HYST": "matr_asse_depl_c",
    "RIGI_THER": "matr_asse_temp_r",
    "RIGI_ACOU": "matr_asse_pres_c",
    "MASS_ACOU": "matr_asse_pres_c",
    "AMOR_ACOU": "matr_asse_pres_c",
}


def _type_output(value, type_name: str) -> None:
    """Give a CO("NAME") output its concept type, as code_aster's sd_prod does
    (``self.type_sdprod``): ``asterlite check`` binds the name to that type."""
    if isinstance(value, CO):
        value.produced_type = type_name


def _sdprod(kw) -> None:
    """Types of the CO outputs: the numbering, each matrix by its option, each
    vector (code_aster's assemblage_prod); the command itself makes nothing."""
    _type_output(kw.get("NUME_DDL"), "nume_ddl_sdaster")
    for occurrence in kw.get("MATR_ASSE") or ():
        option = occurrence.get("OPTION")
        _type_output(occurrence.get("MATRICE"), MATRIX_TYPES.get(option, "matr_asse_depl_r"))
    for occurrence in kw.get("VECT_ASSE") or ():
        _type_output(occurrence.get("VECTEUR"), "cham_no_sdaster")
    return None


ASSEMBLAGE = MACRO(
    nom="ASSEMBLAGE",
    sd_prod=_sdprod,
    fr="Compute assembled matrices and vectors",
    regles=(AU_MOINS_UN("MATR_ASSE", "VECT_ASSE"),),
    MODELE=SIMP(statut="o", typ="modele_sdaster"),
    CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
    INST=SIMP(statut="f", typ="R", defaut=0.0),
    CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
    CHARGE=SIMP(statut="f", typ=("char_meca", "char_ther", "char_acou"), max="**"),
    CHAR_CINE=SIMP(statut="f", typ=("char_cine_meca", "char_cine_ther", "char_cine_acou")),
    NUME_DDL=SIMP(statut="o", typ=("nume_ddl_sdaster", "CO")),
    MATR_ASSE=FACT(
        statut="f",
        max="**",
        MATRICE=SIMP(statut="o", typ="CO"),
        OPTION=SIMP(statut="o", typ="TXM", into=MATRIX_OPTIONS),
        b_group_ma=BLOC(
            condition=is_in(
                "OPTION",
                (
                    "RIGI_GYRO",
                    "MECA_GYRO",
                    "IMPE_MECA",
                    "AMOR_MECA",
                    "MASS_MECA",
                    "RIGI_MECA",
                    "MASS_MECA_DIAG",
                    "MASS_FLUI_STRU",
                ),
            ),  # fmt: skip
            GROUP_MA=group_ma(),
        ),
        b_rigi_meca=BLOC(
            condition=equal_to("OPTION", "RIGI_MECA"),
            MODE_FOURIER=SIMP(statut="f", typ="I", defaut=0),
        ),
        b_rigi_geom=BLOC(
            condition=equal_to("OPTION", "RIGI_GEOM"),
            SIEF_ELGA=SIMP(statut="o", typ="cham_elem"),
            MODE_FOURIER=SIMP(statut="f", typ="I", defaut=0),
        ),
        b_rigi_ther=BLOC(
            condition=equal_to("OPTION", "RIGI_THER"),
            MODE_FOURIER=SIMP(statut="f", typ="I", defaut=0),
        ),
        b_amor_meca=BLOC(
            condition=equal_to("OPTION", "AMOR_MECA"),
            AMOR_FLUI=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="OUI"),
            VNOR=SIMP(statut="f", typ="R", into=(1.0, -1.0), defaut=1.0),
            TYPE_AMOR=SIMP(statut="f", typ="TXM", into=("TOUT", "ABSO"), defaut="TOUT"),
        ),
        b_impe_meca=BLOC(
            condition=is_in("OPTION", ("IMPE_MECA", "AMOR_ACOU")),
            VNOR=SIMP(statut="f", typ="R", into=(1.0, -1.0), defaut=1.0),
        ),
    ),
    VECT_ASSE=FACT(
        statut="f",
        max="**",
        VECTEUR=SIMP(statut="o", typ="CO"),
        OPTION=SIMP(statut="o", typ="TXM", into=("CHAR_MECA", "CHAR_ACOU", "CHAR_THER")),
        b_char_meca=BLOC(
            condition=equal_to("OPTION", "CHAR_MECA"),
            CHARGE=SIMP(statut="f", typ="char_meca", max="**"),
            MODE_FOURIER=SIMP(statut="f", typ="I", defaut=0),
        ),
        b_char_ther=BLOC(
            condition=equal_to("OPTION", "CHAR_THER"),
            CHARGE=SIMP(statut="f", typ="char_ther", max="**"),
        ),
        b_char_acou=BLOC(
            condition=equal_to("OPTION", "CHAR_ACOU"),
            CHARGE=SIMP(statut="f", typ="char_acou", max="**"),
        ),
    ),
    TITRE=SIMP(statut="f", typ="TXM"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
