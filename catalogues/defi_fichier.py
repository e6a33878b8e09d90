"""DEFI_FICHIER: open, reserve or close a file on a logical unit.

Returns the unit number (an integer) when ASSOCIER/RESERVER is given no UNITE.
"""

from asterlite.catalog import AU_MOINS_UN, BLOC, MACRO, SIMP, UN_PARMI, equal_to


def _sdprod(kw) -> str | None:
    if kw.get("ACTION") in ("ASSOCIER", "RESERVER") and kw.get("UNITE") is None:
        return "entier"
    return None


DEFI_FICHIER = MACRO(
    nom="DEFI_FICHIER",
    sd_prod=_sdprod,
    reentrant="n",
    fr="Open or close a file associated with a logical unit",
    ACTION=SIMP(statut="f", typ="TXM", into=("ASSOCIER", "LIBERER", "RESERVER"), defaut="ASSOCIER"),
    b_associer=BLOC(
        condition=equal_to("ACTION", "ASSOCIER"),
        regles=(AU_MOINS_UN("FICHIER", "UNITE"),),
        UNITE=SIMP(statut="f", typ="I"),
        FICHIER=SIMP(statut="f", typ="TXM"),
        TYPE=SIMP(statut="f", typ="TXM", into=("ASCII", "BINARY", "LIBRE"), defaut="ASCII"),
        b_type_ascii=BLOC(
            condition=equal_to("TYPE", "ASCII"),
            ACCES=SIMP(statut="f", typ="TXM", into=("NEW", "APPEND", "OLD"), defaut="NEW"),
        ),
        b_type_autre=BLOC(
            condition=~equal_to("TYPE", "ASCII"),
            ACCES=SIMP(statut="f", typ="TXM", into=("NEW", "OLD"), defaut="NEW"),
        ),
    ),
    b_reserver=BLOC(
        condition=equal_to("ACTION", "RESERVER"),
        regles=(AU_MOINS_UN("FICHIER", "UNITE"),),
        UNITE=SIMP(statut="f", typ="I"),
        FICHIER=SIMP(statut="f", typ="TXM"),
        TYPE=SIMP(statut="f", typ="TXM", into=("ASCII",), defaut="ASCII"),
        ACCES=SIMP(statut="f", typ="TXM", into=("APPEND",), defaut="APPEND"),
    ),
    b_liberer=BLOC(
        condition=equal_to("ACTION", "LIBERER"),
        regles=(UN_PARMI("FICHIER", "UNITE"),),
        UNITE=SIMP(statut="f", typ="I"),
        FICHIER=SIMP(statut="f", typ="TXM"),
    ),
    INFO=SIMP(statut="f", typ="I", into=(1, 2)),
)
