"""MACRO_MATR_ASSE (code_aster 10 to 11): numbering and assembled matrices in
one command.

Legacy command, replaced by ``ASSEMBLAGE``, which runs it (its legacy form,
asterlite.legacy.macros_v11). As in code_aster 11, the
stiffness occurrence comes first and, when NUME_DDL is a CO("NAME"), the
numbering is built from it and the loads; each MATR_ASSE occurrence is a
CALC_MATR_ELEM + ASSE_MATRICE bound to its CO("NAME"). SOLVEUR only chose
the renumbering of the numbering, which changes no result in asterlite.
"""

from asterlite.catalogues.common import NO_EFFECT_SOLVER

from asterlite.catalog import BLOC, FACT, MACRO, SIMP, equal_to
from asterlite.lang.values import CO

MATRIX_OPTIONS = (
    "RIGI_MECA", "MASS_MECA", "MASS_MECA_DIAG", "AMOR_MECA", "RIGI_MECA_HYST", "IMPE_MECA",
    "ONDE_FLUI", "RIGI_FLUI_STRU", "MASS_FLUI_STRU", "RIGI_ROTA", "RIGI_GEOM",
    "RIGI_MECA_LAGR", "MECA_GYRO", "RIGI_THER", "MASS_THER", "RIGI_ACOU", "MASS_ACOU",
    "AMOR_ACOU", "MASS_ID_MTEM_R", "MASS_ID_MTNS_R", "MASS_ID_MDEP_R", "MASS_ID_MDNS_R",
)  # fmt: skip

# assembled type of each option (code_aster 11's macro_matr_asse_prod)
MATRIX_TYPES = {
    "RIGI_MECA_HYST": "matr_asse_depl_c",
    "RIGI_ACOU": "matr_asse_pres_c",
    "MASS_ACOU": "matr_asse_pres_c",
    "AMOR_ACOU": "matr_asse_pres_c",
    **dict.fromkeys(
        ("RIGI_THER", "MASS_THER", "MASS_ID_MTEM_R", "MASS_ID_MTNS_R"), "matr_asse_temp_r"
    ),
}


def _type_output(value, type_name: str) -> None:
    """Type a CO("NAME") output as code_aster's sd_prod did (``type_sdprod``)."""
    if isinstance(value, CO):
        value.produced_type = type_name


def _sdprod(kw) -> None:
    _type_output(kw.get("NUME_DDL"), "nume_ddl_sdaster")
    for occurrence in kw.get("MATR_ASSE") or ():
        option = occurrence.get("OPTION")
        _type_output(occurrence.get("MATRICE"), MATRIX_TYPES.get(option, "matr_asse_depl_r"))
    return None


def _renum(into, default) -> SIMP:
    return SIMP(statut="f", typ="TXM", into=into, defaut=default)


MACRO_MATR_ASSE = MACRO(
    nom="MACRO_MATR_ASSE",
    sd_prod=_sdprod,
    fr="Compute assembled matrices (legacy: ASSEMBLAGE)",
    MODELE=SIMP(statut="o", typ="modele_sdaster"),
    CHAM_MATER=SIMP(statut="f", typ="cham_mater"),
    INST=SIMP(statut="f", typ="R", defaut=0.0),
    CARA_ELEM=SIMP(statut="f", typ="cara_elem"),
    CHARGE=SIMP(statut="f", typ=("char_meca", "char_ther", "char_acou"), max="**"),
    CHAR_CINE=SIMP(statut="f", typ=("char_cine_meca", "char_cine_ther", "char_cine_acou")),
    NUME_DDL=SIMP(statut="o", typ=("nume_ddl_sdaster", "CO")),
    SOLVEUR=FACT(
        statut="d",
        no_effect=NO_EFFECT_SOLVER,
        METHODE=SIMP(
            statut="f",
            typ="TXM",
            defaut="MULT_FRONT",
            into=("MULT_FRONT", "LDLT", "GCPC", "MUMPS"),
        ),
        b_mult_front=BLOC(
            condition=equal_to("METHODE", "MULT_FRONT"),
            RENUM=_renum(("MD", "MDA", "METIS"), "METIS"),
        ),
        b_ldlt=BLOC(condition=equal_to("METHODE", "LDLT"), RENUM=_renum(("RCMK", "SANS"), "RCMK")),
        b_mumps=BLOC(
            condition=equal_to("METHODE", "MUMPS"),
            RENUM=_renum(("AMD", "AMF", "PORD", "METIS", "QAMD", "AUTO"), "AUTO"),
        ),
        b_gcpc=BLOC(condition=equal_to("METHODE", "GCPC"), RENUM=_renum(("RCMK", "SANS"), "RCMK")),
    ),
    MATR_ASSE=FACT(
        statut="o",
        max="**",
        MATRICE=SIMP(statut="o", typ="CO"),
        OPTION=SIMP(statut="o", typ="TXM", into=MATRIX_OPTIONS),
        b_rigi_meca=BLOC(
            condition=equal_to("OPTION", "RIGI_MECA"),
            MODE_FOURIER=SIMP(statut="f", typ="I", defaut=0),
        ),
        b_rigi_geom=BLOC(
            condition=equal_to("OPTION", "RIGI_GEOM"),
            SIEF_ELGA=SIMP(statut="o", typ="cham_elem"),
            MODE_FOURIER=SIMP(statut="f", typ="I", defaut=0),
        ),
        b_rigi_meca_lagr=BLOC(
            condition=equal_to("OPTION", "RIGI_MECA_LAGR"),
            THETA=SIMP(statut="o", typ="theta_geom"),
            PROPAGATION=SIMP(statut="f", typ="R"),
        ),
        b_rigi_ther=BLOC(
            condition=equal_to("OPTION", "RIGI_THER"),
            MODE_FOURIER=SIMP(statut="f", typ="I", defaut=0),
        ),
    ),
    TITRE=SIMP(statut="f", typ="TXM", max="**"),
    INFO=SIMP(statut="f", typ="I", defaut=1, into=(1, 2)),
)
