"""ASSE_MATRICE: assemble elementary matrices into a global matrix."""

from asterlite.catalogues.nume_ddl import MATR_ELEM_TYPES

from asterlite.catalog import MACRO, SIMP

# elementary matrix type -> assembled matrix type
ASSEMBLED = {
    "matr_elem_depl_c": "matr_asse_depl_c",
    "matr_elem_temp_r": "matr_asse_temp_r",
    "matr_elem_pres_c": "matr_asse_pres_c",
}


def _sdprod(kw) -> str:
    elements = kw.get("MATR_ELEM") or ()
    first = elements[0] if elements else None
    for elem_type, asse_type in ASSEMBLED.items():
        if getattr(first, "satisfies", lambda _t: False)(elem_type):
            return asse_type
    return "matr_asse_depl_r"


ASSE_MATRICE = MACRO(
    nom="ASSE_MATRICE",
    sd_prod=_sdprod,
    reentrant="n",
    fr="Assemble elementary matrices",
    MATR_ELEM=SIMP(statut="o", typ=MATR_ELEM_TYPES, max="**"),
    NUME_DDL=SIMP(statut="o", typ="nume_ddl_sdaster"),
    SYME=SIMP(statut="f", typ="TXM", into=("OUI",)),
    CHAR_CINE=SIMP(
        statut="f", typ=("char_cine_meca", "char_cine_ther", "char_cine_acou"), max="**"
    ),
    INFO=SIMP(statut="f", typ="I", into=(1, 2), defaut=1),
)
