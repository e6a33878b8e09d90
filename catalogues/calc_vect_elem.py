"""CALC_VECT_ELEM: elementary load vectors."""

from asterlite.catalogues.common import tout

from asterlite.catalog import AU_MOINS_UN, BLOC, FACT, MACRO, SIMP, UN_PARMI, equal_to, exists


def _sdprod(kw) -> str:
    option = kw.get("OPTION")
    if option == "CHAR_THER":
        return "vect_elem_temp_r"
    if option == "CHAR_ACOU":
        return "vect_elem_pres_c"
    return "vect_elem_depl_r"


CALC_VECT_ELEM = MACRO(
    nom="CALC_VECT_ELEM",
    sd_prod=_sdprod,
    reentrant="n",
    fr="Compute elementary load vectors",
    OPTION=SIMP(statut="o", typ="TXM", into=("CHAR_MECA", "CHAR_THER", "CHAR_ACOU", "FORC_VARC")),
    b_char_meca=BLOC(
        condition=equal_to("OPTION", "CHAR_MECA"),
        regles=(AU_MOINS_UN("CHARGE", "MODELE"),),
        CHARGE=SIMP(statut="f", typ="char_meca", max="**"),
        MODELE=SIMP(statut="f", typ="modele_sdaster"),
        b_charge=BLOC(
            condition=exists("CHARGE"),
            CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
            CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
            INST=SIMP(statut="f", typ="R", defaut=0.0),
            MODE_FOURIER=SIMP(statut="f", typ="I", defaut=0),
        ),
        b_modele=BLOC(
            condition=exists("MODELE"),
            fr="Model holding substructures",
            SOUS_STRUC=FACT(
                statut="o",
                regles=(UN_PARMI("TOUT", "SUPER_MAILLE"),),
                CAS_CHARGE=SIMP(statut="o", typ="TXM"),
                TOUT=tout(),
                SUPER_MAILLE=SIMP(statut="f", typ="ma", max="**"),
            ),
        ),
    ),
    b_char_varc=BLOC(
        condition=equal_to("OPTION", "FORC_VARC"),
        MODELE=SIMP(statut="o", typ="modele_sdaster"),
        CHAM_MATER=SIMP(statut="o", typ="cham_mater"),
        CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
        INST=SIMP(statut="f", typ="R", defaut=0.0),
    ),
    b_char_ther=BLOC(
        condition=equal_to("OPTION", "CHAR_THER"),
        CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
        CHARGE=SIMP(statut="o", typ="char_ther", max="**"),
        INST=SIMP(statut="f", typ="R", defaut=0.0),
    ),
    b_char_acou=BLOC(
        condition=equal_to("OPTION", "CHAR_ACOU"),
        CHAM_MATER=SIMP(statut="o", typ="cham_mater"),
        CHARGE=SIMP(statut="o", typ="char_acou", max="**"),
    ),
)
