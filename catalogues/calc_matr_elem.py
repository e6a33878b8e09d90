"""CALC_MATR_ELEM: elementary matrices (stiffness, mass, damping...)."""

from asterlite.catalogues.common import OUI_NON, group_ma

from asterlite.catalog import AU_MOINS_UN, BLOC, ENSEMBLE, MACRO, SIMP, equal_to, is_in

OPTIONS = (
    "RIGI_MECA", "MASS_MECA", "RIGI_GEOM", "MASS_THER", "AMOR_MECA", "RIGI_THER", "IMPE_MECA",
    "ONDE_FLUI", "MASS_FLUI_STRU", "RIGI_FLUI_STRU", "RIGI_ROTA", "MECA_GYRO", "RIGI_GYRO",
    "MASS_MECA_DIAG", "RIGI_ACOU", "MASS_ACOU", "AMOR_ACOU", "RIGI_MECA_HYST",
)  # fmt: skip
CHARGE_MECA = dict(typ="char_meca", max="**")


def _sdprod(kw) -> str:
    option = kw.get("OPTION")
    if option == "RIGI_MECA_HYST":
        return "matr_elem_depl_c"
    if option in ("RIGI_THER", "MASS_THER"):
        return "matr_elem_temp_r"
    if option in ("RIGI_ACOU", "MASS_ACOU", "AMOR_ACOU"):
        return "matr_elem_pres_c"
    return "matr_elem_depl_r"


CALC_MATR_ELEM = MACRO(
    nom="CALC_MATR_ELEM",
    sd_prod=_sdprod,
    reentrant="n",
    fr="Compute elementary matrices",
    OPTION=SIMP(statut="o", typ="TXM", into=OPTIONS),
    MODELE=SIMP(statut="o", typ="modele_sdaster"),
    INST=SIMP(statut="f", typ="R", defaut=0.0),
    b_rigi_meca=BLOC(
        condition=equal_to("OPTION", "RIGI_MECA"),
        GROUP_MA=group_ma(),
        CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
        CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
        MODE_FOURIER=SIMP(statut="f", typ="I", defaut=0),
        CHARGE=SIMP(statut="f", **CHARGE_MECA),
        CALC_ELEM_MODELE=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="OUI"),
    ),
    b_mass_meca=BLOC(
        condition=is_in("OPTION", ("MASS_MECA", "MASS_MECA_DIAG")),
        GROUP_MA=group_ma(),
        CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
        CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
        CHARGE=SIMP(statut="f", **CHARGE_MECA),
    ),
    b_rigi_geom=BLOC(
        condition=equal_to("OPTION", "RIGI_GEOM"),
        GROUP_MA=group_ma(),
        SIEF_ELGA=SIMP(statut="o", typ="cham_elem"),
        CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
        STRX_ELGA=SIMP(statut="f", typ="cham_elem"),
        DEPL=SIMP(statut="f", typ="cham_no_sdaster"),
        CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
        MODE_FOURIER=SIMP(statut="f", typ="I", defaut=0),
    ),
    b_rigi_rota=BLOC(
        condition=equal_to("OPTION", "RIGI_ROTA"),
        CHAM_MATER=SIMP(statut="o", typ="cham_mater"),
        CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
        CHARGE=SIMP(statut="o", **CHARGE_MECA),
    ),
    b_gyro=BLOC(
        condition=is_in("OPTION", ("MECA_GYRO", "RIGI_GYRO")),
        CHAM_MATER=SIMP(statut="o", typ="cham_mater"),
        CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
        CHARGE=SIMP(statut="f", **CHARGE_MECA),
        GROUP_MA=group_ma(),
    ),
    b_amor_meca=BLOC(
        condition=equal_to("OPTION", "AMOR_MECA"),
        GROUP_MA=group_ma(),
        CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
        CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
        RIGI_MECA=SIMP(statut="f", typ="matr_elem_depl_r"),
        MASS_MECA=SIMP(statut="f", typ="matr_elem_depl_r"),
        CHARGE=SIMP(statut="f", **CHARGE_MECA),
        AMOR_FLUI=SIMP(statut="f", typ="TXM", into=OUI_NON, defaut="OUI"),
        VNOR=SIMP(statut="f", typ="R", into=(1.0, -1.0), defaut=1.0),
        TYPE_AMOR=SIMP(statut="f", typ="TXM", into=("TOUT", "ABSO"), defaut="TOUT"),
        b_amor_tout=BLOC(
            condition=equal_to("TYPE_AMOR", "TOUT"),
            regles=(AU_MOINS_UN("CARA_ELEM", "RIGI_MECA"), ENSEMBLE("RIGI_MECA", "CHAM_MATER")),
        ),
        b_amor_flui=BLOC(
            condition=equal_to("TYPE_AMOR", "ABSO"), regles=(AU_MOINS_UN("CHAM_MATER"),)
        ),
    ),
    b_rigi_hyst=BLOC(
        condition=equal_to("OPTION", "RIGI_MECA_HYST"),
        GROUP_MA=group_ma(),
        CHARGE=SIMP(statut="f", **CHARGE_MECA),
        CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
        CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
        RIGI_MECA=SIMP(statut="o", typ="matr_elem_depl_r"),
    ),
    b_rigi_ther=BLOC(
        condition=equal_to("OPTION", "RIGI_THER"),
        CHAM_MATER=SIMP(statut="o", typ="cham_mater"),
        CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
        MODE_FOURIER=SIMP(statut="f", typ="I", defaut=0),
        CHARGE=SIMP(statut="f", typ="char_ther", max="**"),
    ),
    b_mass_ther=BLOC(
        condition=equal_to("OPTION", "MASS_THER"),
        CHAM_MATER=SIMP(statut="o", typ="cham_mater"),
        CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
    ),
    b_rigi_acou=BLOC(
        condition=equal_to("OPTION", "RIGI_ACOU"),
        CHAM_MATER=SIMP(statut="o", typ="cham_mater"),
        CHARGE=SIMP(statut="f", typ="char_acou", max="**"),
    ),
    b_mass_acou=BLOC(
        condition=is_in("OPTION", ("MASS_ACOU", "AMOR_ACOU")),
        CHAM_MATER=SIMP(statut="o", typ="cham_mater"),
        CHARGE=SIMP(statut="f", typ="char_acou", max="**"),
        b_direction_ac=BLOC(
            condition=equal_to("OPTION", "AMOR_ACOU"),
            VNOR=SIMP(statut="f", typ="R", into=(1.0, -1.0), defaut=1.0),
        ),
    ),
    b_rigi_flui=BLOC(
        condition=equal_to("OPTION", "RIGI_FLUI_STRU"),
        CARA_ELEM=SIMP(statut="o", typ="cara_elem"),
        CHAM_MATER=SIMP(statut="o", typ="cham_mater"),
        CHARGE=SIMP(statut="o", **CHARGE_MECA),
    ),
    b_mass_flui=BLOC(
        condition=equal_to("OPTION", "MASS_FLUI_STRU"),
        GROUP_MA=group_ma(),
        CARA_ELEM=SIMP(statut="o", typ="cara_elem"),
        CHAM_MATER=SIMP(statut="o", typ="cham_mater"),
        CHARGE=SIMP(statut="o", **CHARGE_MECA),
    ),
    b_impe_meca=BLOC(
        condition=is_in("OPTION", ("IMPE_MECA", "ONDE_FLUI")),
        CHAM_MATER=SIMP(statut="o", typ="cham_mater"),
        GROUP_MA=group_ma(),
        CHARGE=SIMP(statut="f", **CHARGE_MECA),
        b_direction_me=BLOC(
            condition=equal_to("OPTION", "IMPE_MECA"),
            VNOR=SIMP(statut="f", typ="R", into=(1.0, -1.0), defaut=1.0),
        ),
    ),
)
